// FrameLoop's overlapped step: Box2D steps frame k+1 on a worker thread while the window draws
// frame k, and the next step() adopts it, so that the window's frame takes the longer of physics
// and everything else rather than their sum.
//
// The world, its worker and the snapshot the accessors read meanwhile are physics/live_world.hpp's
// (why it is safe, why it is the same frame); this file arms the slow-frame note and runs the
// adopted frame through the same detect_and_check() step() runs (tests/app/test_frame_loop_overlap.cpp).
#include "app/frame_loop_impl.hpp"
#include "check/recorded_lane.hpp"

namespace nbscope {

void FrameLoop::begin_step() {
  FrameLoopState& m = *impl_;
  Simulation* sim = m.simulation();
  if (sim == nullptr || sim->pending() || m.source().showing_past() || sim->resuming()) return;
  // As step() does: the stale-positions fault detects the next frame on this one's positions.
  if (m.pipeline.options().fault == Fault::StalePositions) m.pipeline.remember_previous(m.frame_number() + 1, m.now());
  m.watch_step();  // settle() moves the note on to the detection, and ends it
  // The new frame is detected and checked on the worker too, unless a plugin detects it; the views
  // read the shown frame's result meanwhile, as they read the world's snapshot.
  std::function<void(const Frame&)> detect;
  if (m.detection_can_leave_thread()) {
    m.shown_result = std::make_unique<FrameResult>(m.pipeline.result());
    m.shown_detector_bytes = m.pipeline.detector().own_bytes();
    m.shown_detect = m.pipeline.detect_options();
    detect = [&m](const Frame& next) { m.detect_on_worker(next); };
  }
  if (!sim->begin_step(std::move(detect))) {
    m.watch.disarm();  // no thread: the next step() steps here as it always did
    m.shown_result.reset();
  }
}

std::shared_ptr<const FrameTrace> FrameLoopState::shown_trace() {
  FrameResult& shown = *shown_result;
  if (shown.trace || pipeline.options().fault == Fault::StalePositions) return shown.trace;
  const std::string& algorithm = pipeline.options().algorithm;
  try {
    const std::unique_ptr<Detector> detector = make_lane_detector(algorithm);
    shown.trace = trace_frame(*detector, now(), shown_detect, frame_number(), shown.selected().grid);
  } catch (const Error& e) {
    // Refused as Pipeline::trace refuses it: kept with its reason, not tried again every UI frame.
    auto refused = std::make_shared<FrameTrace>(refused_trace(frame_number(), algorithm));
    refused->refusal = e.what();
    shown.trace = std::move(refused);
  }
  return shown.trace;
}

bool FrameLoopState::settle() {
  if (!pending()) return false;
  const Unwatch unwatch{watch};
  const bool detected = shown_result != nullptr;
  // The pipeline is this thread's again however the step ends.
  struct Back {
    FrameLoopState& m;
    ~Back() {
      m.shown_result.reset();
      m.apply_wanted_traces();
    }
  } back{*this};
  const double physics_ms = simulation()->finish_step();  // rethrows the step's (or its detection's) Error
  set_physics_ms(physics_ms);
  physics_overlapped = true;
  detection_overlapped = detected;
  if (detected) publish(FrameChange::Kind::stepped);
  else detect_and_check(FrameChange::Kind::stepped);
  return true;
}

}  // namespace nbscope

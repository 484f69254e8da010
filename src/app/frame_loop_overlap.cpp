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
  if (sim == nullptr || sim->pending() || m.frames().showing_past() || sim->resuming()) return;
  // As step() does: the stale-positions fault detects the next frame on this one's positions.
  if (m.lanes().options().fault == Fault::StalePositions) m.lanes().remember_previous(m.frame_number() + 1, m.now());
  m.watch_step();  // settle() moves the note on to the detection, and ends it
  // The new frame is detected and checked on the worker too, unless a plugin detects it; the views
  // read the shown frame's result meanwhile, as they read the world's snapshot.
  std::function<void(const Frame&)> detect;
  if (m.detection_can_leave_thread()) {
    m.pipeline.lend();
    detect = [&m](const Frame& next) { m.detect_on_worker(next); };
  }
  if (!sim->begin_step(std::move(detect))) {
    m.watch.disarm();  // no thread: the next step() steps here as it always did
    m.pipeline.take_back();
  }
}

void LoopPipeline::lend() {
  shown_result_ = std::make_unique<FrameResult>(pipeline_.result());
  shown_detector_bytes_ = pipeline_.detector().own_bytes();
  shown_detect_ = pipeline_.detect_options();
}

void LoopPipeline::take_back() {
  shown_result_.reset();
  if (wanted_traces_) pipeline_.set_record_traces(*wanted_traces_);
  wanted_traces_.reset();
}

std::shared_ptr<const FrameTrace> LoopPipeline::shown_trace() {
  FrameResult& shown = *shown_result_;
  if (shown.trace || pipeline_.options().fault == Fault::StalePositions) return shown.trace;
  const std::string& algorithm = pipeline_.options().algorithm;
  try {
    const std::unique_ptr<Detector> detector = make_lane_detector(algorithm);
    shown.trace = trace_frame(*detector, source_.elements(), shown_detect_, source_.frame(), shown.selected().grid);
  } catch (const Error& e) {
    // Refused as Pipeline::trace refuses it: kept with its reason, not tried again every UI frame.
    auto refused = std::make_shared<FrameTrace>(refused_trace(source_.frame(), algorithm));
    refused->refusal = e.what();
    shown.trace = std::move(refused);
  }
  return shown.trace;
}

bool FrameLoopState::settle() {
  if (!pending()) return false;
  const Unwatch unwatch{watch};
  const bool detected = pipeline.shown_result_ != nullptr;  // lent: the worker detected the step
  // The pipeline is this thread's again however the step ends.
  struct Back {
    LoopPipeline& pipeline;
    ~Back() { pipeline.take_back(); }
  } back{pipeline};
  const double physics_ms = simulation()->finish_step();  // rethrows the step's (or its detection's) Error
  set_physics_ms(physics_ms);
  source.physics_overlapped_ = true;
  source.detection_overlapped_ = detected;
  if (detected) publish(FrameChange::Kind::stepped);
  else detect_and_check(FrameChange::Kind::stepped);
  return true;
}

}  // namespace nbscope

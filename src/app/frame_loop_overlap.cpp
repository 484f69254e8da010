// FrameLoop's overlapped step: Box2D steps frame k+1 on a worker thread while the window draws
// frame k, and the next step() adopts it, so that the window's frame takes the longer of physics
// and everything else rather than their sum.
//
// The world, its worker and the snapshot the accessors read meanwhile are physics/live_world.hpp's
// (why it is safe, why it is the same frame); this file arms the slow-frame note and runs the
// adopted frame through the same detect_and_check() step() runs (tests/app/test_frame_loop_overlap.cpp).
#include "app/frame_loop_impl.hpp"

namespace nbscope {

void FrameLoop::begin_step() {
  FrameLoopState& m = *impl_;
  Simulation* sim = m.simulation();
  if (sim == nullptr || sim->pending() || m.source().showing_past() || sim->resuming()) return;
  // As step() does: the stale-positions fault detects the next frame on this one's positions.
  if (m.pipeline.options().fault == Fault::StalePositions) m.pipeline.remember_previous(m.frame_number() + 1, m.now());
  m.watch_step();  // settle() moves the note on to the detection, and ends it
  if (!sim->begin_step()) m.watch.disarm();  // no thread: the next step() steps here as it always did
}

bool FrameLoopState::settle() {
  if (!pending()) return false;
  const Unwatch unwatch{watch};
  const double physics_ms = simulation()->finish_step();  // rethrows the step's Error; the future is spent either way
  set_physics_ms(physics_ms);
  physics_overlapped = true;
  detect_and_check(FrameChange::Kind::stepped);
  return true;
}

}  // namespace nbscope

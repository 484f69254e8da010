// FrameLoop's overlapped step: Box2D steps frame k+1 on a worker thread while the window draws
// frame k, and the next step() adopts it, so that the window's frame takes the longer of physics
// and everything else rather than their sum.
//
// Why it is safe: the worker touches only the PhysicsWorld (its b2World, bodies, elements, poses),
// and between begin_step() and the adoption this thread calls nothing of it, nor any Box2D code
// that keeps global state (b2Distance's and the TOI's counters, b2Contact's registers; a new world
// is built only after waiting): the accessors read ShownFrame, a copy taken before the worker
// starts, and members the worker never sees (lanes, checker, history; the box2d detector's own
// b2DynamicTree shares nothing). Every call that needs the world adopts the step first (settle) or
// waits for the worker. The future's get()/wait() is the synchronisation point: the worker's
// writes happen-before its return.
//
// Why it is the same frame: the worker runs the very PhysicsWorld::step() that step() runs, on the
// same world in the same order (Box2D is deterministic), and the adoption then runs the same
// detect_and_check() step() runs; only the thread differs (tests/app/test_frame_loop_overlap.cpp).
#include <system_error>

#include "app/frame_loop_impl.hpp"

namespace nbscope {

void FrameLoop::begin_step() {
  Impl& m = *impl_;
  if (m.pending() || !m.world || m.kept || m.resume_world) return;
  PhysicsWorld& world = *m.world;
  ShownFrame& shown = m.shown;
  shown.frame = world.frame();
  shown.time = world.time();
  shown.bodies = world.body_count();
  shown.dragging = world.dragging();
  shown.elements = world.elements();
  shown.sources = world.sources();
  world.shapes(shown.shapes);
  // As step() does: the stale-positions fault detects the next frame on this one's positions.
  m.stale = world.elements();
  m.stale_for = world.frame() + 1;
  m.watch_physics();  // settle() moves the note on to the detection, and ends it
  try {
    m.stepping = std::async(std::launch::async, [&world] {
      const auto t0 = Clock::now();
      world.step();
      return ms_since(t0);
    });
  } catch (const std::system_error&) {
    // No thread to be had: nothing is pending, and the next step() steps here as it always did.
    m.watch.disarm();
  }
}

bool FrameLoop::step_pending() const { return impl_->pending(); }
bool FrameLoop::physics_overlapped() const { return impl_->physics_overlapped; }

bool FrameLoop::Impl::settle() {
  if (!pending()) return false;
  const Unwatch unwatch{watch};
  const double physics_ms = stepping.get();  // rethrows the step's Error; the future is spent either way
  set_physics_ms(physics_ms);
  physics_overlapped = true;
  detect_and_check();
  return true;
}

void FrameLoop::Impl::discard_step() {
  if (!pending()) return;
  try {
    stepping.get();
  } catch (const std::exception&) {
    // The world that failed to step is being replaced: its error goes with it.
  }
}

}  // namespace nbscope

// nbscope physics: re-simulating a run to a past frame (resume.hpp).
#include "physics/resume.hpp"

#include <chrono>

#include "core/error.hpp"

namespace nbscope {

void Resume::begin(const Scene& scene, std::int64_t target) {
  world_ = std::make_unique<PhysicsWorld>(scene);
  path_ = scene.path;
  target_ = target;
  next_drag_ = 0;
  divergence_.clear();
}

bool Resume::advance(double budget_ms, const std::vector<DragInput>& drags, const HashOf& hash_of) {
  if (!world_) return true;
  PhysicsWorld& w = *world_;
  const auto t0 = std::chrono::steady_clock::now();
  const auto ms = [&] { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count(); };
  do {
    if (w.frame() >= target_) break;
    // The drags made on this frame, in their order, then the step, as the original run did.
    while (next_drag_ < drags.size() && drags[next_drag_].frame <= w.frame()) replay_drag(w, drags[next_drag_++]);
    if (w.frame() + 1 == target_) previous_ = w.elements();
    try {
      w.step();
    } catch (const Error& e) {
      const std::int64_t at = w.frame();
      cancel();  // `w` is gone after this
      throw Error(path_ + ": resuming at frame " + std::to_string(at) + ": " + e.what());
    }
    // Determinism check: every kept frame on the way must come back exactly.
    if (!divergence_.first())
      if (const std::uint64_t before = hash_of(w.frame()); before != 0) divergence_.compare(w.frame(), before, hash_elements(w.elements()));
  } while (ms() < budget_ms);
  return w.frame() >= target_;
}

void Resume::cancel() {
  world_.reset();
  target_ = -1;
}

std::pair<std::int64_t, std::int64_t> Resume::progress() const {
  if (!world_) return {0, 0};
  return {world_->frame(), target_};
}

void Resume::reset() {
  cancel();
  divergence_.clear();
}

std::unique_ptr<PhysicsWorld> Resume::take_world() {
  target_ = -1;
  if (world_ && world_->frame() == 0) previous_ = world_->elements();
  return std::move(world_);
}

}  // namespace nbscope

// nbscope physics: continuing a run from a past frame K, and the check that a run made again is the
// run made the first time.
//
//   Resume       a fresh world built from the scene and stepped to K with the drags the run logged
//                (physics/live_world.hpp), a few frames per call so that the window stays live;
//                Box2D is deterministic, so it arrives at K bit for bit.
// Divergence (physics/divergence.hpp) checks it arrives at K as the run did.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "physics/divergence.hpp"
#include "physics/live_world.hpp"

namespace nbscope {

class Resume {
 public:
  // The hash the run had at a frame (0 when it is not known).
  using HashOf = std::function<std::uint64_t(std::int64_t frame)>;

  // Starts re-simulating `scene` towards frame `target` (a past frame of the run).
  void begin(const Scene& scene, std::int64_t target);
  // Re-simulates for about `budget_ms` of wall time (at least one step when not there yet), replaying
  // `drags` at their frames and comparing each frame with `hash_of`; true once at the target. Throws
  // Error "path: resuming at frame K: ..." (the resume is cancelled) when a step refuses.
  bool advance(double budget_ms, const std::vector<DragInput>& drags, const HashOf& hash_of);
  // Stops before arriving.
  void cancel();
  // True between begin() and arriving or cancelling.
  [[nodiscard]] bool active() const { return world_ != nullptr; }
  // The frame being resumed from (-1 when none).
  [[nodiscard]] std::int64_t target() const { return target_; }
  // Frames re-simulated so far and the target.
  [[nodiscard]] std::pair<std::int64_t, std::int64_t> progress() const;
  // The first re-simulated frame that differed from the run's (kept after arriving).
  [[nodiscard]] std::optional<std::int64_t> divergence() const { return divergence_.first(); }
  // Forgets the divergence (a new run).
  void reset();
  // After arriving: the world at the target (the resume is then over), and the elements of the frame
  // before it (the target's own for frame 0).
  [[nodiscard]] std::unique_ptr<PhysicsWorld> take_world();
  [[nodiscard]] const Elements& previous_elements() const { return previous_; }

 private:
  std::unique_ptr<PhysicsWorld> world_;
  std::string path_;
  std::int64_t target_ = -1;
  std::size_t next_drag_ = 0;
  Elements previous_;
  Divergence divergence_;
};

}  // namespace nbscope

// nbscope physics: a past frame of a world, rebuilt from what the history kept of it (WorldState)
// and the world's fixed geometry: the same elements, shapes, tight AABBs, F, G, T and scope of
// A-in-F the live world had at that frame, bit for bit, without stepping anything.
//
// G and T come from the same grid over the frame's tight AABBs as the live world's
// (physics/aabb_pairs.hpp), and the same touching test.
#pragma once
#include <memory>
#include <vector>

#include "physics/frame.hpp"
#include "physics/world.hpp"

namespace nbscope {

// Also a Frame: the frame a past frame shows (the run's own next frame is kept, nothing steps it).
class KeptWorldFrame final : public Box2dFrame, public Frame {
 public:
  // `world` supplies the shapes and bodies (it must be the same scene's world, at this frame or
  // later, and outlive this object); `state` the frame's transforms and contact list.
  KeptWorldFrame(const PhysicsWorld& world, std::shared_ptr<const WorldState> state);

  [[nodiscard]] std::int64_t frame() const override { return state_->frame; }
  [[nodiscard]] double time() const override { return state_->time; }
  [[nodiscard]] const Elements& elements() const override { return elements_; }
  [[nodiscard]] std::int64_t body_count() const override { return static_cast<std::int64_t>(state_->poses.size()); }
  void contact_pairs(PairList& out) const override { state_->contacts.unpack(out); }
  void ground_truth(PairList& tight_aabb_pairs, PairList& touching) const override;
  void in_box2d_scope(const PairList& pairs, PairList& out, Box2dScope& why_not) const override;
  void shapes(std::vector<BodyShape>& out) const override;
  // Frame: the world's element sources, the shapes, this frame as Box2D's side.
  [[nodiscard]] const std::vector<ElementSource>& element_sources() const override { return world_.sources(); }
  void body_shapes(std::vector<BodyShape>& out) const override { shapes(out); }
  [[nodiscard]] const Box2dFrame* box2d() const override { return this; }
  // The kept state this frame was rebuilt from.
  [[nodiscard]] const WorldState& state() const { return *state_; }

 private:
  const PhysicsWorld& world_;
  std::shared_ptr<const WorldState> state_;
  std::vector<b2Transform> poses_;
  Elements elements_;
  std::vector<b2AABB> aabbs_;
  mutable AabbPairFinder aabb_pairs_;  // scratch of ground_truth()
};

}  // namespace nbscope

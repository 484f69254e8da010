#include "physics/kept_frame.hpp"

#include <algorithm>
#include <cassert>

namespace nbscope {

KeptWorldFrame::KeptWorldFrame(const PhysicsWorld& world, std::shared_ptr<const WorldState> state)
    : world_(world), state_(std::move(state)) {
  assert(state_ != nullptr && "KeptWorldFrame: no state");
  assert(static_cast<std::size_t>(state_->fixtures) <= world_.fixtures_.size() &&
         "KeptWorldFrame: the state has more fixtures than the world (another scene's state?)");
  poses_.resize(state_->poses.size());
  for (std::size_t b = 0; b < poses_.size(); ++b) {
    const BodyPose& p = state_->poses[b];
    poses_[b].p.Set(p.x, p.y);
    poses_[b].q.s = p.s;
    poses_[b].q.c = p.c;
  }
  world_.geometry_at(poses_, static_cast<std::size_t>(state_->fixtures), elements_, aabbs_);
}

void KeptWorldFrame::ground_truth(PairList& tight_aabb_pairs, PairList& touching) const {
  aabb_pairs_.find(aabbs_.data(), aabbs_.size(), tight_aabb_pairs);
  world_.touching_of(tight_aabb_pairs, poses_, elements_, touching);
}

void KeptWorldFrame::in_box2d_scope(const PairList& pairs, PairList& out, Box2dScope& why_not) const {
  world_.scope_at(pairs, aabbs_, out, why_not);
}

void KeptWorldFrame::shapes(std::vector<BodyShape>& out) const {
  world_.shapes_at(poses_, static_cast<std::size_t>(state_->fixtures), out);
}

}  // namespace nbscope

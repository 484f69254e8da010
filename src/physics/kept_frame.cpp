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
  tight_aabb_pairs.clear();
  touching.clear();
  b2DynamicTree tree;
  for (std::size_t i = 0; i < aabbs_.size(); ++i)
    tree.CreateProxy(aabbs_[i], reinterpret_cast<void*>(static_cast<std::uintptr_t>(i)));
  struct Query {
    const KeptWorldFrame* self = nullptr;
    const b2DynamicTree* tree = nullptr;
    ElementId i = 0;
    PairList* g = nullptr;
    PairList* t = nullptr;
    bool QueryCallback(std::int32_t proxy) {
      const auto j = static_cast<ElementId>(reinterpret_cast<std::uintptr_t>(tree->GetUserData(proxy)));
      const auto& boxes = self->aabbs_;
      if (j <= i || !b2TestOverlap(boxes[static_cast<std::size_t>(i)], boxes[static_cast<std::size_t>(j)])) return true;
      g->push_back({i, j});
      if (self->world_.touching_at(i, j, self->poses_, self->elements_)) t->push_back({i, j});
      return true;
    }
  } query{this, &tree, 0, &tight_aabb_pairs, &touching};
  const auto by_j = [](const Pair& x, const Pair& y) { return x.j < y.j; };
  for (std::size_t i = 0; i < aabbs_.size(); ++i) {
    query.i = static_cast<ElementId>(i);
    const std::size_t g0 = tight_aabb_pairs.size(), t0 = touching.size();
    tree.Query(&query, aabbs_[i]);
    std::sort(tight_aabb_pairs.begin() + static_cast<std::ptrdiff_t>(g0), tight_aabb_pairs.end(), by_j);
    std::sort(touching.begin() + static_cast<std::ptrdiff_t>(t0), touching.end(), by_j);
  }
}

void KeptWorldFrame::in_box2d_scope(const PairList& pairs, PairList& out, Box2dScope& why_not) const {
  world_.scope_at(pairs, aabbs_, out, why_not);
}

void KeptWorldFrame::shapes(std::vector<BodyShape>& out) const {
  world_.shapes_at(poses_, static_cast<std::size_t>(state_->fixtures), out);
}

}  // namespace nbscope

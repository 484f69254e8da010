// PhysicsWorld's limits (physics/world_limits.hpp): the contact estimate before Box2D steps, the
// contact count after every sub-step, and every body finite and inside the world after the step.
// Each refusal is one line naming the frame (and the body), remembered so the world steps no more.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "physics/world.hpp"

namespace nbscope {

namespace {

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

std::string limit_text(std::int64_t limit) {
  return "the limit is " + grouped(limit) + " (raise it with --max-contacts or the scene's \"max_contacts\")";
}

}  // namespace

std::string PhysicsWorld::body_name(std::size_t body) const {
  const std::string s = "body " + std::to_string(body);
  const BodyOrigin& o = origins_[body];
  if (o.generator == -1) return s + " (bodies[" + std::to_string(o.ordinal) + "])";
  if (o.generator >= 0) return s + " (generators[" + std::to_string(o.generator) + "] #" + std::to_string(o.ordinal) + ")";
  return s;
}

void PhysicsWorld::refuse(const std::string& what) {
  broken_ = (scene_.path.empty() ? "" : scene_.path + ": ") + "frame " + std::to_string(frame_ + 1) + ": " + what;
  throw Error(broken_);
}

std::int64_t PhysicsWorld::estimate_contacts() const {
  const float dt = static_cast<float>(scene_.time_step / scene_.sub_steps);
  const float margin = b2_aabbExtension;
  std::vector<CountBox> boxes;
  boxes.reserve(fixtures_.size());
  for (std::size_t i = 0; i < fixtures_.size(); ++i) {
    const b2Fixture* f = fixtures_[i];
    const b2Body* body = f->GetBody();
    b2AABB box;
    f->GetShape()->ComputeAABB(&box, body->GetTransform(), 0);
    // The next sub-step's displacement as Box2D clamps it, swept and then stretched ahead by
    // b2_aabbMultiplier as b2DynamicTree::MoveProxy does: 5x the displacement beyond the box.
    b2Vec2 d = dt * body->GetLinearVelocity();
    if (d.LengthSquared() > b2_maxTranslationSquared) d *= b2_maxTranslation / d.Length();
    d *= 1.0f + b2_aabbMultiplier;
    boxes.push_back({std::min(box.lowerBound.x, box.lowerBound.x + d.x) - margin,
                     std::min(box.lowerBound.y, box.lowerBound.y + d.y) - margin,
                     std::max(box.upperBound.x, box.upperBound.x + d.x) + margin,
                     std::max(box.upperBound.y, box.upperBound.y + d.y) + margin, sources_[i].body,
                     dynamic_[static_cast<std::size_t>(sources_[i].body)] != 0});
    const CountBox& c = boxes.back();
    if (!(std::isfinite(c.x0) && std::isfinite(c.y0) && std::isfinite(c.x1) && std::isfinite(c.y1))) return -1;
  }
  return count_overlapping_boxes(boxes);
}

bool PhysicsWorld::estimate_needed() const {
  // New bodies (the first frame, an emitter's) may land anywhere; Box2D's count near the limit
  // may cross it.
  if (estimate_due_ || world_->GetContactCount() > max_contacts_ / 4) return true;
  // Otherwise the contacts can grow much in one frame only where fat AABBs stretch far beyond the
  // bodies: fast bodies, whose boxes reach (sub_steps + b2_aabbMultiplier) displacements ahead.
  float fastest = 0;
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    if (dynamic_[b] != 0 || bodies_[b]->GetType() == b2_kinematicBody) fastest = std::max(fastest, bodies_[b]->GetLinearVelocity().LengthSquared());
  const double step = std::min(std::sqrt(static_cast<double>(fastest)) * scene_.time_step / scene_.sub_steps, double{b2_maxTranslation});
  return (scene_.sub_steps + b2_aabbMultiplier) * step > 8 * elements_.max_radius();
}

void PhysicsWorld::check_contact_estimate() {
  if (!estimate_needed()) {
    // About as many as Box2D has now (before the first step it has none yet: the estimate stays).
    if (frame_ > 0) estimated_contacts_.store(world_->GetContactCount(), std::memory_order_relaxed);
    return;
  }
  estimate_due_ = false;
  const std::int64_t n = estimate_contacts();
  if (n < 0) return;  // a non-finite body: check_bodies() names it after the step
  estimated_contacts_.store(n, std::memory_order_relaxed);
  if (n <= max_contacts_) return;
  refuse("Box2D would create about " + grouped(n) + " contacts (" + bytes_text(static_cast<double>(n) * static_cast<double>(bytes_per_contact())) +
         ") between the fat AABBs of " + grouped(static_cast<std::int64_t>(bodies_.size())) + " bodies; " + limit_text(max_contacts_));
}

void PhysicsWorld::check_contact_count(int sub_step) {
  const std::int64_t n = world_->GetContactCount();
  if (n <= max_contacts_) return;
  refuse("Box2D made " + grouped(n) + " contacts (" + bytes_text(static_cast<double>(n) * static_cast<double>(bytes_per_contact())) +
         ") in sub-step " + std::to_string(sub_step + 1) + " of " + std::to_string(scene_.sub_steps) + " among " +
         grouped(static_cast<std::int64_t>(bodies_.size())) + " bodies; " + limit_text(max_contacts_));
}

void PhysicsWorld::check_bodies() {
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    const b2Vec2 p = bodies_[b]->GetPosition(), v = bodies_[b]->GetLinearVelocity();
    const float a = bodies_[b]->GetAngle(), w = bodies_[b]->GetAngularVelocity();
    const bool position = std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(a);
    if (!position || !(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(w))) {
      refuse(body_name(b) + " has a non-finite " + (position ? "velocity" : "position") + " after the step (position (" +
             number_text(p.x) + ", " + number_text(p.y) + ") m, angle " + number_text(a) + ", velocity (" + number_text(v.x) + ", " +
             number_text(v.y) + ") m/s, angular velocity " + number_text(w) + "): Box2D's simulation broke down");
    }
    if (std::abs(p.x) > kMaxWorldCoordinate || std::abs(p.y) > kMaxWorldCoordinate) {
      refuse(body_name(b) + " is at (" + number_text(p.x) + ", " + number_text(p.y) + ") m, beyond +-" +
             grouped(static_cast<std::int64_t>(kMaxWorldCoordinate)) +
             " m: it has left any sensible world (Box2D's float positions there are 0.0625 m apart)");
    }
  }
}

}  // namespace nbscope

// PhysicsWorld's limits (physics/world_limits.hpp): the contact estimate before Box2D steps, the
// contact count after every sub-step, and every body finite and inside the world after the step.
// Each refusal is one line naming the frame (and the body), remembered so the world steps no more.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "physics/fixture_shape.hpp"
#include "physics/world.hpp"

namespace nbscope {

namespace {

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

// What `contacts` Box2D contacts take.
std::string contact_bytes_text(std::int64_t contacts) {
  return bytes_text(static_cast<double>(contacts) * static_cast<double>(bytes_per_contact()));
}

std::string limit_text(std::int64_t limit) {
  return "the limit is " + grouped(limit) + " (raise it with --max-contacts or the scene's \"max_contacts\")";
}

// "0" or "a denormal (1e-40)": what a float below FLT_MIN is.
std::string tiny_text(float v) { return v == 0 ? std::string("0") : "a denormal (" + number_text(v) + ")"; }

}  // namespace

std::string box2d_float_trouble(const BodySpec& body) {
  const bool several = body.fixtures.size() > 1;
  const auto fixture = [&](std::size_t k) { return several ? "fixtures[" + std::to_string(k) + "]: " : std::string(); };
  std::vector<b2MassData> masses(body.fixtures.size());
  for (std::size_t k = 0; k < body.fixtures.size(); ++k) {
    const ShapeSpec& s = body.fixtures[k];
    const FixtureShape shape(s);
    if (s.kind == ShapeKind::Circle && !(shape.circle.m_radius >= FLT_MIN))
      return fixture(k) + "radius " + number_text(s.radius) + " m is " + tiny_text(shape.circle.m_radius) +
             " in Box2D's float (at least " + number_text(FLT_MIN) + " m)";
    shape.shape->ComputeMass(&masses[k], static_cast<float>(s.density));
    if (body.type == BodyType::Dynamic && s.density > 0 && !(masses[k].mass >= FLT_MIN))
      return fixture(k) + "its mass in Box2D's float is " + tiny_text(masses[k].mass) + " kg (density " + number_text(s.density) +
             "), whose inverse is infinite: Box2D's first step would turn the body NaN; make it larger or denser";
  }
  if (body.type != BodyType::Dynamic) return "";  // Box2D gives static and kinematic bodies no mass
  // b2Body::ResetMassData after fixture k is created: its list holds fixtures k..0, newest first.
  for (std::size_t k = 0; k < body.fixtures.size(); ++k) {
    if (!(static_cast<float>(body.fixtures[k].density) > 0)) continue;  // CreateFixture resets the mass only then
    float mass = 0, inertia = 0;
    b2Vec2 centre(0, 0);
    for (std::size_t j = k + 1; j-- > 0;) {
      if (static_cast<float>(body.fixtures[j].density) == 0) continue;
      mass += masses[j].mass;
      centre += masses[j].mass * masses[j].center;
      inertia += masses[j].I;
    }
    centre *= 1.0f / mass;
    if (!(inertia > 0)) continue;
    inertia -= mass * b2Dot(centre, centre);
    if (!(inertia >= FLT_MIN))
      return "its rotational inertia about its centre of mass is " + (inertia > 0 ? tiny_text(inertia) : number_text(inertia)) +
             " in Box2D's float (shapes far smaller than their distance from the body's origin): Box2D would stop on an assertion";
  }
  return "";
}

std::string PhysicsWorld::body_name(std::size_t body) const {
  const std::string s = "body " + std::to_string(body);
  const BodyOrigin& o = origins_[body];
  if (o.generator == -1) return s + " (bodies[" + std::to_string(o.ordinal) + "])";
  if (o.generator >= 0) return s + " (generators[" + std::to_string(o.generator) + "] #" + std::to_string(o.ordinal) + ")";
  return s;
}

std::string PhysicsWorld::frame_prefix() const {
  return (scene_.path.empty() ? "" : scene_.path + ": ") + "frame " + std::to_string(frame_ + 1) + ": ";
}

void PhysicsWorld::refuse(const std::string& what) {
  broken_ = frame_prefix() + what;
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
  if (estimate_due_ || world_->GetContactCount() > std::min(max_contacts_, memory_contact_limit_) / 4) return true;
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
  const std::string contacts = "Box2D would create about " + grouped(n) + " contacts (" + contact_bytes_text(n) + ") between the fat AABBs of " +
                               grouped(static_cast<std::int64_t>(bodies_.size())) + " bodies; ";
  if (n > max_contacts_) refuse(contacts + limit_text(max_contacts_));
  update_memory_limit();
  if (n > memory_contact_limit_) refuse(contacts + memory_text());
  check_emitter_growth(n);
}

void PhysicsWorld::check_emitter_growth(std::int64_t n) {
  // Checkpoints from 64 bodies on, each at twice the bodies of the last: the growth between two
  // is contacts ~ bodies^k. A pile Box2D parts (gravity, a box, bodies given speed) grows with k
  // about 1 or less and some 3 to 6 contacts a body; bodies left on top of each other, k about 2.
  constexpr std::int64_t kFirstCheckpoint = 64;
  constexpr double kSquareLike = 1.5;
  constexpr std::int64_t kPiledContactsPerBody = 8;
  std::int64_t to_come = 0;
  for (std::size_t e = 0; e < emitters_.size(); ++e)
    to_come += scene_.generators[static_cast<std::size_t>(emitter_generators_[e])].count - emitters_[e].emitted();
  const auto b = static_cast<std::int64_t>(bodies_.size());
  if (to_come == 0 || b < kFirstCheckpoint) return;
  if (growth_bodies_ == 0 || n == 0 || growth_contacts_ == 0) {
    growth_bodies_ = b;
    growth_contacts_ = n;
    return;
  }
  if (b < 2 * growth_bodies_) return;
  const std::int64_t before_b = growth_bodies_, before_n = growth_contacts_;
  growth_bodies_ = b;
  growth_contacts_ = n;
  const double k = std::log(static_cast<double>(n) / static_cast<double>(before_n)) / std::log(static_cast<double>(b) / static_cast<double>(before_b));
  if (k < kSquareLike || n < kPiledContactsPerBody * b) return;
  const double projected = static_cast<double>(n) * std::pow(static_cast<double>(b + to_come) / static_cast<double>(b), k);
  const std::int64_t limit = std::min(max_contacts_, memory_contact_limit_);
  if (projected <= static_cast<double>(limit)) return;
  char growth[16];
  std::snprintf(growth, sizeof growth, "%.1f", k);
  const auto about = static_cast<std::int64_t>(std::min(projected, 1e18));
  refuse("the emitters' bodies pile up: " + grouped(b) + " bodies make about " + grouped(n) + " contacts, where " + grouped(before_b) + " made " +
         grouped(before_n) + " (contacts growing as bodies^" + growth + "); with the " + grouped(to_come) + " still to come, about " + grouped(about) +
         " contacts (" + contact_bytes_text(about) + "); " + (limit == max_contacts_ ? limit_text(max_contacts_) : memory_text()));
}

void PhysicsWorld::update_memory_limit() {
  memory_ = memory_budget_now();
  if (!memory_.bytes) {
    memory_contact_limit_ = kMaxMaxContacts;
    return;
  }
  // What the contacts Box2D holds take is theirs already (its allocator reuses a destroyed
  // contact's memory); what the process can still get comes on top.
  const double held = static_cast<double>(world_->GetContactCount()), bytes = static_cast<double>(bytes_per_contact());
  memory_contact_limit_ = static_cast<std::int64_t>(std::min(held + static_cast<double>(*memory_.bytes) / bytes, double{kMaxMaxContacts}));
}

std::string PhysicsWorld::memory_text() const {
  return "this process can get about " + contact_bytes_text(memory_contact_limit_) + " for them (" + memory_.source +
         "; --max-contacts cannot raise that)";
}

void PhysicsWorld::check_contact_count(int sub_step) {
  const std::int64_t n = world_->GetContactCount();
  if (n <= std::min(max_contacts_, memory_contact_limit_)) return;
  refuse("Box2D made " + grouped(n) + " contacts (" + contact_bytes_text(n) + ") in sub-step " + std::to_string(sub_step + 1) + " of " +
         std::to_string(scene_.sub_steps) + " among " + grouped(static_cast<std::int64_t>(bodies_.size())) + " bodies; " +
         (n > max_contacts_ ? limit_text(max_contacts_) : memory_text()));
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

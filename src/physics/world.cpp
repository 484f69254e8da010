// PhysicsWorld: building bodies from specs, stepping, and reading Box2D's pair sets back as element
// pairs. Element ids travel through Box2D as each fixture's user data.
//
// Index: building | stepping and geometry | F, G, T and the scope of A ⊆ F | shapes | mouse drag.
#include "physics/world.hpp"

#include <algorithm>
#include <cmath>
#include <typeinfo>

#include "core/error.hpp"
#include "physics/box2d_memory.hpp"
#include "physics/fixture_shape.hpp"

namespace nbscope {

namespace {

// Box2D 2.4.1 has no const GetUserData; reading it changes nothing.
ElementId element_of(const b2Fixture* f) {
  return static_cast<ElementId>(const_cast<b2Fixture*>(f)->GetUserData().pointer);
}

b2BodyType to_b2(BodyType t) {
  switch (t) {
    case BodyType::Static: return b2_staticBody;
    case BodyType::Kinematic: return b2_kinematicBody;
    case BodyType::Dynamic: return b2_dynamicBody;
  }
  return b2_dynamicBody;
}

BodyType from_b2(b2BodyType t) {
  switch (t) {
    case b2_staticBody: return BodyType::Static;
    case b2_kinematicBody: return BodyType::Kinematic;
    case b2_dynamicBody: return BodyType::Dynamic;
  }
  return BodyType::Dynamic;
}

// World centre of a body-local point, in double from Box2D's float transform. The elements and
// the circle test of T both use this, so they agree to the last bit.
inline void world_point(const b2Transform& xf, b2Vec2 p, double& x, double& y) {
  const double c = xf.q.c, s = xf.q.s, px = p.x, py = p.y;
  x = static_cast<double>(xf.p.x) + (c * px - s * py);
  y = static_cast<double>(xf.p.y) + (s * px + c * py);
}

}  // namespace

// ---- building ------------------------------------------------------------------------------

PhysicsWorld::PhysicsWorld(const Scene& scene) : scene_(scene) {
  const std::vector<BodySpec> initial = initial_bodies(scene_);
  // initial_bodies() lists the scene's bodies, then each generator's (but emitters') in file order.
  std::vector<BodyOrigin> origins;
  origins.reserve(initial.size());
  for (std::size_t i = 0; i < scene_.bodies.size(); ++i) origins.push_back({-1, static_cast<std::int64_t>(i)});
  for (std::size_t g = 0; g < scene_.generators.size(); ++g)
    if (scene_.generators[g].kind != GeneratorKind::Emitter)
      for (std::int64_t k = 0; k < scene_.generators[g].count; ++k) origins.push_back({static_cast<std::int32_t>(g), k});
  // Bodies Box2D's float cannot hold are refused before any is made, each named as the scene makes it.
  for (std::size_t b = 0; b < initial.size(); ++b)
    if (const std::string trouble = box2d_float_trouble(initial[b]); !trouble.empty())
      throw Error(initial[b].where + (b < origins.size() && origins[b].generator >= 0 ? "body #" + std::to_string(origins[b].ordinal) + ": " : "") + trouble);
  for (const GeneratorSpec& g : scene_.generators)
    if (g.kind == GeneratorKind::Emitter && g.count > 0)
      if (const std::string trouble = box2d_float_trouble(g.body); !trouble.empty()) throw Error(g.body.where + "every body it pours: " + trouble);

  world_ = std::make_unique<b2World>(to_b2(scene_.gravity));
  b2BodyDef ground_def;
  ground_ = world_->CreateBody(&ground_def);
  const Box2dAllocScope alloc_scope(world_.get(), 1, (scene_.path.empty() ? "" : scene_.path + ": ") + "building the world: ");
  world_->SetAllowSleeping(false);  // every body moves through the broadphase every frame (docs/architecture.md, "Invariants")
  world_->SetContinuousPhysics(scene_.continuous);
  elements_.dim = 2;
  max_contacts_ = scene_.max_contacts;
  bodies_.reserve(initial.size());
  for (std::size_t b = 0; b < initial.size(); ++b) add_body(initial[b], b < origins.size() ? origins[b] : BodyOrigin{-2, 0});
  for (std::size_t g = 0; g < scene_.generators.size(); ++g)
    if (scene_.generators[g].kind == GeneratorKind::Emitter) {
      emitters_.emplace_back(scene_.generators[g]);
      emitter_generators_.push_back(static_cast<std::int32_t>(g));
    }
  update_geometry();
  // Refused here rather than at the first step: frame 0's detection and check would otherwise
  // spend seconds and gigabytes on the same overlaps first.
  check_contact_estimate();
}

PhysicsWorld::~PhysicsWorld() = default;

double PhysicsWorld::largest_emitted_radius(std::string& out_where) const {
  double largest = 0;
  for (const GeneratorSpec& g : scene_.generators) {
    if (g.kind != GeneratorKind::Emitter || g.count == 0) continue;
    for (const ShapeSpec& s : g.body.fixtures) {
      const FixtureShape shape(s);
      if (shape.radius > largest) {
        largest = shape.radius;
        out_where = g.where;
      }
    }
  }
  return largest;
}

void PhysicsWorld::add_body(const BodySpec& spec, BodyOrigin origin) {
  b2BodyDef def;
  def.type = to_b2(spec.type);
  def.position = to_b2(spec.position);
  def.angle = static_cast<float>(spec.angle);
  def.linearVelocity = to_b2(spec.velocity);
  def.angularVelocity = static_cast<float>(spec.angular_velocity);
  def.userData.pointer = bodies_.size();
  b2Body* body = world_->CreateBody(&def);
  const auto body_index = static_cast<std::int32_t>(bodies_.size());
  bodies_.push_back(body);
  origins_.push_back(origin);
  bodies_now_.store(static_cast<std::int64_t>(bodies_.size()), std::memory_order_relaxed);
  dynamic_.push_back(body->GetType() == b2_dynamicBody ? 1 : 0);

  for (std::size_t k = 0; k < spec.fixtures.size(); ++k) {
    const ShapeSpec& s = spec.fixtures[k];
    const auto id = static_cast<ElementId>(fixtures_.size());
    b2FixtureDef fd;
    fd.density = static_cast<float>(s.density);
    fd.friction = static_cast<float>(s.friction);
    fd.restitution = static_cast<float>(s.restitution);
    fd.userData.pointer = static_cast<std::uintptr_t>(id);
    FixtureShape shape(s);
    fd.shape = shape.shape;
    const b2Vec2 centre = shape.centre;
    const double radius = shape.radius;
    // Our own list keeps the element order (Box2D's fixture list is newest first).
    fixtures_.push_back(body->CreateFixture(&fd));
    const b2Filter& filter = fixtures_.back()->GetFilterData();
    default_filters_ = default_filters_ && filter.categoryBits == b2Filter{}.categoryBits &&
                       filter.maskBits == b2Filter{}.maskBits && filter.groupIndex == b2Filter{}.groupIndex;
    circle_.push_back(s.kind == ShapeKind::Circle ? 1 : 0);
    local_centres_.push_back(centre);
    radii_.push_back(radius);
    sources_.push_back({body_index, static_cast<std::int32_t>(k)});
  }
}

// ---- stepping and geometry -----------------------------------------------------------------

void PhysicsWorld::step() {
  if (!broken_.empty()) throw Error(broken_);
  const Box2dAllocScope alloc_scope(world_.get(), 1, frame_prefix());  // the ground body is not the scene's
  for (std::size_t e = 0; e < emitters_.size(); ++e) {
    pending_.clear();
    emitters_[e].emit_until(time_, pending_);
    const std::int64_t first = emitters_[e].emitted() - static_cast<std::int64_t>(pending_.size());
    for (std::size_t k = 0; k < pending_.size(); ++k)
      add_body(pending_[k], {emitter_generators_[e], first + static_cast<std::int64_t>(k)});
    estimate_due_ = estimate_due_ || !pending_.empty();
  }
  // Until update_geometry() the frame's elements, AABBs and poses stay the last frame's, so that a
  // refused step leaves that frame whole (shapes() and the check read only its fixtures).
  check_contact_estimate();
  const float dt = static_cast<float>(scene_.time_step / scene_.sub_steps);
  for (int k = 0; k < scene_.sub_steps; ++k) {
    world_->Step(dt, scene_.velocity_iterations, scene_.position_iterations);
    check_contact_count(k);
  }
  check_bodies();
  ++frame_;
  time_ += scene_.time_step;
  update_geometry();
}

void PhysicsWorld::update_geometry() {
  poses_.resize(bodies_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b) poses_[b] = bodies_[b]->GetTransform();
  geometry_at(poses_, fixtures_.size(), elements_, aabbs_);
}

void PhysicsWorld::geometry_at(const std::vector<b2Transform>& poses, std::size_t n, Elements& out_elements,
                               std::vector<b2AABB>& out_aabbs) const {
  out_aabbs.resize(n);
  out_elements.dim = 2;
  if (static_cast<std::size_t>(out_elements.size()) != n) {
    out_elements.resize(static_cast<std::int64_t>(n));
    for (std::size_t i = 0; i < n; ++i) out_elements.r[static_cast<Eigen::Index>(i)] = radii_[i];
  }
  double* const x = out_elements.x.data();
  double* const y = out_elements.y.data();
  for (std::size_t i = 0; i < n; ++i) {
    const b2Transform& xf = poses[static_cast<std::size_t>(sources_[i].body)];
    world_point(xf, local_centres_[i], x[i], y[i]);
    fixtures_[i]->GetShape()->ComputeAABB(&out_aabbs[i], xf, 0);
  }
}

void PhysicsWorld::capture(WorldState& out, const PairList* contacts) const {
  out.frame = frame_;
  out.time = time_;
  out.fixtures = static_cast<std::int32_t>(aabbs_.size());
  out.poses.resize(poses_.size());
  for (std::size_t b = 0; b < poses_.size(); ++b) {
    const b2Transform& xf = poses_[b];
    out.poses[b] = BodyPose{xf.p.x, xf.p.y, xf.q.s, xf.q.c};
  }
  out.poses.shrink_to_fit();
  if (contacts != nullptr) {
    out.contacts = PackedPairs::pack(*contacts);
  } else {
    PairList f;
    contact_pairs(f);
    out.contacts = PackedPairs::pack(f);
  }
}

void PhysicsWorld::element_centre(const WorldState& state, ElementId k, double& x, double& y) const {
  const auto i = static_cast<std::size_t>(k);
  element_centre(state, sources_[i], local_centres_[i], x, y);
}

void PhysicsWorld::element_centre(const WorldState& state, const ElementSource& source, b2Vec2 local_centre, double& x,
                                  double& y) {
  const BodyPose& p = state.poses[static_cast<std::size_t>(source.body)];
  b2Transform xf;
  xf.p.Set(p.x, p.y);
  xf.q.s = p.s;
  xf.q.c = p.c;
  world_point(xf, local_centre, x, y);
}

// ---- F, G, T and the scope of A ⊆ F --------------------------------------------------------

void PhysicsWorld::contact_pairs(PairList& out) const {
  // The walk is a chain of cache misses: a contact's successor is known only once the contact is
  // loaded. But the list keeps its order from one frame to the next (Box2D pushes new contacts at
  // its head and unlinks destroyed ones), so the walk follows where it is in the last walk's order
  // and fetches the contacts met there a little further on ahead of time. Where the order differs,
  // prefetches are wasted and the result is the same.
  constexpr std::size_t kAhead = 16;          // contacts fetched ahead
  constexpr std::size_t kNear = 16, kFar = 256;  // how far the last order is searched for the contact met
  constexpr std::size_t kMissesBeforeFar = 8;
  // Addresses only: the last walk's contacts may be destroyed by now (prefetching them is harmless).
  std::vector<std::uintptr_t>& last = contact_order_;
  std::vector<std::uintptr_t>& now = contact_order_next_;
  const std::size_t n = last.size();
  now.clear();
  out.clear();
  out.reserve(static_cast<std::size_t>(world_->GetContactCount()));
  std::size_t k = 0, misses = 0;  // the walk is at last[k]
  for (const b2Contact* contact = world_->GetContactList(); contact != nullptr; contact = contact->GetNext()) {
    const auto c = reinterpret_cast<std::uintptr_t>(contact);
    if (k < n && last[k] == c) {
      ++k;
      misses = 0;
    } else {
      // Contacts destroyed since the last walk are skipped; a new contact is not found.
      const std::size_t reach = std::min(n - std::min(n, k), misses >= kMissesBeforeFar ? kFar : kNear);
      std::size_t s = 1;
      while (s < reach && last[k + s] != c) ++s;
      if (s < reach) {
        k += s + 1;
        misses = 0;
      } else {
        misses = misses >= kMissesBeforeFar ? 0 : misses + 1;
      }
    }
    if (k + kAhead < n) {
      // What the walk reads of a contact (links, fixtures) lies in its first 112 bytes (b2Contact, 2.4.1).
      const auto* next = reinterpret_cast<const char*>(last[k + kAhead]);
      __builtin_prefetch(next);
      __builtin_prefetch(next + 64);
      __builtin_prefetch(next + 111);
    }
    now.push_back(c);
    const ElementId a = element_of(contact->GetFixtureA()), b = element_of(contact->GetFixtureB());
    // Fixtures added by a step that was then refused are not elements of the frame shown.
    if (static_cast<std::size_t>(std::max(a, b)) >= aabbs_.size()) continue;
    out.push_back(a < b ? Pair{a, b} : Pair{b, a});
  }
  last.swap(now);
  contact_sorter_.sort(out, fixtures_.size());  // linear: a counting sort by i
}

bool PhysicsWorld::tight_aabbs_overlap(ElementId a, ElementId b) const {
  return b2TestOverlap(aabbs_[static_cast<std::size_t>(a)], aabbs_[static_cast<std::size_t>(b)]);
}

bool PhysicsWorld::touching_at(ElementId a, ElementId b, const std::vector<b2Transform>& poses,
                               const Elements& elements) const {
  const auto ia = static_cast<std::size_t>(a), ib = static_cast<std::size_t>(b);
  if (circle_[ia] != 0 && circle_[ib] != 0) {
    // Same centres and radii as the elements (see world_point; a circle's radius is its shape's
    // m_radius), and Box2D's circle rule.
    const double dx = elements.x[a] - elements.x[b];
    const double dy = elements.y[a] - elements.y[b];
    const double rr = radii_[ia] + radii_[ib];
    return dx * dx + dy * dy <= rr * rr;
  }
  const b2Fixture* fa = fixtures_[ia];
  const b2Fixture* fb = fixtures_[ib];
  const b2Transform& xa = poses[static_cast<std::size_t>(sources_[static_cast<std::size_t>(a)].body)];
  const b2Transform& xb = poses[static_cast<std::size_t>(sources_[static_cast<std::size_t>(b)].body)];
  return b2TestOverlap(fa->GetShape(), 0, fb->GetShape(), 0, xa, xb);
}

void PhysicsWorld::ground_truth(PairList& tight_aabb_pairs, PairList& touching_pairs) const {
  aabb_pairs_.find(aabbs_.data(), aabbs_.size(), tight_aabb_pairs);
  touching_of(tight_aabb_pairs, poses_, elements_, touching_pairs);
}

void PhysicsWorld::touching_of(const PairList& tight_aabb_pairs, const std::vector<b2Transform>& poses,
                               const Elements& elements, PairList& out) const {
  out.clear();
  for (const Pair& p : tight_aabb_pairs)
    if (touching_at(p.i, p.j, poses, elements)) out.push_back(p);
}

void PhysicsWorld::in_box2d_scope(const PairList& pairs, PairList& out, Box2dScope& why_not) const {
  scope_at(pairs, aabbs_, out, why_not);
}

void PhysicsWorld::scope_at(const PairList& pairs, const std::vector<b2AABB>& aabbs, PairList& out,
                            Box2dScope& why_not) const {
  out.clear();
  why_not = {};
  out.reserve(pairs.size());
  b2ContactFilter* filter = world_->GetContactManager().m_contactFilter;
  // Box2D's own filter (the class itself, not a subclass) passes every pair of fixtures with the
  // default filter data (category 1, mask 0xFFFF, no group): then it need not be asked pair by pair.
  if (filter != nullptr && typeid(*filter) == typeid(b2ContactFilter) && default_filters_) filter = nullptr;
  const bool joints = world_->GetJointCount() > 0;
  for (const Pair& p : pairs) {
    const auto i = static_cast<std::size_t>(p.i), j = static_cast<std::size_t>(p.j);
    // Bodies by index (the same body <=> the same index): no pointer chasing for the common cases.
    const auto body_a = static_cast<std::size_t>(sources_[i].body), body_b = static_cast<std::size_t>(sources_[j].body);
    if (body_a == body_b) {
      ++why_not.same_body;
      continue;
    }
    if (dynamic_[body_a] == 0 && dynamic_[body_b] == 0) {
      ++why_not.no_dynamic;
      continue;
    }
    b2Fixture* fa = fixtures_[i];
    b2Fixture* fb = fixtures_[j];
    bool joined = false;  // as b2Body::ShouldCollide (private in 2.4.1)
    if (joints)
      for (const b2JointEdge* je = bodies_[body_b]->GetJointList(); je != nullptr; je = je->next)
        if (je->other == bodies_[body_a] && !je->joint->GetCollideConnected()) joined = true;
    if (joined) {
      ++why_not.joint;
      continue;
    }
    if (filter != nullptr && !filter->ShouldCollide(fa, fb)) {
      ++why_not.fixture_filter;
      continue;
    }
    // A polygon's bounding circle reaches beyond its AABB, where Box2D never looks. Two circles'
    // bounding circles are the shapes: a real contact has overlapping AABBs, so it must be in F.
    const bool both_circles = circle_[i] != 0 && circle_[j] != 0;
    if (!both_circles && !b2TestOverlap(aabbs[i], aabbs[j])) {
      ++why_not.beyond_aabb;
      continue;
    }
    out.push_back(p);
  }
}

// ---- shapes --------------------------------------------------------------------------------

void PhysicsWorld::shapes(std::vector<BodyShape>& out) const { shapes_at(poses_, aabbs_.size(), out); }

void PhysicsWorld::shapes_at(const std::vector<b2Transform>& poses, std::size_t n, std::vector<BodyShape>& out) const {
  out.clear();
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const b2Fixture* f = fixtures_[i];
    const b2Body* body = f->GetBody();
    const b2Transform& xf = poses[static_cast<std::size_t>(sources_[i].body)];
    BodyShape s;
    s.element = static_cast<ElementId>(i);
    s.body = sources_[i].body;
    s.body_type = from_b2(body->GetType());
    s.angle = std::atan2(static_cast<double>(xf.q.s), static_cast<double>(xf.q.c));
    s.radius = f->GetShape()->m_radius;
    if (f->GetType() == b2Shape::e_circle) {
      s.form = ShapeForm::Circle;
      world_point(xf, static_cast<const b2CircleShape*>(f->GetShape())->m_p, s.centre.x, s.centre.y);
    } else {
      const auto* poly = static_cast<const b2PolygonShape*>(f->GetShape());
      s.form = ShapeForm::Polygon;
      world_point(xf, poly->m_centroid, s.centre.x, s.centre.y);
      s.vertex_count = poly->m_count;
      for (int32 k = 0; k < poly->m_count; ++k) world_point(xf, poly->m_vertices[k], s.vertices[k].x, s.vertices[k].y);
    }
    out.push_back(s);
  }
}

// ---- mouse drag ----------------------------------------------------------------------------

bool PhysicsWorld::begin_drag(double x, double y) {
  end_drag();
  const b2Vec2 p(static_cast<float>(x), static_cast<float>(y));
  struct Pick final : b2QueryCallback {
    b2Vec2 point;
    b2Body* hit = nullptr;
    bool ReportFixture(b2Fixture* f) override {
      if (f->GetBody()->GetType() != b2_dynamicBody || !f->TestPoint(point)) return true;
      hit = f->GetBody();
      return false;
    }
  } pick;
  pick.point = p;
  b2AABB box;
  box.lowerBound = p - b2Vec2(0.001f, 0.001f);
  box.upperBound = p + b2Vec2(0.001f, 0.001f);
  world_->QueryAABB(&pick, box);
  if (pick.hit == nullptr) return false;
  b2MouseJointDef def;
  def.bodyA = ground_;
  def.bodyB = pick.hit;
  def.target = p;
  const float g = std::max(10.0f, world_->GetGravity().Length());
  def.maxForce = 1000.0f * pick.hit->GetMass() * g;
  b2LinearStiffness(def.stiffness, def.damping, 5.0f, 0.7f, def.bodyA, def.bodyB);
  mouse_joint_ = static_cast<b2MouseJoint*>(world_->CreateJoint(&def));
  pick.hit->SetAwake(true);
  return true;
}

void PhysicsWorld::drag_to(double x, double y) {
  if (mouse_joint_ != nullptr) mouse_joint_->SetTarget(b2Vec2(static_cast<float>(x), static_cast<float>(y)));
}

void PhysicsWorld::end_drag() {
  if (mouse_joint_ == nullptr) return;
  world_->DestroyJoint(mouse_joint_);
  mouse_joint_ = nullptr;
}

}  // namespace nbscope

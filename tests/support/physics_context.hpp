// nbscope tests: the physics floor's fixture, as Jolt's PhysicsTestContext is its physics tests': a
// Box2D world built from a small scene (its JSON text, or a bundled scene), stepped N frames, with
// its elements, its Box2D frame and its fixtures at hand, so a test says only what it sets and what
// it expects. The world is the product's own (physics/world.hpp), built and stepped here alone.
//
// Beside it, what two frames that must be the same are compared by (FrameSets: elements, shapes,
// F, G, T and A-in-F's scope over every pair of meeting bounding circles, found by a double loop).
#pragma once
#include <gtest/gtest.h>
#include <box2d/box2d.h>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "io/scene_json.hpp"
#include "physics/box2d_frame.hpp"
#include "physics/world.hpp"

namespace nbscope::testphysics {

// A scene from its JSON text, as a file "test.json" would give it.
inline Scene scene_of(const std::string& json) { return parse_scene_json(json, "test.json"); }

// Every pair (i < j) of `e` whose bounding circles touch or overlap: all N(N-1)/2 pairs looked at.
inline PairList meeting_circles(const Elements& e) {
  PairList out;
  for (ElementId i = 0; i < e.size(); ++i)
    for (ElementId j = i + 1; j < e.size(); ++j) {
      const double dx = e.x[i] - e.x[j], dy = e.y[i] - e.y[j], reach = e.r[i] + e.r[j];
      if (dx * dx + dy * dy <= reach * reach) out.push_back({i, j});
    }
  return out;
}

// A body of one circle fixture of `radius` at `offset` in the body (a scene built in memory).
inline BodySpec circle_body(double radius, BodyType type = BodyType::Dynamic, Vec2 offset = {}) {
  BodySpec b;
  b.type = type;
  ShapeSpec s;
  s.radius = radius;
  s.offset = offset;
  b.fixtures.push_back(s);
  return b;
}

// True when both sets hold the same elements, to the bit.
inline bool same_elements(const Elements& a, const Elements& b) {
  return a.size() == b.size() && (a.x == b.x).all() && (a.y == b.y).all() && (a.r == b.r).all();
}

// Everything Box2D's side of one frame gives: what a kept or an overlapped frame must give again.
struct FrameSets {
  std::int64_t frame = 0;
  double time = 0;
  std::int64_t bodies = 0;
  Elements elements;
  std::vector<BodyShape> shapes;
  PairList contacts, tight_aabb, touching, scope;
  Box2dScope why_not;
};

inline FrameSets sets_of(const Box2dFrame& f) {
  FrameSets s;
  s.frame = f.frame();
  s.time = f.time();
  s.bodies = f.body_count();
  s.elements = f.elements();
  f.shapes(s.shapes);
  f.contact_pairs(s.contacts);
  f.ground_truth(s.tight_aabb, s.touching);
  f.in_box2d_scope(meeting_circles(s.elements), s.scope, s.why_not);
  return s;
}

// Every field of `a` equals `b`'s, to the bit.
inline void expect_same_sets(const FrameSets& a, const FrameSets& b) {
  SCOPED_TRACE("frame " + std::to_string(a.frame));
  EXPECT_EQ(a.frame, b.frame);
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.bodies, b.bodies);
  EXPECT_TRUE(same_elements(a.elements, b.elements));
  ASSERT_EQ(a.shapes.size(), b.shapes.size());
  for (std::size_t k = 0; k < a.shapes.size(); ++k) {
    const BodyShape& s = a.shapes[k];
    const BodyShape& t = b.shapes[k];
    EXPECT_TRUE(s.form == t.form && s.body_type == t.body_type && s.element == t.element && s.body == t.body &&
                s.centre.x == t.centre.x && s.centre.y == t.centre.y && s.radius == t.radius && s.angle == t.angle &&
                s.vertex_count == t.vertex_count)
        << "shape " << k;
    for (std::size_t v = 0; v < static_cast<std::size_t>(s.vertex_count); ++v)
      EXPECT_TRUE(s.vertices[v].x == t.vertices[v].x && s.vertices[v].y == t.vertices[v].y) << "shape " << k << " vertex " << v;
  }
  EXPECT_EQ(a.contacts, b.contacts);
  EXPECT_EQ(a.tight_aabb, b.tight_aabb);
  EXPECT_EQ(a.touching, b.touching);
  EXPECT_EQ(a.scope, b.scope);
  EXPECT_EQ(a.why_not.same_body, b.why_not.same_body);
  EXPECT_EQ(a.why_not.no_dynamic, b.why_not.no_dynamic);
  EXPECT_EQ(a.why_not.joint, b.why_not.joint);
  EXPECT_EQ(a.why_not.fixture_filter, b.why_not.fixture_filter);
  EXPECT_EQ(a.why_not.beyond_aabb, b.why_not.beyond_aabb);
}

class PhysicsTestContext {
 public:
  // The world of a scene given as JSON text ("test.json"), stepped `frames` frames.
  explicit PhysicsTestContext(const std::string& json, int frames = 0) : PhysicsTestContext(scene_of(json), frames) {}
  // The world of `scene`, stepped `frames` frames.
  explicit PhysicsTestContext(Scene scene, int frames = 0)
      : scene_(std::move(scene)), world_(std::make_unique<PhysicsWorld>(scene_)) {
    step(frames);
  }
  // A bundled scene (assets/scenes/NAME.json; needs NBSCOPE_SOURCE_DIR), stepped `frames` frames.
  static PhysicsTestContext bundled(const std::string& name, int frames = 0) {
    return PhysicsTestContext(read_scene_json(std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/" + name + ".json"), frames);
  }

  // Steps the world `frames` frames.
  void step(int frames = 1) {
    for (int k = 0; k < frames; ++k) world_->step();
  }

  [[nodiscard]] const Scene& scene() const { return scene_; }
  [[nodiscard]] PhysicsWorld& world() { return *world_; }
  [[nodiscard]] const Box2dFrame& frame() const { return *world_; }
  [[nodiscard]] const Elements& elements() const { return world_->elements(); }
  // A fresh world of the same scene, at frame 0 (a second, independent run).
  [[nodiscard]] std::unique_ptr<PhysicsWorld> fresh_world() const { return std::make_unique<PhysicsWorld>(scene_); }
  // Hands the world over (to a LiveWorld); the context has none after.
  [[nodiscard]] std::unique_ptr<PhysicsWorld> take_world() { return std::move(world_); }

  // What the history keeps of the current frame.
  [[nodiscard]] std::shared_ptr<WorldState> capture() const {
    auto state = std::make_shared<WorldState>();
    world_->capture(*state);
    return state;
  }
  // Box2D's fixture of every element (fixtures_of below).
  [[nodiscard]] std::vector<const b2Fixture*> fixtures() const;

 private:
  Scene scene_;
  std::unique_ptr<PhysicsWorld> world_;
};

// Box2D's fixture of every element of `w` (element k's fixture at k), read from the bodies themselves.
inline std::vector<const b2Fixture*> fixtures_of(const PhysicsWorld& w) {
  std::vector<const b2Fixture*> out(static_cast<std::size_t>(w.elements().size()));
  for (const b2Body* b = w.world().GetBodyList(); b != nullptr; b = b->GetNext())
    for (const b2Fixture* f = b->GetFixtureList(); f != nullptr; f = f->GetNext())
      out[static_cast<std::size_t>(const_cast<b2Fixture*>(f)->GetUserData().pointer)] = f;
  return out;
}

inline std::vector<const b2Fixture*> PhysicsTestContext::fixtures() const { return fixtures_of(*world_); }

// A fixture's tight AABB at its body's transform now.
inline b2AABB tight_aabb(const b2Fixture* f) {
  b2AABB b;
  f->GetShape()->ComputeAABB(&b, f->GetBody()->GetTransform(), 0);
  return b;
}

}  // namespace nbscope::testphysics

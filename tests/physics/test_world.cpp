// The world (physics/world.hpp): the elements of a Box2D world (bounding circles from shapes,
// worked by hand), Box2D's pair sets against brute force over all fixture pairs, the scope of
// A-in-F, mouse drag. Generators and the box2d detector have their own files.
#include <gtest/gtest.h>

#include "support/generators.hpp"
#include "support/physics_context.hpp"

#include <box2d/box2d.h>

#include <cmath>

#include "physics/world.hpp"

namespace nbscope {
namespace {

constexpr double kSkin = 2 * 0.005;  // b2_polygonRadius, written out as Box2D defines it

using testdata::brute_pairs;
using testphysics::PhysicsTestContext;
using testphysics::scene_of;

// ---- elements ------------------------------------------------------------------------------

// Each fixture's element is its bounding circle (circles exact, polygons with skin and margin), worked by hand.
TEST(PhysicsWorld, ElementsAreTheFixturesBoundingCircles) {
  const Scene s = scene_of(R"({"gravity": [0, 0], "bodies": [
      {"shape": "circle", "radius": 0.5, "position": [1, 2]},
      {"type": "static", "shape": "box", "half_extents": [1, 0.5], "position": [5, 5], "angle": 0.3},
      {"shape": "polygon", "vertices": [[0, 0], [3, 0], [0, 3]], "position": [10, 0]},
      {"position": [-4, 0], "angle": 1.5707963267948966, "fixtures": [
          {"shape": "circle", "radius": 0.25, "offset": [2, 0]},
          {"shape": "box", "half_extents": [0.5, 0.5], "offset": [0, 1]}]}]})");
  PhysicsWorld w(s);
  const Elements& e = w.elements();
  ASSERT_EQ(e.size(), 5);
  const double margin = kSkin + kPolygonCircleMargin;
  EXPECT_NEAR(e.x[0], 1, 1e-6);
  EXPECT_NEAR(e.y[0], 2, 1e-6);
  EXPECT_DOUBLE_EQ(e.r[0], 0.5);
  EXPECT_NEAR(e.x[1], 5, 1e-6);
  EXPECT_NEAR(e.y[1], 5, 1e-6);
  EXPECT_NEAR(e.r[1], std::hypot(1.0, 0.5) + margin, 1e-6);
  // Triangle: centroid (1, 1); farthest vertex (3, 0) or (0, 3) at sqrt(5).
  EXPECT_NEAR(e.x[2], 11, 1e-6);
  EXPECT_NEAR(e.y[2], 1, 1e-6);
  EXPECT_NEAR(e.r[2], std::sqrt(5.0) + margin, 1e-6);
  // The compound body is turned a quarter: offset (2, 0) lands at (0, 2), (0, 1) at (-1, 0).
  EXPECT_NEAR(e.x[3], -4, 1e-5);
  EXPECT_NEAR(e.y[3], 2, 1e-5);
  EXPECT_DOUBLE_EQ(e.r[3], 0.25);
  EXPECT_NEAR(e.x[4], -5, 1e-5);
  EXPECT_NEAR(e.y[4], 0, 1e-5);
  const std::vector<ElementSource>& src = w.sources();
  EXPECT_EQ(src[3].body, 3);
  EXPECT_EQ(src[3].fixture, 0);
  EXPECT_EQ(src[4].body, 3);
  EXPECT_EQ(src[4].fixture, 1);
  std::vector<BodyShape> shapes;
  w.shapes(shapes);
  ASSERT_EQ(shapes.size(), 5u);
  EXPECT_EQ(shapes[1].form, ShapeForm::Polygon);
  EXPECT_EQ(shapes[1].body_type, BodyType::Static);
  EXPECT_EQ(shapes[1].vertex_count, 4);
  EXPECT_EQ(shapes[3].form, ShapeForm::Circle);
  EXPECT_NEAR(shapes[3].radius, 0.25, 1e-7);
  // Every polygon vertex lies inside its element (bounding circle).
  for (const BodyShape& sh : shapes)
    for (int k = 0; k < sh.vertex_count; ++k)
      EXPECT_LE(std::hypot(sh.vertices[static_cast<std::size_t>(k)].x - e.x[sh.element], sh.vertices[static_cast<std::size_t>(k)].y - e.y[sh.element]) + kSkin,
                e.r[sh.element]);
}

// An emitter's bodies join the elements as they are poured, after the scene's own.
TEST(PhysicsWorld, EmittedBodiesAppearAsNewElements) {
  const Scene s = scene_of(R"({"bodies": [{"type": "static", "shape": "box", "half_extents": [5, 0.5]}],
      "generators": [{"kind": "emitter", "count": 3, "position": [0, 5], "rate": 30}]})");
  PhysicsWorld w(s);
  EXPECT_EQ(w.elements().size(), 1);
  w.step();
  EXPECT_EQ(w.elements().size(), 2);
  for (int k = 0; k < 10; ++k) w.step();
  EXPECT_EQ(w.elements().size(), 4);
  EXPECT_EQ(w.body_count(), 4);
  EXPECT_EQ(w.sources()[3].body, 3);
}

// ---- Box2D's sets against brute force ------------------------------------------------------

// A jumble of overlapping circles, boxes and triangles (dynamic, static and a compound body).
const char* kJumble = R"({"gravity": [0, -2], "bodies": [
    {"position": [0, 3], "fixtures": [{"shape": "circle", "radius": 0.4, "offset": [-0.3, 0]},
                                      {"shape": "circle", "radius": 0.4, "offset": [0.3, 0]}]}],
  "generators": [
    {"kind": "random_box", "count": 150, "seed": 3, "min": [-6, 0], "max": [6, 8], "radius": [0.2, 0.6], "body": {"shape": "circle"}},
    {"kind": "random_box", "count": 60, "seed": 4, "min": [-6, 0], "max": [6, 8], "random_angle": true,
     "body": {"shape": "box", "half_extents": [0.4, 0.2]}},
    {"kind": "random_box", "count": 60, "seed": 5, "min": [-6, 0], "max": [6, 8], "random_angle": true,
     "body": {"shape": "polygon", "vertices": [[-0.3, -0.3], [0.4, -0.2], [0, 0.5]]}},
    {"kind": "random_box", "count": 30, "seed": 6, "min": [-6, 0], "max": [6, 8],
     "body": {"type": "static", "shape": "box", "half_extents": [0.3, 0.3]}}]})";

// G and T equal Box2D's AABB and shape tests run on every pair of fixtures.
TEST(PhysicsWorld, GroundTruthMatchesAllPairsByBruteForce) {
  PhysicsTestContext c(kJumble, 5);
  PhysicsWorld& w = c.world();
  PairList g, t;
  w.ground_truth(g, t);
  // Every fixture pair, tested directly with Box2D's own shape and AABB tests.
  const std::vector<const b2Fixture*> fixtures = c.fixtures();
  PairList g_expected, t_expected;
  for (std::size_t i = 0; i < fixtures.size(); ++i) {
    for (std::size_t j = i + 1; j < fixtures.size(); ++j) {
      const b2Fixture* a = fixtures[i];
      const b2Fixture* b = fixtures[j];
      if (!b2TestOverlap(testphysics::tight_aabb(a), testphysics::tight_aabb(b))) continue;
      const Pair p{static_cast<ElementId>(i), static_cast<ElementId>(j)};
      g_expected.push_back(p);
      if (b2TestOverlap(a->GetShape(), 0, b->GetShape(), 0, a->GetBody()->GetTransform(), b->GetBody()->GetTransform()))
        t_expected.push_back(p);
    }
  }
  EXPECT_GT(t_expected.size(), 50u);
  EXPECT_EQ(g, g_expected);
  EXPECT_EQ(t, t_expected);
  // Touching shapes always have meeting bounding circles: T ⊆ brute force on the elements.
  EXPECT_TRUE(pairs_missing_from(t, brute_pairs(w.elements())).empty());
}

// F holds every pair of G in A-in-F's scope, frame after frame.
TEST(PhysicsWorld, ContactListHoldsEveryDynamicTightAabbPair) {
  PhysicsWorld w(scene_of(kJumble));
  PairList f;
  w.contact_pairs(f);
  EXPECT_TRUE(f.empty());  // Box2D makes contacts inside Step
  for (int step = 0; step < 10; ++step) {
    w.step();
    w.contact_pairs(f);
    PairList g, t, scope;
    w.ground_truth(g, t);
    Box2dScope why;
    w.in_box2d_scope(g, scope, why);
    EXPECT_TRUE(pairs_missing_from(scope, f).empty()) << "step " << step;
    EXPECT_EQ(why.beyond_aabb, 0u);  // G's pairs all overlap by construction
    EXPECT_EQ(why.same_body, 1u);    // the two circles of the compound body
    EXPECT_GT(why.no_dynamic, 0u);   // static boxes overlapping each other
  }
}

// Same-body, static-only and beyond-AABB pairs leave the scope, each counted, on a hand-laid scene.
TEST(PhysicsWorld, ScopeLeavesOutWhatBox2dFilters) {
  // Two fixtures of one body, two statics, a dynamic pair and a polygon whose bounding circle
  // reaches a circle its AABB does not.
  PhysicsWorld w(scene_of(R"({"gravity": [0, 0], "bodies": [
      {"position": [0, 0], "fixtures": [{"shape": "circle", "radius": 0.5, "offset": [-0.4, 0]},
                                        {"shape": "circle", "radius": 0.5, "offset": [0.4, 0]}]},
      {"type": "static", "shape": "circle", "radius": 0.5, "position": [10, 0]},
      {"type": "static", "shape": "circle", "radius": 0.5, "position": [10.9, 0]},
      {"shape": "circle", "radius": 0.5, "position": [20, 0]},
      {"shape": "circle", "radius": 0.5, "position": [20.9, 0]},
      {"shape": "box", "half_extents": [1, 1], "position": [30, 0]},
      {"shape": "circle", "radius": 0.3, "position": [31.4, 0]}]})"));
  const PairList all = brute_pairs(w.elements());
  EXPECT_EQ(all, (PairList{{0, 1}, {2, 3}, {4, 5}, {6, 7}}));
  PairList scope;
  Box2dScope why;
  w.in_box2d_scope(all, scope, why);
  EXPECT_EQ(scope, (PairList{{4, 5}}));
  EXPECT_EQ(why.same_body, 1u);
  EXPECT_EQ(why.no_dynamic, 1u);
  EXPECT_EQ(why.beyond_aabb, 1u);
  w.step();
  PairList f;
  w.contact_pairs(f);
  EXPECT_EQ(f, (PairList{{4, 5}, {6, 7}}));  // box and circle: their fat AABBs (+0.1 m) do overlap
}

// ---- mouse drag ----------------------------------------------------------------------------

// Only a dynamic body under the pointer is picked, and the mouse joint pulls it to the target.
TEST(PhysicsWorld, DragPullsTheDynamicBodyUnderThePointer) {
  PhysicsWorld w(scene_of(R"({"gravity": [0, 0], "bodies": [
      {"shape": "circle", "radius": 0.5, "position": [0, 0]},
      {"type": "static", "shape": "circle", "radius": 0.5, "position": [5, 0]}]})"));
  EXPECT_FALSE(w.begin_drag(5, 0));  // static: not draggable
  EXPECT_FALSE(w.begin_drag(2, 2));  // nothing there
  EXPECT_TRUE(w.begin_drag(0.1, 0.1));
  EXPECT_TRUE(w.dragging());
  w.drag_to(0, 3);
  for (int k = 0; k < 120; ++k) w.step();
  EXPECT_GT(w.elements().y[0], 2.0);
  w.end_drag();
  EXPECT_FALSE(w.dragging());
  w.end_drag();  // harmless
}

}  // namespace
}  // namespace nbscope

// Physics: generators, the elements of a Box2D world (bounding circles from shapes), Box2D's pair
// sets against brute force over all fixture pairs, the box2d detector across frames, mouse drag.
#include <gtest/gtest.h>

#include "support/generators.hpp"

#include <box2d/box2d.h>

#include <cmath>
#include <set>

#include "core/brute.hpp"
#include "core/error.hpp"
#include "io/scene_json.hpp"
#include "physics/box2d_detector.hpp"
#include "physics/generators.hpp"
#include "physics/world.hpp"

namespace nbscope {
namespace {

constexpr double kSkin = 2 * 0.005;  // b2_polygonRadius, written out as Box2D defines it

Scene scene_of(const std::string& text) { return parse_scene_json(text, "test.json"); }

using testdata::brute_pairs;

// ---- generators ----------------------------------------------------------------------------

TEST(Generators, GridIsRowMajorFromTheOrigin) {
  const Scene s = scene_of(R"({"generators": [{"kind": "grid", "columns": 3, "rows": 2, "origin": [1, 2], "spacing": [0.5, 4]}]})");
  const std::vector<BodySpec> b = initial_bodies(s);
  ASSERT_EQ(b.size(), 6u);
  for (int row = 0; row < 2; ++row) {
    for (int col = 0; col < 3; ++col) {
      EXPECT_DOUBLE_EQ(b[static_cast<std::size_t>(row * 3 + col)].position.x, 1 + 0.5 * col);
      EXPECT_DOUBLE_EQ(b[static_cast<std::size_t>(row * 3 + col)].position.y, 2 + 4 * row);
    }
  }
  EXPECT_EQ(b[0].fixtures[0].radius, 0.5);  // the default template
}

TEST(Generators, RandomBoxStaysInsideAndIsReproducible) {
  const char* text = R"({"generators": [{"kind": "random_box", "count": 500, "seed": SEED, "min": [-3, 10], "max": [4, 12],
                        "radius": [0.1, 0.3], "speed": [2, 3], "body": {"shape": "circle"}}]})";
  auto with_seed = [&](int seed) {
    std::string t = text;
    t.replace(t.find("SEED"), 4, std::to_string(seed));
    return initial_bodies(scene_of(t));
  };
  const auto a = with_seed(1), b = with_seed(1), c = with_seed(2);
  ASSERT_EQ(a.size(), 500u);
  bool differs = false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_GE(a[k].position.x, -3);
    EXPECT_LT(a[k].position.x, 4);
    EXPECT_GE(a[k].position.y, 10);
    EXPECT_LT(a[k].position.y, 12);
    EXPECT_GE(a[k].fixtures[0].radius, 0.1);
    EXPECT_LT(a[k].fixtures[0].radius, 0.3);
    const double speed = std::hypot(a[k].velocity.x, a[k].velocity.y);
    EXPECT_GE(speed, 2 - 1e-12);
    EXPECT_LE(speed, 3 + 1e-12);
    EXPECT_EQ(a[k].position.x, b[k].position.x);
    EXPECT_EQ(a[k].fixtures[0].radius, b[k].fixtures[0].radius);
    differs = differs || a[k].position.x != c[k].position.x;
  }
  EXPECT_TRUE(differs);
}

TEST(Generators, PileRowsAreHexagonal) {
  const Scene s = scene_of(R"({"generators": [{"kind": "pile", "count": 7, "columns": 3, "position": [0, 1],
                            "spacing": 2, "jitter": 0, "body": {"shape": "circle", "radius": 0.9}}]})");
  const std::vector<BodySpec> b = initial_bodies(s);
  ASSERT_EQ(b.size(), 7u);
  const double xs[] = {-2, 0, 2, -1, 1, 3, -2};
  for (std::size_t k = 0; k < 7; ++k) {
    EXPECT_NEAR(b[k].position.x, xs[k], 1e-12) << k;
    EXPECT_NEAR(b[k].position.y, 1 + static_cast<double>(k / 3) * std::sqrt(3.0), 1e-12) << k;
  }
}

TEST(Generators, APileBeyondTheWorldLimitIsRefusedNamingTheGenerator) {
  // 100 bodies 10 km apart in one row: 1000 km wide, where float positions mean nothing.
  const Scene s = scene_of(R"({"generators": [
      {"kind": "pile", "count": 100, "columns": 100, "position": [0, 1], "spacing": 10000}]})");
  try {
    initial_bodies(s);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "test.json:2: generators[0]: the pile would reach beyond +-100000 m (1 rows of 100, 10000 m apart)");
  }
}

TEST(Generators, EmitterPoursAtItsRate) {
  const Scene s = scene_of(R"({"generators": [{"kind": "emitter", "count": 10, "position": [0, 5], "rate": 4, "start": 1}]})");
  EXPECT_TRUE(initial_bodies(s).empty());
  Emitter e(s.generators[0]);
  std::vector<BodySpec> out;
  e.emit_until(0.9, out);
  EXPECT_EQ(out.size(), 0u);
  e.emit_until(1.0, out);
  EXPECT_EQ(out.size(), 1u);  // the first at `start`
  e.emit_until(2.0, out);
  EXPECT_EQ(out.size(), 5u);  // 1 + 4 per second
  e.emit_until(100, out);
  EXPECT_EQ(out.size(), 10u);  // never more than count
  for (const BodySpec& b : out) EXPECT_EQ(b.position.y, 5);
}

// ---- elements ------------------------------------------------------------------------------

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

TEST(PhysicsWorld, GroundTruthMatchesAllPairsByBruteForce) {
  PhysicsWorld w(scene_of(kJumble));
  for (int step = 0; step < 5; ++step) w.step();
  PairList g, t;
  w.ground_truth(g, t);
  // Every fixture pair, tested directly with Box2D's own shape and AABB tests.
  const b2World& world = w.world();
  std::vector<const b2Fixture*> fixtures(static_cast<std::size_t>(w.elements().size()));
  for (const b2Body* b = world.GetBodyList(); b; b = b->GetNext())
    for (const b2Fixture* f = b->GetFixtureList(); f; f = f->GetNext())
      fixtures[static_cast<std::size_t>(const_cast<b2Fixture*>(f)->GetUserData().pointer)] = f;
  PairList g_expected, t_expected;
  for (std::size_t i = 0; i < fixtures.size(); ++i) {
    for (std::size_t j = i + 1; j < fixtures.size(); ++j) {
      const b2Fixture* a = fixtures[i];
      const b2Fixture* b = fixtures[j];
      b2AABB ba, bb;
      a->GetShape()->ComputeAABB(&ba, a->GetBody()->GetTransform(), 0);
      b->GetShape()->ComputeAABB(&bb, b->GetBody()->GetTransform(), 0);
      if (!b2TestOverlap(ba, bb)) continue;
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

// ---- the box2d detector --------------------------------------------------------------------

TEST(Box2dDetector, MatchesBruteForceAsElementsMoveAppearAndVanish) {
  Box2dDetector d;
  SceneRng rng(7);
  Elements e;
  e.dim = 2;
  for (int frame = 0; frame < 30; ++frame) {
    const std::int64_t n = 50 + (frame * 37) % 400;  // grows and shrinks
    const std::int64_t old = e.size();
    e.x.conservativeResize(n);
    e.y.conservativeResize(n);
    e.r.conservativeResize(n);
    for (std::int64_t k = 0; k < n; ++k) {
      if (k >= old) {
        e.x[k] = rng.uniform(0, 20);
        e.y[k] = rng.uniform(0, 20);
        e.r[k] = rng.uniform(0.1, 0.6);
      } else {
        e.x[k] += rng.uniform(-0.5, 0.5);  // some stay inside their fat AABBs, some leave
        e.y[k] += rng.uniform(-0.05, 0.05);
      }
    }
    PairList p;
    d.detect(e, DetectOptions{}, p);
    sort_pairs(p);
    ASSERT_EQ(p, brute_pairs(e)) << "frame " << frame;
  }
  EXPECT_GT(d.own_bytes(), 0u);
}

TEST(Box2dDetector, RefusesThreeDimensionsAndFarAwayElements) {
  Box2dDetector d;
  PairList p;
  Elements e3;
  e3.dim = 3;
  EXPECT_THROW(d.detect(e3, DetectOptions{}, p), Error);
  Elements far = make_elements_2d(Eigen::ArrayXd::Constant(1, 1e300), Eigen::ArrayXd::Zero(1), Eigen::ArrayXd::Ones(1));
  EXPECT_THROW(d.detect(far, DetectOptions{}, p), Error);
}

TEST(Box2dDetector, FindsThePairsOfElementsADenormalApart) {
  // The Morton sort's scale is 65535 / spread: infinite here, and the fuzzer's UBSan once caught its cast.
  Box2dDetector d;
  Eigen::ArrayXd x(3), y(3), r(3);
  x << 0.0, 5e-324, 1e-323;
  y << 0.0, 0.0, 5e-324;
  r << 1.0, 1.0, 1.0;
  const Elements e = make_elements_2d(x, y, r);
  PairList p;
  d.detect(e, DetectOptions{}, p);
  sort_pairs(p);
  EXPECT_EQ(p, brute_pairs(e));
  EXPECT_EQ(p.size(), 3u);
}

TEST(Box2dDetector, IsRegisteredByPhysics) {
  register_physics_detectors();
  register_physics_detectors();  // twice is harmless
  int found = 0;
  for (const DetectorInfo& info : detector_infos()) found += info.name == "box2d";
  EXPECT_EQ(found, 1);
  EXPECT_EQ(make_detector("box2d")->name(), "box2d");
}

// ---- mouse drag ----------------------------------------------------------------------------

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

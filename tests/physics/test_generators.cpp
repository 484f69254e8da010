// Generators (physics/generators.hpp): the random numbers they draw from against splitmix64's
// published values, each generator's bodies against positions worked by hand, the emitter's pouring
// over time, and a body's extent.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "physics/generators.hpp"
#include "support/physics_context.hpp"

namespace nbscope {
namespace {

using testphysics::scene_of;

// ---- the random numbers ----------------------------------------------------------------------

// SceneRng is splitmix64: its first outputs are the reference implementation's (worked in Python).
TEST(SceneRng, GivesSplitmix64sReferenceSequence) {
  SceneRng zero(0), answer(42);
  EXPECT_EQ(zero.next(), 0xe220a8397b1dcdafULL);
  EXPECT_EQ(zero.next(), 0x6e789e6aa1b965f4ULL);
  EXPECT_EQ(zero.next(), 0x06c45d188009454fULL);
  EXPECT_EQ(answer.next(), 0xbdd732262feb6e95ULL);
  EXPECT_EQ(answer.next(), 0x28efe333b266f103ULL);
}

// uniform(lo, hi) is the next 53 bits scaled into [lo, hi): the same draw as next() made by hand.
TEST(SceneRng, UniformIsTheTop53BitsScaledIntoTheRange) {
  SceneRng a(7), b(7);
  for (int k = 0; k < 1000; ++k) {
    const double u = a.uniform(-2, 3);
    const double by_hand = -2 + 5 * std::ldexp(static_cast<double>(b.next() >> 11), -53);
    ASSERT_EQ(u, by_hand) << k;
    ASSERT_GE(u, -2);
    ASSERT_LT(u, 3);
  }
}

// ---- the generators ---------------------------------------------------------------------------

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

// ---- a body's extent --------------------------------------------------------------------------

// The farthest point of a body's shapes from its origin, each kind worked by hand (polygons and
// boxes with Box2D's 0.01 m skin).
TEST(Generators, BodyExtentIsTheFarthestPointOfItsShapes) {
  BodySpec b;
  ShapeSpec circle;
  circle.radius = 0.5;
  circle.offset = {3, 4};  // 5 from the origin
  b.fixtures.push_back(circle);
  EXPECT_DOUBLE_EQ(body_extent(b), 5.5);
  ShapeSpec box;
  box.kind = ShapeKind::Box;
  box.half_extents = {6, 8};  // corners 10 from its centre
  box.offset = {0, 0};
  b.fixtures.push_back(box);
  EXPECT_DOUBLE_EQ(body_extent(b), 10.01);
  ShapeSpec triangle;
  triangle.kind = ShapeKind::Polygon;
  triangle.vertices = {{0, 0}, {12, 0}, {0, 5}};  // (12, 0): 12 away
  b.fixtures.push_back(triangle);
  EXPECT_DOUBLE_EQ(body_extent(b), 12.01);
}

}  // namespace
}  // namespace nbscope

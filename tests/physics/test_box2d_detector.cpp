// The box2d detector (physics/box2d_detector.hpp): Box2D's dynamic tree as a contact detector, held
// to a loop over all pairs (support/generators.hpp's brute_pairs) across frames, on odd inputs, and
// registered with core's registry.
#include <gtest/gtest.h>

#include "support/generators.hpp"

#include "core/error.hpp"
#include "physics/box2d_detector.hpp"
#include "physics/generators.hpp"

namespace nbscope {
namespace {

using testdata::brute_pairs;

// Across frames whose elements move (within and beyond their fat AABBs), appear and vanish, the
// proxies kept between detections give every pair a loop over all pairs gives.
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

// 3D elements and elements beyond float's range are refused with an Error, not detected wrongly.
TEST(Box2dDetector, RefusesThreeDimensionsAndFarAwayElements) {
  Box2dDetector d;
  PairList p;
  Elements e3;
  e3.dim = 3;
  EXPECT_THROW(d.detect(e3, DetectOptions{}, p), Error);
  Elements far = make_elements_2d(Eigen::ArrayXd::Constant(1, 1e300), Eigen::ArrayXd::Zero(1), Eigen::ArrayXd::Ones(1));
  EXPECT_THROW(d.detect(far, DetectOptions{}, p), Error);
}

// Elements a denormal apart (an infinite Morton scale) still give brute force's pairs.
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

// register_physics_detectors() adds "box2d" to core's registry once, however often it is called.
TEST(Box2dDetector, IsRegisteredByPhysics) {
  register_physics_detectors();
  register_physics_detectors();  // twice is harmless
  int found = 0;
  for (const DetectorInfo& info : detector_infos()) found += info.name == "box2d";
  EXPECT_EQ(found, 1);
  EXPECT_EQ(make_detector("box2d")->name(), "box2d");
}

}  // namespace
}  // namespace nbscope

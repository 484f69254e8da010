// Periodic frames in the overlays, through a recording DrawSink: a pair touching across x's periodic
// edge is two half-links ending at the box's edge (never one line across the box), the elements
// near an edge get faded ghosts at their images across it (none far from the edges, none in an open
// space), the periodic edges are drawn, picking ignores ghosts, and the ids overlay names a dump's
// atoms by their ids.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "render/camera_framing.hpp"
#include "render/overlays.hpp"
#include "support/draw_recorder.hpp"

namespace nbscope::render {
namespace {

using testdraw::Recorder;  // support/draw_recorder.hpp

// Elements 0 and 1 touch across x's edge of the box [0, 10) (0.4 and 9.7: 0.7 apart through the
// edge, radii 0.5); element 2 sits in the middle, far from every edge. y is open.
Elements across_the_edge(bool periodic) {
  Elements e;
  e.push_back(0.4, 5, 0, 0.5);
  e.push_back(9.7, 5, 0, 0.5);
  e.push_back(5, 5, 0, 0.5);
  e.box.periodic[0] = periodic;
  e.box.lo[0] = 0;
  e.box.hi[0] = 10;
  return e;
}

struct Rig {
  Elements e;
  PairList pairs{{0, 1}};
  Camera camera;
  explicit Rig(bool periodic) : e(across_the_edge(periodic)) {
    camera.set_viewport(700, 400);
    camera.fit({{-2, 2}, {12, 8}});
  }
  [[nodiscard]] OverlayScene scene() const {
    OverlayScene s;
    s.elements = &e;
    s.pairs = &pairs;
    return s;
  }
  [[nodiscard]] Recorder draw(const OverlayScene& s, OverlayFlags f = {}) const {
    Recorder rec;
    draw_scene(s, f, camera, rec);
    return rec;
  }
};

TEST(PeriodicOverlays, APairTouchingAcrossTheEdgeIsTwoHalfLinksEndingAtTheBoxEdge) {
  const Rig rig(true);
  const Recorder rec = rig.draw(rig.scene());
  const auto links = rec.lines_of(palette::kPair);
  ASSERT_EQ(links.size(), 2u);
  for (const auto& l : links) EXPECT_LT(std::abs(l.to.x() - l.from.x()), 1.0f) << "no line across the box";
  // From each centre towards the other's nearest image, ending at the edge it crosses.
  const auto from_left = std::find_if(links.begin(), links.end(), [](const auto& l) { return l.from.x() < 1; });
  const auto from_right = std::find_if(links.begin(), links.end(), [](const auto& l) { return l.from.x() > 9; });
  ASSERT_NE(from_left, links.end());
  ASSERT_NE(from_right, links.end());
  EXPECT_FLOAT_EQ(from_left->from.x(), 0.4f);
  EXPECT_FLOAT_EQ(from_left->to.x(), 0.0f);
  EXPECT_FLOAT_EQ(from_right->from.x(), 9.7f);
  EXPECT_FLOAT_EQ(from_right->to.x(), 10.0f);
  for (const auto& l : links) EXPECT_FLOAT_EQ(l.to.y(), 5.0f);
}

TEST(PeriodicOverlays, TheSamePairInAnOpenSpaceIsOneLineAndNothingElseIsDrawn) {
  const Rig rig(false);
  const Recorder rec = rig.draw(rig.scene());
  const auto links = rec.lines_of(palette::kPair);
  ASSERT_EQ(links.size(), 1u);
  EXPECT_FLOAT_EQ(links[0].from.x(), 0.4f);
  EXPECT_FLOAT_EQ(links[0].to.x(), 9.7f);
  EXPECT_EQ(rec.lines.size(), 1u) << "no box edges";
  EXPECT_TRUE(rec.circles.empty()) << "no ghosts";
}

TEST(PeriodicOverlays, ElementsNearAnEdgeGetGhostsAtTheirImagesAndTheEdgesAreDrawn) {
  const Rig rig(true);
  const Recorder rec = rig.draw(rig.scene());
  std::vector<float> ghosts;
  for (const auto& c : rec.circles) {
    EXPECT_EQ(c.layer, Layer::Bodies);
    EXPECT_LT(c.fill.a, 255) << "faded";
    EXPECT_FLOAT_EQ(c.centre.y(), 5.0f);
    ghosts.push_back(c.centre.x());
  }
  std::sort(ghosts.begin(), ghosts.end());
  // Element 0 across the right edge, element 1 across the left; element 2 (x = 5) none.
  ASSERT_EQ(ghosts.size(), 2u);
  EXPECT_FLOAT_EQ(ghosts[0], -0.3f);
  EXPECT_FLOAT_EQ(ghosts[1], 10.4f);
  // Every other line lies on x = 0 or x = 10, and both edges are there.
  bool low = false, high = false;
  for (const auto& l : rec.lines) {
    if (l.colour == palette::kPair) continue;
    EXPECT_EQ(l.from.x(), l.to.x());
    EXPECT_TRUE(l.from.x() == 0.0f || l.from.x() == 10.0f) << l.from.x();
    (l.from.x() == 0.0f ? low : high) = true;
  }
  EXPECT_TRUE(low && high);
  // No ghost with the bodies and the bounding circles off.
  OverlayFlags bare;
  bare.bodies = false;
  EXPECT_TRUE(rig.draw(rig.scene(), bare).circles.empty());
}

TEST(PeriodicOverlays, PickingIgnoresGhosts) {
  const Elements e = across_the_edge(true);
  EXPECT_EQ(element_at(e, {10.4, 5}), -1) << "element 0's ghost";
  EXPECT_EQ(element_at(e, {0.4, 5}), 0);
}

TEST(PeriodicOverlays, AViolationAcrossTheEdgeIsMarkedOnBothSides) {
  const Rig rig(true);
  CheckDraw checks;
  checks.violations = {{0, 1}};
  OverlayScene s = rig.scene();
  s.checks = &checks;
  const Recorder rec = rig.draw(s);
  const auto red = rec.lines_of(palette::kViolation);
  ASSERT_EQ(red.size(), 2u);
  for (const auto& l : red) EXPECT_LT(std::abs(l.to.x() - l.from.x()), 1.0f);
  int rings = 0;
  for (const auto& c : rec.circles)
    if (c.layer == Layer::Top) {
      ++rings;
      EXPECT_TRUE(std::abs(c.centre.x() - 0.05f) < 1e-5f || std::abs(c.centre.x() - 10.05f) < 1e-5f) << c.centre.x();
    }
  EXPECT_EQ(rings, 2);
}

// A violation gone to across the edge is drawn as the check measures it: each element joined to the
// other's nearest image (0.7 long), both ringed there, from both sides; never a line across the box
// nor one stopping at the edge (the half-links left the image unmarked).
TEST(PeriodicOverlays, AFocusPairAcrossTheEdgeJoinsEachElementToTheOthersNearestImage) {
  const Rig rig(true);
  OverlayScene s = rig.scene();
  s.focus_pair = Pair{0, 1};
  const Recorder rec = rig.draw(s);
  const auto marked = rec.lines_of(palette::kViolation);
  ASSERT_EQ(marked.size(), 2u);
  std::vector<std::pair<float, float>> ends;
  for (const auto& l : marked) ends.emplace_back(std::min(l.from.x(), l.to.x()), std::max(l.from.x(), l.to.x()));
  std::sort(ends.begin(), ends.end());
  EXPECT_NEAR(ends[0].first, -0.3f, 1e-5f) << "element 1's image left of element 0";
  EXPECT_NEAR(ends[0].second, 0.4f, 1e-5f);
  EXPECT_NEAR(ends[1].first, 9.7f, 1e-5f);
  EXPECT_NEAR(ends[1].second, 10.4f, 1e-5f) << "element 0's image right of element 1";
  std::vector<float> rings;
  for (const auto& c : rec.circles)
    if (c.layer == Layer::Top && c.outline == palette::kSelection) rings.push_back(c.centre.x());
  std::sort(rings.begin(), rings.end());
  ASSERT_EQ(rings.size(), 4u);
  EXPECT_NEAR(rings[0], -0.3f, 1e-5f);
  EXPECT_NEAR(rings[1], 0.4f, 1e-5f);
  EXPECT_NEAR(rings[2], 9.7f, 1e-5f);
  EXPECT_NEAR(rings[3], 10.4f, 1e-5f);
}

// Home of a frame without elements (every frame of a run still empty): its periodic box, not a
// metre square at the origin.
TEST(PeriodicOverlays, AFrameWithoutElementsFitsItsPeriodicBox) {
  Elements e;
  e.box.periodic[0] = e.box.periodic[1] = true;
  e.box.lo[0] = -5;
  e.box.hi[0] = 95;
  e.box.lo[1] = 10;
  e.box.hi[1] = 40;
  const WorldRect box = elements_box(e, Grid{});
  EXPECT_EQ(box.min, Eigen::Vector2d(-5, 10));
  EXPECT_EQ(box.max, Eigen::Vector2d(95, 40));
}

TEST(PeriodicOverlays, ATrailWrappedAcrossTheBoxDrawsNoSegmentAcrossIt) {
  const Rig rig(true);
  const std::vector<std::vector<Vec2>> trails{{Vec2(9.5f, 5), Vec2(9.9f, 5), Vec2(0.3f, 5), Vec2(0.6f, 5)}};
  OverlayScene s = rig.scene();
  s.trails = trails;
  const Recorder rec = rig.draw(s);
  int segments = 0;
  for (const auto& l : rec.lines)
    if (l.colour.r == palette::kTrail.r && l.colour.g == palette::kTrail.g && l.colour.b == palette::kTrail.b) {
      ++segments;
      EXPECT_LT(std::abs(l.to.x() - l.from.x()), 1.0f);
    }
  EXPECT_EQ(segments, 2);
}

TEST(PeriodicOverlays, TheIdsOverlayNamesADumpsAtomsByTheirIds) {
  const Rig rig(false);
  const std::vector<std::int64_t> ids{2753, 12, 99};
  OverlayScene s = rig.scene();
  s.ids = &ids;
  OverlayFlags f;
  f.ids = true;
  std::vector<std::string> texts = rig.draw(s, f).text_strings();
  std::sort(texts.begin(), texts.end());
  EXPECT_EQ(texts, (std::vector<std::string>{"12", "2753", "99"}));
  texts = rig.draw(rig.scene(), f).text_strings();  // without ids: the rows
  std::sort(texts.begin(), texts.end());
  EXPECT_EQ(texts, (std::vector<std::string>{"0", "1", "2"}));
}

}  // namespace
}  // namespace nbscope::render

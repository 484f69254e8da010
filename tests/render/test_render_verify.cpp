// A verify run drawn without GL: a recording DrawSink sees the user's lists as arrow chains with
// their heads named as the book names them, each problem's wrong link as a red arrow between the
// right two elements (from the list's head when the link leaves it), a red ring on every element at
// fault, a cut list's end in red, the selected problem highlighted and its text in the legend —
// numbered from 1 when the arrays file counts from 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/overlays.hpp"
#include "render/overlay_verify.hpp"
#include "support/verify_fixture.hpp"
#include "support/draw_recorder.hpp"

namespace nbscope::render {
namespace {

using testdata::PlantedBug;

using testdraw::Recorder;  // support/draw_recorder.hpp

struct Drawn {
  std::vector<TracedList> lists;
  VerifyMarks marks;
  Recorder rec;
};

Drawn draw(const PlantedBug& p, bool with_marks, int selected = 0, OverlayFlags flags = {}) {
  Drawn d;
  d.lists = user_lists(p.run.user, p.run.verdict, p.run.user.base);
  d.marks = verify_marks(p.run.verdict, selected);
  OverlayScene s;
  s.elements = &p.run.elements;
  s.grid = &p.run.grid;
  s.lists = &d.lists;
  s.book_numbering = p.run.user.base == 1;
  s.verify = with_marks ? &d.marks : nullptr;
  set_overlay(flags, &OverlayFlags::lists, true);  // and their ids with them, as the verify view opens
  draw_scene(s, flags, p.camera, d.rec);
  return d;
}

// The element whose centre is nearest to `at`.
ElementId nearest(const Elements& e, Vec2 at) {
  ElementId best = -1;
  double best_d = std::numeric_limits<double>::max();
  for (ElementId k = 0; k < static_cast<ElementId>(e.size()); ++k) {
    const double d = std::hypot(e.x[k] - at.x(), e.y[k] - at.y());
    if (d < best_d) {
      best_d = d;
      best = k;
    }
  }
  return best;
}

bool red(Rgba c) { return c == palette::kViolation; }

TEST(VerifyOverlay, APlantedWrongLinkIsDrawnRedBetweenTheRightTwoElements) {
  const PlantedBug p(0);
  const Drawn d = draw(p, true);
  std::vector<std::pair<ElementId, ElementId>> red_links;
  for (const auto& a : d.rec.arrows)
    if (red(a.colour)) red_links.emplace_back(nearest(p.run.elements, a.from), nearest(p.run.elements, a.to));
  // 1 -> 6 along C[4][6]'s chain, 8 -> 6 where C[1][6]'s walk met 6 again; nothing else in red.
  std::sort(red_links.begin(), red_links.end());
  EXPECT_EQ(red_links, (std::vector<std::pair<ElementId, ElementId>>{{1, 6}, {8, 6}}));
  // The chain's other links keep the list's colour: 3 -> 1 and 6 -> 4 are drawn, not in red.
  int chain_links = 0;
  for (const auto& a : d.rec.arrows)
    if (a.colour == list_colour("cell list", false) && nearest(p.run.elements, a.to) != nearest(p.run.elements, a.from)) ++chain_links;
  EXPECT_GE(chain_links, 3);
  // Without the marks the same lists have no red at all: the test can fail.
  const Drawn plain = draw(p, false);
  EXPECT_TRUE(std::none_of(plain.rec.arrows.begin(), plain.rec.arrows.end(), [](const auto& a) { return red(a.colour); }));
}

TEST(VerifyOverlay, ALinkFromAHeadStartsAtTheHeadsSquare) {
  PlantedBug p(0);
  // C[4][5]'s head names element 2, which lies in C[1][6]: a wrong link from the head.
  verify::Problem head;
  head.kind = verify::ProblemKind::WrongList;
  head.text = "C[4][5] = 2, but element 2 lies in cell (1,6)";
  head.elements = {2};
  head.link = std::make_pair(ElementId{-1}, ElementId{2});
  head.family = 0;
  head.list = 1;
  p.run.verdict.problems = {head};
  p.run.verdict.problem_count = 1;
  p.run.verdict.lists[1].chain = {2};
  for (auto& l : p.run.verdict.lists) l.cut = false;
  const Drawn d = draw(p, true);
  int found = 0;
  for (const auto& a : d.rec.arrows) {
    if (!red(a.colour)) continue;
    ++found;
    // It starts in cell (4,5)'s top-left corner, where its head's square is, and ends at element 2.
    EXPECT_NEAR(a.from.x(), 4.12, 0.05);
    EXPECT_NEAR(a.from.y(), 5.88, 0.05);
    EXPECT_EQ(nearest(p.run.elements, a.to), 2);
  }
  EXPECT_EQ(found, 1);
}

TEST(VerifyOverlay, ElementsAtFaultGetRedRingsAndTheSelectedProblemIsHighlighted) {
  const PlantedBug p(0);
  const Drawn d = draw(p, true, 1);  // the dropped element's problem selected
  std::vector<ElementId> ringed, white;
  for (const auto& c : d.rec.circles) {
    if (c.layer != Layer::Top) continue;
    const ElementId k = nearest(p.run.elements, c.centre);
    if (c.radius <= p.run.elements.r[k]) continue;  // a ring goes round the disc
    if (red(c.outline)) ringed.push_back(k);
    if (c.outline == palette::kSelection) white.push_back(k);
  }
  std::sort(ringed.begin(), ringed.end());
  ringed.erase(std::unique(ringed.begin(), ringed.end()), ringed.end());
  EXPECT_EQ(ringed, (std::vector<ElementId>{0, 6}));  // the dropped one and the one on two lists
  EXPECT_EQ(white, (std::vector<ElementId>{0}));
  const Drawn plain = draw(p, false);
  EXPECT_TRUE(std::none_of(plain.rec.circles.begin(), plain.rec.circles.end(), [](const auto& c) { return red(c.outline); }));
}

TEST(VerifyOverlay, ACutListEndsInARedCrossInsteadOfTheBar) {
  const PlantedBug p(0);
  const Drawn d = draw(p, true);
  // C[1][6]'s walk was cut after 8: red strokes just below-right of element 8, none at the others' ends.
  int at_8 = 0, at_others = 0;
  for (const auto& l : d.rec.lines) {
    const ElementId k = nearest(p.run.elements, l.from);
    // (The legend's key arrow is red too, far from every element.)
    if (!red(l.colour) || std::hypot(p.run.elements.x[k] - l.from.x(), p.run.elements.y[k] - l.from.y()) > 0.3) continue;
    (k == 8 ? at_8 : at_others) += 1;
  }
  EXPECT_GE(at_8, 3);  // the stub and the two strokes of the cross
  EXPECT_EQ(at_others, 0);
}

TEST(VerifyOverlay, HeadsAndIdsAreNumberedAsTheFileCounts) {
  for (const int base : {0, 1}) {
    const PlantedBug p(base);
    const Drawn d = draw(p, true);
    const std::string b = base == 1 ? "C[5][7]" : "C[4][6]";
    EXPECT_TRUE(d.rec.has_text(b)) << "base " << base;
    EXPECT_TRUE(d.rec.has_text(base == 1 ? "C[2][7]" : "C[1][6]")) << "base " << base;
    // Every id on its element, from 1 in the book's numbering.
    for (ElementId k = 0; k < 9; ++k) {
      const bool on_it = std::any_of(d.rec.texts.begin(), d.rec.texts.end(), [&](const Recorder::Text& t) {
        return t.text == std::to_string(k + base) && std::hypot(p.run.elements.x[k] - t.at.x(), p.run.elements.y[k] - t.at.y()) <= p.run.elements.r[k];
      });
      EXPECT_TRUE(on_it) << "id of element " << k << ", base " << base;
    }
    // The selected problem's text in the legend, with its place among the problems.
    EXPECT_TRUE(d.rec.has_text_containing("1 of 3 problems: E[" + std::to_string(1 + base) + "] = " + std::to_string(6 + base)))
        << "base " << base;
  }
}

TEST(VerifyOverlay, MarksFindTheirListsAndTheCaptionWraps) {
  const PlantedBug p(1);
  const VerifyMarks m = verify_marks(p.run.verdict, 2, 40);
  ASSERT_EQ(m.problems.size(), 3u);
  EXPECT_EQ(m.problems[0].list, 0);
  EXPECT_EQ(m.problems[1].list, -1);  // no list: the dropped element's problem names none
  EXPECT_EQ(m.problems[2].list, 3);
  EXPECT_EQ(m.selected, 2);
  ASSERT_GE(m.caption.size(), 2u);
  EXPECT_EQ(m.caption[0].rfind("3 of 3 problems: ", 0), 0u) << m.caption[0];
  for (const std::string& line : m.caption) EXPECT_LE(line.size(), 40u) << line;
  EXPECT_EQ(m.caption[1].rfind("  ", 0), 0u);  // continuation lines indented
  EXPECT_FALSE(m.ok);
  const std::vector<TracedList> lists = user_lists(p.run.user, p.run.verdict, 1);
  ASSERT_EQ(lists.size(), 4u);
  EXPECT_EQ(lists[0].head_label, "C[5][7]");
  EXPECT_EQ(lists[0].kind, "cell list");
  EXPECT_EQ((std::array<std::int32_t, 3>{lists[3].cell[0], lists[3].cell[1], lists[3].cell[2]}), (std::array<std::int32_t, 3>{1, 6, -1}));
  EXPECT_TRUE(lists[3].cut);
  verify::ArraysVerdict clean;
  clean.lists = p.run.verdict.lists;
  const VerifyMarks ok = verify_marks(clean, 0);
  EXPECT_TRUE(ok.ok);
  EXPECT_EQ(ok.selected, -1);
  ASSERT_FALSE(ok.caption.empty());
  EXPECT_EQ(ok.caption[0].rfind("no problems: 4 lists", 0), 0u) << ok.caption[0];
}

}  // namespace
}  // namespace nbscope::render

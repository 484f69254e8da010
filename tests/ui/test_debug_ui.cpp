// The debugging loop's UI side without GL: the stepper finds a violation's pair (the test, or why
// there is none) and says so; first/previous/next violation through the filter; the operation
// before/after on an element or a cell; the Timeline's and Violations panel's keys and requests;
// the camera kept on a point.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <deque>

#include "core/detector.hpp"
#include "support/ui_fixture.hpp"
#include "ui/panels.hpp"
#include "ui/stepper_panels.hpp"

namespace nbscope::ui {
namespace {

using testui::BookFrame;
using testui::ImGuiScope;
using testui::press;
using testui::release;
using testui::run_frame;

// In the book's nine elements (0-based here) 0 and 1 touch, 2 and 4 share cell (1, 6), and 0 and 8
// lie three columns apart.
TEST(StepperTarget, GoesToTheTestOfAPairAndSaysWhatItMeans) {
  BookFrame f;
  f.sim.algorithm = "nbs";
  f.sim.paused = false;  // a target is captured even while the simulation runs
  StepperSession s;
  s.set_target({0, Pair{0, 1}, Invariant::AEqualsR, "missing from A (in R)"});
  EXPECT_TRUE(s.target_pending());
  s.update(f.traced(), 0, 1);
  ASSERT_TRUE(s.has_capture()) << s.message();
  EXPECT_FALSE(s.target_pending());
  ASSERT_TRUE(s.target_location().has_value());
  EXPECT_EQ(s.target_location()->finding, PairFinding::Tested);
  const TraceEvent* e = s.stepper().current();
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->op, TraceOp::TestPair);
  EXPECT_TRUE((e->element == 0 && e->other == 1) || (e->element == 1 && e->other == 0));
  EXPECT_TRUE(e->contact);
  EXPECT_EQ(s.stepper().position(), *s.target_location()->event + 1);
  EXPECT_NE(s.target_status().find("tested against"), std::string::npos) << s.target_status();
  EXPECT_NE(s.target_status().find("lost after detection"), std::string::npos) << s.target_status();
  // The element filter and the breakpoint aim at the pair, for the next question.
  EXPECT_EQ(s.focus_element, 0);
  EXPECT_EQ(s.breakpoint.kind, BreakKind::FirstPairOf);
}

TEST(StepperTarget, SaysWhenTwoCellsAreNotNeighboursInBookNumbering) {
  BookFrame f;
  f.sim.algorithm = "screen";
  StepperSession s(StepperConfig{std::nullopt, true});
  s.set_target({0, Pair{0, 8}, Invariant::AabbInCells, "tight AABBs overlap but the cells are not neighbours"});
  s.update(f.traced(), 0, 1);
  ASSERT_TRUE(s.target_location().has_value());
  EXPECT_EQ(s.target_location()->finding, PairFinding::NotNeighbours);
  // Book numbering: element 1 in cell (5,7), element 9 in (2,7).
  EXPECT_NE(s.target_status().find("1 lies in cell (5,7) and 9 in (2,7): not neighbours"), std::string::npos)
      << s.target_status();
}

TEST(StepperTarget, WaitsForItsFrame) {
  BookFrame f;
  f.sim.algorithm = "nbs";
  f.sim.paused = true;
  StepperSession s;
  s.set_target({7, Pair{0, 1}, Invariant::TInA, "shapes touch but the pair is not in A"});
  s.update(f.traced(), 0, 1);  // frame 0 shown: the target waits
  EXPECT_TRUE(s.target_pending());
  EXPECT_TRUE(s.target_status().empty());
  f.result.frame = 7;
  s.update(f.traced(), 0, 2);
  EXPECT_FALSE(s.target_pending());
  EXPECT_FALSE(s.target_status().empty());
  // Another frame captured later: the status described frame 7, and goes.
  f.result.frame = 8;
  s.update(f.traced(), 0, 3);
  EXPECT_TRUE(s.target_status().empty());
}

TEST(StepperLongTraces, SeeksTheOperationsOfAnElementOrACell) {
  BookFrame f;
  f.sim.algorithm = "nbs";
  StepperSession s;
  s.update(f.traced(), 0, 1);
  ASSERT_TRUE(s.has_capture());
  Stepper& st = s.stepper();
  st.seek(0);
  std::vector<std::size_t> about_3;
  for (std::size_t n = 0; n < st.size(); ++n) {
    Breakpoint b;
    b.element = 3;
    if (breakpoint_matches(b, st.events()[n])) about_3.push_back(n);
  }
  ASSERT_GE(about_3.size(), 3u);
  ASSERT_TRUE(s.seek_touching(BreakKind::Element, 3, {-1, -1}, +1));
  EXPECT_EQ(st.position(), about_3[0] + 1);
  ASSERT_TRUE(s.seek_touching(BreakKind::Element, 3, {-1, -1}, +1));
  EXPECT_EQ(st.position(), about_3[1] + 1);
  ASSERT_TRUE(s.seek_touching(BreakKind::Element, 3, {-1, -1}, -1));
  EXPECT_EQ(st.position(), about_3[0] + 1);
  EXPECT_FALSE(s.seek_touching(BreakKind::Element, 3, {-1, -1}, -1));
  EXPECT_NE(s.status.find("no earlier operation on element 3"), std::string::npos) << s.status;
  // Cell (4, 6) holds element 0 (x 4.75, y 6.45): the first operation naming it is a push onto it.
  st.seek(0);
  ASSERT_TRUE(s.seek_touching(BreakKind::Cell, -1, {4, 6}, +1));
  const TraceEvent* e = st.current();
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->cell[0], 4);
  EXPECT_EQ(e->cell[1], 6);
  // The operation's point for the camera: its element's centre.
  const auto p = s.focus_point();
  ASSERT_TRUE(p.has_value());
  EXPECT_DOUBLE_EQ(p->x(), f.elements.x[e->element]);
}

// Five violations over three frames; the filter hides T-in-A.
struct ViolationsFixture {
  std::vector<Violation> all;
  SimView sim;
  UiState state;
  ViolationsFixture() {
    const Invariant inv[] = {Invariant::AEqualsR, Invariant::TInA, Invariant::AEqualsR, Invariant::TInA, Invariant::AabbInCells};
    for (int k = 0; k < 5; ++k) all.push_back(Violation{k / 2 + 1, inv[k], Pair{k, k + 1}, {}, {}, "x"});
    sim.violations = &all;
    sim.violations_total = 5;
  }
};

TEST(Violations, FirstNextPreviousFollowTheFilter) {
  ViolationsFixture v;
  EXPECT_EQ(step_violation(v.sim, v.state, +1), 0u);  // nothing chosen yet: the first
  v.state.violation_filter[static_cast<std::size_t>(Invariant::TInA)] = false;
  v.state.current_violation = 0;
  EXPECT_EQ(step_violation(v.sim, v.state, +1), 2u);  // 1 is T-in-A: skipped
  v.state.current_violation = 2;
  EXPECT_EQ(step_violation(v.sim, v.state, +1), 4u);
  EXPECT_EQ(step_violation(v.sim, v.state, -1), 0u);
  v.state.current_violation = 4;
  EXPECT_EQ(step_violation(v.sim, v.state, +1), std::nullopt);
  EXPECT_EQ(step_violation(v.sim, v.state, 0), 0u);
  v.state.violation_filter = {false, false, false, false};
  EXPECT_EQ(step_violation(v.sim, v.state, 0), std::nullopt);
  EXPECT_EQ(describe_violation(v.all[2], true), "A==R in frame 2: (3, 4) x; the detector's cells (1,1) and (1,1)");
}

// With none chosen, ] and [ start from the frame on screen, not from the run's first violation.
TEST(Violations, NothingChosenStartsFromTheFrameOnScreen) {
  ViolationsFixture v;  // frames 1, 1, 2, 2, 3
  FrameResult shown;
  v.sim.frame = &shown;
  shown.frame = 2;
  EXPECT_EQ(step_violation(v.sim, v.state, +1), 2u) << "the first at or after frame 2";
  EXPECT_EQ(step_violation(v.sim, v.state, -1), 3u) << "the last at or before frame 2";
  EXPECT_EQ(step_violation(v.sim, v.state, 0), 0u) << "Shift+[ is still the run's first";
  shown.frame = 4;
  EXPECT_EQ(step_violation(v.sim, v.state, +1), std::nullopt) << "none after the last";
  EXPECT_EQ(step_violation(v.sim, v.state, -1), 4u);
  shown.frame = 0;
  EXPECT_EQ(step_violation(v.sim, v.state, -1), std::nullopt) << "none before the first";
  v.state.violation_filter[static_cast<std::size_t>(Invariant::AEqualsR)] = false;
  shown.frame = 2;
  EXPECT_EQ(step_violation(v.sim, v.state, +1), 3u) << "through the filter";
}

// The Violations panel's cells are the detector's; for the frame on screen the grid's true cells
// are at hand too, and differ under a wrong integerisation (off-by-one-cell: element 0 in (4,6)
// reported in (5,6), element 1 likewise).
TEST(Violations, TheTrueCellsBesideTheDetectorsOnTheFrameOnScreen) {
  BookFrame f;  // Fig. 3.15 on unit cells: elements 0 and 1 at (4.75, 6.45) and (4.9, 6.5), both in (4,6)
  f.result.frame = 7;
  const Violation off{7, Invariant::AEqualsR, Pair{0, 1}, {5, 6}, {5, 6}, "missing from A (in R)"};
  const auto truth = grid_cells(f.sim, off);
  ASSERT_TRUE(truth.has_value());
  EXPECT_EQ((*truth)[0], (CellIndex{4, 6}));
  EXPECT_EQ((*truth)[1], (CellIndex{4, 6}));
  EXPECT_EQ(cell_pair_text((*truth)[0], (*truth)[1], true), "(5,7) (5,7)");
  Violation other = off;
  other.frame = 6;
  EXPECT_EQ(grid_cells(f.sim, other), std::nullopt) << "another frame's elements are not at hand";
  other = off;
  other.pair = Pair{0, 99};
  EXPECT_EQ(grid_cells(f.sim, other), std::nullopt);
  // The panel draws it (two-line rows) without trouble.
  ImGuiScope scope;
  UiHost host;
  std::vector<Violation> log{off};
  f.sim.violations = &log;
  f.sim.violations_total = 1;
  f.sim.violations_by_invariant = {1, 0, 0, 0};
  f.state.current_violation = 0;
  EXPECT_NO_THROW(run_frame(host, f));
  EXPECT_NO_THROW(run_frame(host, f));
}

// The host's keys ask for frames and violations; the panels draw from the run's data.
TEST(DebugPanels, KeysAskForFramesPlaybackAndViolations) {
  ImGuiScope scope;
  UiHost host;
  BookFrame f;
  ViolationsFixture v;
  std::deque<FrameSummary> timeline;
  for (int k = 0; k <= 3; ++k) timeline.push_back(FrameSummary{k, k / 60.0, 0, true, true, 9, 1, k == 2 ? 2 : 0, 0, 0.1f, 0});
  f.sim.timeline = &timeline;
  f.sim.newest_frame = 3;
  f.result.frame = 3;
  f.sim.violations = &v.all;
  f.sim.violations_total = 5;
  f.sim.violation_frames = 3;
  f.sim.violations_by_invariant = {2, 0, 2, 1};
  f.sim.fault_name = "drop-pair";
  ImGui::GetIO().MousePos = ImVec2(640, 360);
  run_frame(host, f);
  run_frame(host, f);

  press(',');
  run_frame(host, f);
  release();
  EXPECT_EQ(f.requests.frame_delta, -1);
  press('.', true);
  run_frame(host, f);
  release();
  EXPECT_EQ(f.requests.frame_delta, 10);
  press('J');
  run_frame(host, f);
  release();
  EXPECT_EQ(f.requests.play, -1);
  press(']');
  run_frame(host, f);
  release();
  EXPECT_EQ(f.requests.go_to_violation, 4u) << "none chosen: the first at or after frame 3, on screen";
  f.state.current_violation = 3;
  press('[');
  run_frame(host, f);
  release();
  EXPECT_EQ(f.requests.go_to_violation, 2u);
  run_frame(host, f);  // the key up for a frame: the next press is a new one
  press('[', true);
  run_frame(host, f);
  release();
  EXPECT_EQ(f.requests.go_to_violation, 0u);

  // The banner of the injected fault covers the top of the scene: the insets say so.
  EXPECT_GT(host.insets(f.state).top, ImGui::GetFrameHeight() + 5);
  // Both panels were drawn (their windows are among the covered rectangles with the menu and banner).
  EXPECT_GE(host.covered().size(), 4u);
}

TEST(DebugPanels, APastFrameIsSelectedNotDragged) {
  ImGuiScope scope;
  UiHost host;
  BookFrame f;
  f.camera.set({4.75, 6.45}, 40.0);  // element 0 in the middle of the view
  f.sim.showing_past = true;
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(640, 360);
  run_frame(host, f);
  io.MouseDown[0] = true;
  run_frame(host, f);
  io.MouseDown[0] = false;
  EXPECT_EQ(f.state.selected, 0);
  EXPECT_FALSE(f.requests.drag_begin.has_value());
  EXPECT_FALSE(f.state.dragging);
  ASSERT_TRUE(f.state.selected_cell.has_value());
  EXPECT_EQ((*f.state.selected_cell)[0], 4);
}

// The panels read the frame from the FrameResult the view points at, and cope without one.
TEST(DebugPanels, ReadTheFrameResultAndCopeWithNone) {
  ImGuiScope scope;
  UiHost host;
  BookFrame f;
  for (const auto& panel : host.panels()) f.state.panel_open[panel->title()] = true;
  FrameReport& report = f.result.lanes.front().report;
  report.checked = true;
  report.reference = "brute";
  for (int k = 0; k < 8; ++k) report.violations.push_back(Violation{0, Invariant::AEqualsR, Pair{k, k + 1}, {1, 2}, {3, 4}, "missing from A"});
  report.broken[0] = 8;
  f.state.book_numbering = true;
  EXPECT_EQ(violation_line(report.violations[2], true), "A==R: (3, 4) missing from A, cells (2,3) (4,5)");
  EXPECT_EQ(violation_line(report.violations[2], false), "A==R: (2, 3) missing from A, cells (1,2) (3,4)");
  EXPECT_NO_THROW(run_frame(host, f));
  f.sim.frame = nullptr;  // nothing loaded
  f.sim.elements = nullptr;
  f.sim.trace.reset();
  EXPECT_EQ(f.sim.frame_number(), 0);
  EXPECT_EQ(f.sim.grid(), nullptr);
  EXPECT_EQ(f.sim.report(), nullptr);
  EXPECT_NO_THROW(run_frame(host, f));
}

// A dump's frame names its atoms by their ids everywhere a panel names an element (book numbering
// does not apply to ids); its pairs at the boundary are listed apart, in the Violations panel, which
// shows for them even when nothing broke; the Stats panel names the touching convention.
TEST(DebugPanels, AtomsAreNamedByTheirIdsAndBoundaryPairsAreListedApart) {
  ImGuiScope scope;
  UiHost host;
  BookFrame f;
  const std::vector<std::int64_t> ids{2753, 12, 99, 100, 101, 102, 103, 104, 105};
  const Violation rows{0, Invariant::AEqualsR, Pair{2, 3}, {1, 2}, {3, 4}, "missing from A"};
  FrameReport named;
  named.violations.push_back(rows);
  name_atoms(named, &ids);  // as the pipeline names a dump frame's violations
  const Violation& v = named.violations.front();
  EXPECT_EQ(violation_line(v, true), "A==R: atoms (99, 100) missing from A, cells (2,3) (4,5)");
  EXPECT_EQ(describe_violation(v, false), "A==R in frame 0: atoms (99, 100) missing from A; the detector's cells (1,2) and (3,4)");
  EXPECT_EQ(describe_violation(rows, false), "A==R in frame 0: (2, 3) missing from A; the detector's cells (1,2) and (3,4)");
  // A dump's frame is its timestep, and a pair of two elements carries its gap (the checker measures it).
  Violation dumped = v;
  dumped.frame = 20000;
  dumped.gap = -0.0125;
  EXPECT_EQ(describe_violation(dumped, false, 2, FrameUnit::timestep),
            "A==R in timestep 20000: atoms (99, 100) missing from A; distance - radii = -0.0125 (in contact); the detector's cells (1,2) and (3,4)");
  BoundaryPair tie{Pair{0, 1}, 0.0, 0.0, true, true};
  EXPECT_EQ(boundary_line(tie, false, &ids),
            "atoms (2753, 12): an exact tie (gap 0): a contact under --touching inclusive, not under strict (R has it, A not)");
  EXPECT_EQ(touching_line(Touching::strict), "touching: strict (<)");
  EXPECT_EQ(touching_line(Touching::inclusive), "touching: inclusive (<=)");
  // The frame's ids reach the panels in the frame itself (FrameResult::ids).
  EXPECT_EQ(f.sim.ids(), nullptr);
  f.result.ids = std::make_shared<const std::vector<std::int64_t>>(ids);
  EXPECT_EQ(*f.sim.ids(), ids);
  // No violation, one tie: the Violations panel shows, for its boundary section.
  FrameReport& report = f.result.lanes.front().report;
  report.checked = true;
  report.boundary.push_back(tie);
  const Panel* violations = nullptr;
  for (const auto& panel : host.panels())
    if (std::string(panel->title()) == kViolationsTitle) violations = panel.get();
  ASSERT_NE(violations, nullptr);
  UiContext ctx{f.sim, f.state, f.requests, f.camera};
  EXPECT_FALSE(violations->visible(ctx)) << "counted in FrameCounts, not yet";
  report.counts.ties = 1;
  EXPECT_TRUE(violations->visible(ctx));
  f.state.selected = 0;
  f.sim.replaying = true;
  for (const auto& panel : host.panels()) f.state.panel_open[panel->title()] = true;
  EXPECT_NO_THROW(run_frame(host, f));
}

// A click on one of the Stats panel's violation lines chooses it as the Violations panel does: the
// request names its index in the run's log (here after another frame's violation).
TEST(DebugPanels, AViolationLineInStatsIsOneClickFromItsViolation) {
  ImGuiScope scope;
  UiHost host;
  BookFrame f;
  f.result.frame = 5;
  FrameReport& report = f.result.lanes.front().report;
  report.checked = true;
  report.reference = "brute";
  std::vector<Violation> log{Violation{3, Invariant::TInA, Pair{0, 1}, {}, {}, "earlier"}};
  for (int k = 0; k < 3; ++k) {
    report.violations.push_back(Violation{5, Invariant::AEqualsR, Pair{k, k + 1}, {1, 2}, {3, 4}, "missing from A"});
    log.push_back(report.violations.back());
  }
  report.broken[0] = 3;
  f.sim.violations = &log;
  f.sim.violations_total = 4;
  ImGuiIO& io = ImGui::GetIO();
  run_frame(host, f);
  run_frame(host, f);
  const ImGuiWindow* stats = ImGui::FindWindowByName(kStatsTitle);
  ASSERT_NE(stats, nullptr);
  // Down the panel 7 pixels at a time (farther than a double-click reaches), a click each: the first
  // line that answers is the first violation's.
  std::optional<std::size_t> chosen;
  for (float y = stats->Pos.y + 2; y < stats->Pos.y + stats->Size.y && !chosen; y += 7) {
    io.MousePos = ImVec2(stats->Pos.x + 40, y);
    run_frame(host, f);
    io.MouseDown[0] = true;
    run_frame(host, f);
    io.MouseDown[0] = false;
    chosen = f.requests.go_to_violation;
    run_frame(host, f);
  }
  ASSERT_TRUE(chosen.has_value()) << "no violation line in Stats answers a click";
  EXPECT_EQ(*chosen, 1u);
  EXPECT_EQ(violation_index(f.sim, report.violations[2]), 3u);
  EXPECT_EQ(violation_index(f.sim, Violation{5, Invariant::TInA, Pair{0, 1}, {}, {}, ""}), std::nullopt);
}

// Resume here's result is shown whole: wrapped inside the Timeline, not cut at its edge.
TEST(DebugPanels, TheResumeNoteIsShownWhole) {
  ImGuiScope scope;
  UiHost host;
  BookFrame f;
  std::deque<FrameSummary> timeline;
  for (int k = 0; k <= 3; ++k) timeline.push_back(FrameSummary{k, k / 60.0, 0, true, true, 9, 1, 0, 0, 0.1f, 0});
  f.sim.timeline = &timeline;
  f.sim.newest_frame = 209;
  f.sim.resume_note = "resumed at 209 (re-simulated frames matched the kept ones)";
  const auto timeline_window = [&] {
    for (int k = 0; k < 3; ++k) run_frame(host, f);
    const ImGuiWindow* w = ImGui::FindWindowByName(kTimelineTitle);
    EXPECT_NE(w, nullptr);
    return w;
  };
  ImGui::GetIO().DisplaySize = ImVec2(900, 600);  // a narrow dock between the columns
  const ImGuiWindow* w = timeline_window();
  ASSERT_NE(w, nullptr);
  EXPECT_LE(w->ContentSize.x, w->Size.x - 2 * ImGui::GetStyle().WindowPadding.x + 1) << "the note runs past the dock's edge";
  const float one_line = w->Size.y;
  f.sim.resume_note += ", and more words after it so that it needs more than one line in any dock at all";
  w = timeline_window();
  ASSERT_NE(w, nullptr);
  EXPECT_LE(w->ContentSize.x, w->Size.x - 2 * ImGui::GetStyle().WindowPadding.x + 1);
  EXPECT_GT(w->Size.y, one_line) << "a longer note takes more lines";
}

// Restart drops the run: asked first when there are past frames or violations; Enter confirms.
TEST(DebugPanels, RestartOfARunWithHistoryAsksFirst) {
  ImGuiScope scope;
  ImGui::GetIO().KeyMap[ImGuiKey_Enter] = 257;
  UiHost host;
  BookFrame f;
  ImGui::GetIO().MousePos = ImVec2(640, 360);
  run_frame(host, f);
  press('R');
  run_frame(host, f);
  release();
  EXPECT_TRUE(f.requests.restart) << "nothing to lose (frame 0, no violation): at once";
  run_frame(host, f);
  f.sim.newest_frame = 120;
  press('R');
  run_frame(host, f);
  release();
  EXPECT_FALSE(f.requests.restart) << "120 frames would be dropped: asked first";
  run_frame(host, f);
  EXPECT_FALSE(f.requests.restart);
  press('R');
  run_frame(host, f);
  release();
  EXPECT_FALSE(f.requests.restart) << "keys do not reach the scene under the question";
  press(257);
  run_frame(host, f);
  release();
  EXPECT_TRUE(f.requests.restart) << "Enter confirms";
}

TEST(CameraFollow, KeepsAPointInsideTheFreeView) {
  render::Camera cam;
  cam.set_viewport(1000, 600);
  cam.set({0, 0}, 10.0);
  const render::ScreenInsets in{200, 100, 20, 80};
  cam.keep_in_view({1, 1}, in, 0.2);  // already well inside: no move
  EXPECT_EQ(cam.centre(), Eigen::Vector2d(0, 0));
  cam.keep_in_view({200, -50}, in, 0.2);
  const Eigen::Vector2d s = cam.to_screen({200, -50});
  EXPECT_NEAR(s.x(), 200 + 0.5 * (1000 - 200 - 100), 1e-6);
  EXPECT_NEAR(s.y(), 20 + 0.5 * (600 - 20 - 80), 1e-6);
  EXPECT_EQ(cam.pixels_per_metre(), 10.0);
}

}  // namespace
}  // namespace nbscope::ui

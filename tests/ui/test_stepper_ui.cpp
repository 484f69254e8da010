// The stepper's UI side without GL: the session (what it records and when, its wording of events
// and array entries in 0- and 1-based numbering, windows over large arrays), the three panels
// driven by ImGui frames and keys (→/← step, Shift: phase, Space: play), and the scene overlay
// recorded through a DrawSink: the element, the growing list, the mask cell, the tested pair.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <optional>
#include <string>

#include "core/detector.hpp"
#include "core/traced_lists.hpp"
#include "render/palette.hpp"
#include "ui/host.hpp"
#include "ui/panels.hpp"
#include "ui/stepper_panels.hpp"
#include "support/generators.hpp"
#include "support/ui_fixture.hpp"

namespace nbscope::ui {
namespace {

using testui::BookFrame;
using testui::ImGuiScope;
using testui::Recorder;

TEST(StepperSession, WindowsKeepTheFocusInViewAndClampAtTheEnds) {
  EXPECT_EQ(window_range(9, 4, 16), (std::pair<std::int64_t, std::int64_t>{0, 9}));
  EXPECT_EQ(window_range(100, 50, 10), (std::pair<std::int64_t, std::int64_t>{45, 55}));
  EXPECT_EQ(window_range(100, 2, 10), (std::pair<std::int64_t, std::int64_t>{0, 10}));
  EXPECT_EQ(window_range(100, 99, 10), (std::pair<std::int64_t, std::int64_t>{90, 100}));
  EXPECT_EQ(window_range(100, 500, 10), (std::pair<std::int64_t, std::int64_t>{90, 100}));
  EXPECT_EQ(window_range(0, 0, 10), (std::pair<std::int64_t, std::int64_t>{0, 0}));
}

TEST(StepperSession, RecordsOnlyAPausedFrameAndWordsEventsAsTheBook) {
  BookFrame f;
  StepperSession s;
  f.sim.paused = false;
  s.update(f.traced(), 0, 1);
  EXPECT_FALSE(s.has_capture()) << "a running simulation must not be traced every frame";
  f.sim.paused = true;
  s.update(f.traced(), 0, 2);
  ASSERT_TRUE(s.has_capture()) << s.message();
  EXPECT_TRUE(s.current_for(f.sim));
  EXPECT_EQ(s.stepper().size(), 77u);
  const auto& arrays = s.stepper().trace().arrays();
  EXPECT_EQ(entry_name(arrays[0], 46, false), "C[4][6]");
  EXPECT_EQ(entry_name(arrays[0], 46, true), "C[5][7]");
  EXPECT_TRUE(s.holds_elements(0));
  // NBS's B[0]/B[1] (current row / row below) keeps its 0/1 in book numbering, as on p.123.
  TracedArray b{"B", {2, 10}, std::vector<std::int32_t>(20, -1)};
  EXPECT_EQ(entry_name(b, 15, false), "B[1][5]");
  EXPECT_EQ(entry_name(b, 15, true), "B[1][6]");

  // Operation 5: element 4 pushed onto C[5][7] (book numbers), eq. 3.21: E[4] = HEAD = 2; HEAD = 4.
  s.stepper().seek(5);
  s.book_numbering = true;
  EXPECT_EQ(describe_event(s, *s.stepper().current()), "push k=4 onto cell list C[5][7]: E[4] = 2, C[5][7] = 4");
  s.book_numbering = false;
  EXPECT_EQ(describe_event(s, *s.stepper().current()), "push k=3 onto cell list C[4][6]: E[3] = 1, C[4][6] = 3");
  s.stepper().seek(20);
  s.book_numbering = true;
  EXPECT_EQ(describe_event(s, *s.stepper().current()), "test k=2 against 1: contact");
  const std::int32_t own_cell[3] = {4, 6, -1};
  const auto list = s.list_of_cell(own_cell);
  ASSERT_TRUE(list.has_value());
  EXPECT_EQ(list->list, 46);
  const auto& tests = s.tests_of(1);
  ASSERT_FALSE(tests.empty());
  EXPECT_EQ(tests.front().other, 0);
  EXPECT_TRUE(tests.front().contact);

  // The next frame keeps the place in the sequence.
  f.result.frame = 1;
  s.update(f.traced(), 0, 3);
  EXPECT_EQ(s.frame(), 1);
  EXPECT_EQ(s.stepper().position(), 20u);
}

// The element section shows an entry the detection has not written yet as unset, never as the
// array's meaningless initial contents shifted to book numbering.
TEST(StepperSession, ElementEntriesNotWrittenYetShowAsUnset) {
  BookFrame f;
  f.sim.algorithm = "nbs";
  StepperSession s;
  s.capture(f.traced());
  ASSERT_TRUE(s.has_capture()) << s.message();
  s.book_numbering = true;
  s.stepper().seek(5);  // the y-list pushes of elements 1..4 (book): no x-list yet
  EXPECT_EQ(element_entries(s, 3).next, "Y[4] = 3,  X[4] = \xC2\xB7");
  s.book_numbering = false;
  EXPECT_EQ(element_entries(s, 3).next, "Y[3] = 2,  X[3] = \xC2\xB7");
  s.stepper().seek(s.stepper().size());
  EXPECT_EQ(element_entries(s, 3).next.find("\xC2\xB7"), std::string::npos) << element_entries(s, 3).next;
}

// Sort's mapping: a first write says "was unset" in the Stepper's line as in the Arrays panel, and
// the permutation `order` is a position, not a next array.
// A dump's frame: the step texts name each element by its atom id with the row beside it (issue 37:
// the Stepper said k=8 where the Violations panel said atom 9), the arrays' entries still by row.
TEST(StepperSession, NamesADumpsElementsByAtomIdWithTheRowBeside) {
  BookFrame f;
  const std::vector<std::int64_t> ids{101, 102, 103, 104, 105, 106, 107, 108, 109};
  f.result.ids = std::make_shared<const std::vector<std::int64_t>>(ids);  // the frame carries its atoms' ids
  StepperSession s;
  s.capture(f.traced());
  ASSERT_TRUE(s.has_capture()) << s.message();
  s.stepper().seek(5);
  EXPECT_EQ(describe_event(s, *s.stepper().current()), "push k=104 (row 3) onto cell list C[4][6]: E[3] = 1, C[4][6] = 3");
  s.book_numbering = true;
  EXPECT_EQ(describe_event(s, *s.stepper().current()), "push k=104 (row 4) onto cell list C[5][7]: E[4] = 2, C[5][7] = 4");
  s.stepper().seek(20);
  EXPECT_EQ(describe_event(s, *s.stepper().current()), "test k=102 (row 2) against 101 (row 1): contact");
}

TEST(StepperSession, SortWordsFirstWritesAsUnsetAndOrderAsAPosition) {
  BookFrame f;
  f.sim.algorithm = "sort";
  StepperSession s;
  s.capture(f.traced());
  ASSERT_TRUE(s.has_capture()) << s.message();
  s.stepper().seek(2);  // the phase, then ix[0]
  EXPECT_EQ(describe_event(s, *s.stepper().current()), "cell: ix[0] = 4 (was unset) for k=0");
  const ElementEntries early = element_entries(s, 0);
  EXPECT_TRUE(early.next.empty()) << early.next;
  EXPECT_EQ(early.own, "ix[0] = 4,  iy[0] = \xC2\xB7");
  EXPECT_EQ(early.position, "not in order yet");
  s.stepper().seek(s.stepper().size());
  const ElementEntries done = element_entries(s, 0);
  EXPECT_TRUE(done.next.empty()) << done.next;
  EXPECT_EQ(done.own, "ix[0] = 4,  iy[0] = 6");
  EXPECT_EQ(done.position.rfind("order[", 0), 0u) << done.position;
  EXPECT_NE(done.position.find("] = 0"), std::string::npos) << done.position;
}

// The Selection panel names a list's head as the Arrays panel and docs/window.md do (B[0][4], never the
// flat B[4]; the row below's copy B[1][4]), and counts from 1 in book numbering like everything else.
TEST(SelectionPanel, NamesListHeadsAsTheArraysDoInEitherNumbering) {
  BookFrame f;
  auto nbs = make_detector("nbs");
  DetectOptions o;
  o.grid.cell_size = 1.0;
  o.grid.origin = std::array<double, 3>{0, 0, 0};
  o.grid.cells = std::array<std::int64_t, 3>{10, 10, 1};
  PairList pairs;
  TraceLog log;
  nbs->detect_traced(f.elements, o, pairs, log);
  std::vector<std::string> zero, book;
  for (const TracedList& l : traced_lists(log, 9)) {
    if (std::find(l.chain.begin(), l.chain.end(), 3) == l.chain.end()) continue;
    zero.push_back(describe_chain(l, 3, false));
    book.push_back(describe_chain(l, 3, true));
  }
  const auto has = [](const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); };
  EXPECT_TRUE(has(zero, "y_heads[6]: 8 -> 6 -> 4 -> [3] -> 2 -> 1 -> 0 -> -1")) << ::testing::PrintToString(zero);
  EXPECT_TRUE(has(zero, "B[0][4]: 0 -> 1 -> [3] -> -1")) << ::testing::PrintToString(zero);
  EXPECT_TRUE(has(book, "y_heads[7]: 9 -> 7 -> 5 -> [4] -> 3 -> 2 -> 1 -> -1")) << ::testing::PrintToString(book);
  EXPECT_TRUE(has(book, "B[0][5]: 1 -> 2 -> [4] -> -1")) << ::testing::PrintToString(book);
}

TEST(StepperSession, SaysWhyNothingCanBeSteppedInsteadOfThrowing) {
  BookFrame f;
  {
    // Brute force keeps no arrays, but its trace is the pair tests: it can be stepped.
    StepperSession s;
    f.sim.algorithm = "brute";
    s.capture(f.traced());
    ASSERT_TRUE(s.has_capture()) << s.message();
    EXPECT_EQ(s.stepper().size(), 1u + 9u * 8u / 2u);  // the phase, then every pair once
    EXPECT_TRUE(s.stepper().trace().arrays().empty());
  }
  {
    // A trace the frame loop refused (here: a detector that records nothing) says why, in the panels.
    StepperSession s;
    auto refused = std::make_shared<FrameTrace>();
    refused->refusal = "box2d records no operations";
    f.sim.trace = refused;
    EXPECT_NO_THROW(s.capture(f.sim));
    EXPECT_FALSE(s.has_capture());
    EXPECT_EQ(s.message(), "box2d records no operations");
    EXPECT_EQ(idle_message(s), "box2d records no operations");
  }
  const Elements many = testdata::make_layout(testdata::Layout::Loose, kMaxTracedElements + 1, 2, 1);
  f.sim.elements = &many;
  f.sim.frame = nullptr;  // no frame result: no grid to pin
  f.sim.algorithm = "nbs";
  StepperSession s;
  s.capture(f.traced());
  EXPECT_FALSE(s.has_capture());
  EXPECT_NE(s.message().find("too many"), std::string::npos) << s.message();
}

TEST(StepperSession, AConfiguredStepRecordsEvenWhileRunning) {
  BookFrame f;
  f.sim.paused = false;
  StepperSession s(StepperConfig{std::size_t{10}, true});
  s.update(f.traced(), 0, 1);
  ASSERT_TRUE(s.has_capture());
  EXPECT_EQ(s.stepper().position(), 10u);
  EXPECT_TRUE(s.book_numbering);
}

using testui::press;
using testui::release;
using testui::run_frame;

// The Help menu lists every key the host and the Stepper handle (the Stepper's were once missing
// from --help; test_cli.cpp checks --help and docs/window.md).
TEST(HelpMenu, NamesEveryKeyOfTheHostAndTheStepper) {
  std::string text;
  for (const char* line : help_lines()) text += std::string(line) + "\n";
  for (const char* key : {"P play", "O single step", "R restart", "Home", "1..N", "Esc", "J play backwards", "Shift+[", "->",
                          "<-", "Shift+->", "Space", "PageUp", "PageDown", "Shift+PageUp", ",", ".", "@overlays"})
    EXPECT_NE(text.find(key), std::string::npos) << key;
}

// The top-left corner of the window titled `title` in the last frame.
ImVec2 window_pos(const char* title) {
  const ImGuiWindow* w = ImGui::FindWindowByName(title);
  return w != nullptr ? w->Pos : ImVec2(-1, -1);
}

// At 1024x640 with the stepper's panels open the scene keeps about half of the window each way
// (the Arrays dock and the columns once left it a sixth), and the Stepper and Pseudocode keep
// their place when the algorithm changes (the Stepper once moved from y=85 to y=215).
TEST(StepperPanels, LeaveTheSceneHalfTheWindowAndKeepTheirPlaceAcrossAlgorithms) {
  ImGuiScope scope;
  ImGui::GetIO().DisplaySize = ImVec2(1024, 640);
  UiHost host;
  auto session = add_stepper_panels(host, StepperConfig{std::size_t{20}, false});
  BookFrame f;
  f.camera.set_viewport(1024, 640);
  open_stepper_panels(f.state);
  std::optional<ImVec2> stepper, pseudocode;
  for (const char* algorithm : {"screen", "nbs", "tree", "sort", "brute", "nbs"}) {
    f.sim.algorithm = algorithm;
    for (int i = 0; i < 4; ++i) run_frame(host, f);
    ASSERT_TRUE(session->has_capture()) << algorithm << ": " << session->message();
    const render::ScreenInsets in = host.insets(f.state);
    EXPECT_LE(in.left + in.right, 0.52 * 1024) << algorithm;
    EXPECT_LE(in.bottom, 0.5 * 640) << algorithm;
    if (!stepper) {
      stepper = window_pos(kStepperTitle);
      pseudocode = window_pos(kPseudocodeTitle);
    }
    EXPECT_EQ(window_pos(kStepperTitle).y, stepper->y) << algorithm;
    EXPECT_EQ(window_pos(kStepperTitle).x, stepper->x) << algorithm;
    EXPECT_EQ(window_pos(kPseudocodeTitle).y, pseudocode->y) << algorithm;
  }
}

TEST(StepperPanels, KeysStepPhaseAndPlayAndTheSceneShowsTheOperation) {
  ImGuiScope scope;
  UiHost host;
  auto session = add_stepper_panels(host, StepperConfig{std::size_t{1}, false});
  BookFrame f;
  open_stepper_panels(f.state);
  ImGui::GetIO().MousePos = ImVec2(640, 360);
  run_frame(host, f);
  run_frame(host, f);
  ASSERT_TRUE(session->has_capture()) << session->message();
  Stepper& st = session->stepper();
  ASSERT_EQ(st.position(), 1u);

  press(262);  // →
  run_frame(host, f);
  release();
  EXPECT_EQ(st.position(), 2u);
  press(263);  // ←
  run_frame(host, f);
  release();
  EXPECT_EQ(st.position(), 1u);
  press(262, true);  // Shift+→: the next phase, "contacts"
  run_frame(host, f);
  release();
  EXPECT_EQ(st.position(), 11u);
  EXPECT_STREQ(st.phases()[static_cast<std::size_t>(st.current_phase())].label, "contacts");

  // A push: the list C[5][7] = {4,2,1} drawn as two arrows, its cell outlined, the element ringed.
  st.seek(5);
  Recorder push;
  run_frame(host, f, &push);
  EXPECT_EQ(push.arrows.size(), 2u);
  EXPECT_GE(push.rects.size(), 1u);
  EXPECT_GE(push.lines.size(), 4u);
  EXPECT_GE(push.circles.size(), 1u);
  // A test in contact: the pair's segment and its verdict.
  st.seek(20);
  Recorder test;
  run_frame(host, f, &test);
  EXPECT_TRUE(test.has_text("contact"));

  // Space plays at the chosen speed; the frames' time moves it on.
  st.set_speed(600);  // 10 events per 1/60 s frame
  press(32);
  run_frame(host, f);
  release();
  EXPECT_TRUE(st.playing());
  run_frame(host, f);
  run_frame(host, f);
  EXPECT_GT(st.position(), 20u);
}

// The current operation's element wears a ring of its own colour, never the selection's white, so
// the selected element and the element being pushed or tested are told apart.
TEST(StepperScene, TheCurrentElementsRingIsNotTheSelections) {
  BookFrame f;
  StepperSession s;
  s.update(f.traced(), 0, 1);
  ASSERT_TRUE(s.has_capture()) << s.message();
  for (const std::size_t op : {std::size_t{5}, std::size_t{20}}) {  // a push, a test
    s.stepper().seek(op);
    Recorder r;
    draw_stepper_scene(s, r);
    const auto count = [&](render::Rgba c) {
      return std::count_if(r.circles.begin(), r.circles.end(), [&](const Recorder::Circle& circle) { return circle.outline == c; });
    };
    EXPECT_GE(count(render::palette::kOperation), 1) << "operation " << op;
    EXPECT_EQ(count(render::palette::kSelection), 0) << "operation " << op << ": the selection's white ring";
  }
}

// Screen's C[ix][iy] is drawn as the scene shows its cells (ix across, iy upwards); NBS's B[2][nx]
// keeps the current row over the row below, and the tree's child[m][2] one row per child.
TEST(StepperArrays, OnlyACellMatrixIsDrawnAsTheScene) {
  BookFrame f;
  f.sim.algorithm = "screen";
  StepperSession s;
  s.update(f.traced(), 0, 1);
  ASSERT_TRUE(s.has_capture()) << s.message();
  const TracedArray& c = s.stepper().trace().arrays()[0];
  ASSERT_EQ(c.name, "C");
  EXPECT_TRUE(is_cell_matrix(c, s.grid()));
  EXPECT_FALSE(is_cell_matrix(c, nullptr));
  EXPECT_FALSE(is_cell_matrix(TracedArray{"B", {2, 10}, {}}, s.grid()));
  EXPECT_FALSE(is_cell_matrix(TracedArray{"child", {10, 2}, {}}, s.grid()));
  EXPECT_FALSE(is_cell_matrix(TracedArray{"E", {9}, {}}, s.grid()));
}

// Digits past the algorithms offered say so in the Algorithm panel (they did nothing, silently).
TEST(AlgorithmKeys, ADigitWithNoAlgorithmSaysSo) {
  ImGuiScope scope;
  UiHost host;
  BookFrame f;
  f.sim.algorithms = {"brute", "tree", "sort", "screen", "nbs", "box2d"};
  testui::press('7');
  testui::run_frame(host, f);
  testui::release();
  EXPECT_FALSE(f.requests.algorithm.has_value());
  EXPECT_EQ(f.state.algorithm_key_note, "key 7: no algorithm 7 here; keys 1..6 choose those above");
  testui::run_frame(host, f);
  testui::press('2');
  testui::run_frame(host, f);
  testui::release();
  EXPECT_EQ(f.requests.algorithm, std::optional<std::string>("tree"));
  EXPECT_TRUE(f.state.algorithm_key_note.empty());
}

// At operation 0 a detector that builds lists has built none yet; one without lists builds none.
TEST(OverlaysPanel, EmptyListsSayWhetherTheyAreToComeOrNeverAre) {
  EXPECT_EQ(no_lists_note("nbs"), "nbs has built no lists yet");
  EXPECT_EQ(no_lists_note("screen"), "screen has built no lists yet");
  EXPECT_EQ(no_lists_note("brute"), "brute builds no lists");
  EXPECT_EQ(no_lists_note("recorded"), "recorded builds no lists");
}

}  // namespace
}  // namespace nbscope::ui

// The host's columns in the debugging loop: choosing a violation or clicking an element collapses
// no panel and moves none that was there; a collapsed panel opens with one click on its title bar;
// the panels are opaque over the scene.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include "support/ui_fixture.hpp"
#include "ui/panels.hpp"

namespace nbscope::ui {
namespace {

using testui::BookFrame;
using testui::ImGuiScope;
using testui::run_frame;

constexpr const char* kSelectionTitle = "Selection";

const ImGuiWindow* window(const char* title) { return ImGui::FindWindowByName(title); }

// A frame whose check failed with eight violations (the Stats panel lists six and "+2 more"), the
// detector's cells the true ones.
void fail_check(BookFrame& f) {
  FrameReport& report = f.result.lanes.front().report;
  report.checked = true;
  report.reference = "brute";
  report.violations.clear();
  for (int k = 0; k < 8; ++k) {
    Violation v{0, Invariant::AEqualsR, Pair{k, k + 1}, {}, {}, "missing from A"};
    const auto cells = grid_cells(f.sim, v);  // the detector's cells right: one line each
    v.cell_i = (*cells)[0];
    v.cell_j = (*cells)[1];
    report.violations.push_back(v);
  }
  report.broken = {8, 0, 0, 0};
}

void frames(UiHost& host, BookFrame& f, int n) {
  for (int k = 0; k < n; ++k) run_frame(host, f);
}

// A short display: a failed check's Stats panel (about 500 px) fits in the right column, but not
// with the Selection panel (about 130 px) under it.
constexpr float kShortHeight = 600;
struct ShortDisplay {
  ImGuiScope scope;
  ShortDisplay() { ImGui::GetIO().DisplaySize = ImVec2(1280, kShortHeight); }
};

TEST(PanelLayout, ClickingAnElementCollapsesNothingAndMovesNothing) {
  ShortDisplay display;
  UiHost host;
  BookFrame f;
  fail_check(f);
  frames(host, f, 6);
  const ImGuiWindow* stats = window(kStatsTitle);
  ASSERT_NE(stats, nullptr);
  ASSERT_FALSE(stats->Collapsed);
  const ImVec2 at = stats->Pos;
  f.state.selected = 0;  // as a click on element 0 selects it: the Selection panel comes
  frames(host, f, 6);
  EXPECT_FALSE(stats->Collapsed) << "the Selection panel's coming collapsed Stats";
  EXPECT_EQ(stats->Pos.y, at.y);
  const ImGuiWindow* selection = window(kSelectionTitle);
  ASSERT_NE(selection, nullptr);
  EXPECT_FALSE(selection->Collapsed);
  EXPECT_LE(selection->Pos.y + selection->Size.y, kShortHeight) << "the Selection panel takes the room left, and scrolls";
}

TEST(PanelLayout, ChoosingAViolationCollapsesNothing) {
  ShortDisplay display;
  UiHost host;
  BookFrame f;
  f.state.selected = 0;
  frames(host, f, 6);
  const ImGuiWindow* stats = window(kStatsTitle);
  const ImGuiWindow* selection = window(kSelectionTitle);
  ASSERT_NE(stats, nullptr);
  ASSERT_NE(selection, nullptr);
  ASSERT_FALSE(stats->Collapsed);
  ASSERT_FALSE(selection->Collapsed);
  // The violation's frame is shown, its elements selected: Stats now lists the failed check.
  fail_check(f);
  f.state.selected_pair = Pair{0, 1};
  frames(host, f, 6);
  EXPECT_FALSE(stats->Collapsed) << "Stats grew with the violations and was collapsed";
  EXPECT_FALSE(selection->Collapsed);
  EXPECT_LE(stats->Pos.y + stats->Size.y, kShortHeight);
}

// ImGui itself opens a collapsed window with its arrow or a double-click; one click on the title
// bar does it here too.
TEST(PanelLayout, ACollapsedPanelOpensWithOneClickOnItsTitleBar) {
  ImGuiScope scope;
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(1280, 300);  // the left column cannot hold its panels: the host collapses some
  UiHost host;
  BookFrame f;
  frames(host, f, 6);
  const ImGuiWindow* collapsed = nullptr;
  for (const auto& p : host.panels()) {
    const ImGuiWindow* w = window(p->title());
    if (w != nullptr && w->Active && w->Collapsed && collapsed == nullptr) collapsed = w;
  }
  ASSERT_NE(collapsed, nullptr) << "nothing collapsed in a 300 px display";
  io.MousePos = ImVec2(collapsed->Pos.x + collapsed->Size.x * 0.5f, collapsed->Pos.y + collapsed->TitleBarHeight() * 0.5f);
  run_frame(host, f);
  io.MouseDown[0] = true;
  run_frame(host, f);
  io.MouseDown[0] = false;
  frames(host, f, 3);
  EXPECT_FALSE(collapsed->Collapsed) << collapsed->Name << " stayed collapsed after a click on its title bar";
}

// A Stats line's cells are the detector's; where the grid's differ (off-by-one-cell), a line more gives them.
TEST(PanelLayout, StatsAddsTheTrueCellsWhereTheDetectorsDiffer) {
  ImGuiScope scope;
  UiHost host;
  BookFrame f;
  fail_check(f);
  frames(host, f, 4);
  const ImGuiWindow* stats = window(kStatsTitle);
  ASSERT_NE(stats, nullptr);
  const float right = stats->Size.y;
  ++f.result.lanes.front().report.violations[0].cell_i.ix;  // the detector put element 0 one cell right
  frames(host, f, 4);
  EXPECT_GE(stats->Size.y, right + ImGui::GetTextLineHeight()) << "no line for the true cells";
}

// The panels cover the scene: their background is opaque (the scene's lines never show through).
TEST(PanelLayout, PanelsAreOpaque) {
  ImGuiScope scope;
  UiHost host;
  BookFrame f;
  frames(host, f, 3);
  const ImGuiWindow* stats = window(kStatsTitle);
  ASSERT_NE(stats, nullptr);
  ASSERT_FALSE(stats->DrawList->VtxBuffer.empty());
  // The window's background is the first shape of its draw list.
  const ImU32 background = stats->DrawList->VtxBuffer[0].col;
  EXPECT_EQ((background >> IM_COL32_A_SHIFT) & 0xFF, 0xFFu);
}

}  // namespace
}  // namespace nbscope::ui

// The stepping layout (issue 38, "Room to teach"): with Stepper, Arrays and Pseudocode open on the
// book's Fig. 3.15 under `screen` at operation 10, the scene keeps at least half the window and C
// and E are both whole in the Arrays panel's visible region without scrolling, at 1280x720 and 1600x1000.
// The share is measured from the host's own insets: the free scene rectangle (the display less the
// menu bar, the columns and the bottom dock) over the display.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <cstdio>
#include <deque>

#include "support/ui_fixture.hpp"
#include "ui/panels.hpp"
#include "ui/stepper_panels.hpp"

namespace nbscope::ui {
namespace {

using testui::BookFrame;
using testui::ImGuiScope;
using testui::run_frame;

// The share of the display the panels leave to the scene: the rectangle inside the insets.
double scene_share(const render::ScreenInsets& in, ImVec2 display) {
  const double w = display.x - in.left - in.right, h = display.y - in.top - in.bottom;
  return w > 0 && h > 0 ? w * h / (static_cast<double>(display.x) * display.y) : 0.0;
}

// The table the Arrays panel draws array `index` named `name` in (PushID(index), BeginTable(name)
// at the top of its window), or null.
const ImGuiTable* array_table(const ImGuiWindow& arrays, int index, const char* name) {
  const ImGuiID seed = ImHashData(&index, sizeof index, arrays.ID);
  return ImGui::TableFindByID(ImHashStr(name, 0, seed));
}

struct SteppingCase {
  ImVec2 display;
};

class SteppingLayout : public testing::TestWithParam<SteppingCase> {};

TEST_P(SteppingLayout, TheSceneKeepsHalfTheWindowAndCAndEAreOnScreen) {
  ImGuiScope scope;
  const ImVec2 display = GetParam().display;
  ImGui::GetIO().DisplaySize = display;
  UiHost host;
  auto session = add_stepper_panels(host, StepperConfig{std::size_t{10}, true});
  BookFrame f;
  const std::deque<FrameSummary> timeline(1);  // the run's one frame: the Timeline shows, as in the window
  f.sim.timeline = &timeline;
  f.camera.set_viewport(static_cast<int>(display.x), static_cast<int>(display.y));
  f.state.book_numbering = true;
  open_stepper_panels(f.state);
  // As the golden stepper_screen_step10 opens them: --panels -scenes,-overlays.
  f.state.panel_open["Scenes"] = false;
  f.state.panel_open["Overlays"] = false;
  for (int i = 0; i < 8; ++i) run_frame(host, f);
  ASSERT_TRUE(session->has_capture()) << session->message();
  ASSERT_EQ(session->stepper().position(), 10u);

  const render::ScreenInsets in = host.insets(f.state);
  const double share = scene_share(in, display);
  std::printf("%gx%g: insets left %g right %g top %g bottom %g, scene %gx%g = %.3f of the window\n", display.x, display.y,
              in.left, in.right, in.top, in.bottom, display.x - in.left - in.right, display.y - in.top - in.bottom, share);
  EXPECT_GE(share, 0.5);

  const ImGuiWindow* arrays = ImGui::FindWindowByName(kArraysTitle);
  ASSERT_NE(arrays, nullptr);
  ASSERT_TRUE(arrays->Active);
  ASSERT_FALSE(arrays->Collapsed);
  EXPECT_EQ(arrays->ScrollMax.y, 0.0f) << "the Arrays panel scrolls";
  const ImRect visible = arrays->InnerClipRect;
  const auto& names = session->stepper().trace().arrays();
  ASSERT_GE(names.size(), 2u);
  for (int a = 0; a < 2; ++a) {
    const ImGuiTable* t = array_table(*arrays, a, names[static_cast<std::size_t>(a)].name.c_str());
    ASSERT_NE(t, nullptr) << names[static_cast<std::size_t>(a)].name;
    const ImRect drawn(t->OuterRect.Min, ImVec2(t->OuterRect.Max.x, t->RowPosY2));
    std::printf("  %s rows %g..%g x %g..%g, visible %g..%g x %g..%g\n", names[static_cast<std::size_t>(a)].name.c_str(),
                drawn.Min.y, drawn.Max.y, drawn.Min.x, drawn.Max.x, visible.Min.y, visible.Max.y, visible.Min.x,
                visible.Max.x);
    EXPECT_TRUE(visible.Contains(drawn)) << names[static_cast<std::size_t>(a)].name << " is not all in the panel's visible region";
    EXPECT_LE(drawn.Max.y, display.y);
  }
  // Whole, not windowed: C's header row and its ten rows iy; E's label and its nine entries.
  EXPECT_EQ(array_table(*arrays, 0, "C")->CurrentRow + 1, 11);
  EXPECT_EQ(array_table(*arrays, 1, "E")->ColumnsCount, 10);
}

INSTANTIATE_TEST_SUITE_P(Displays, SteppingLayout,
                         testing::Values(SteppingCase{ImVec2(1280, 720)}, SteppingCase{ImVec2(1600, 1000)}),
                         [](const testing::TestParamInfo<SteppingCase>& info) {
                           return std::to_string(static_cast<int>(info.param.display.x)) + "x" +
                                  std::to_string(static_cast<int>(info.param.display.y));
                         });

}  // namespace
}  // namespace nbscope::ui

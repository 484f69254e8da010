// The stepping layout (issue 38, "Room to teach"): with Stepper, Arrays and Pseudocode open, the
// scene keeps at least half the window, every array of the current phase is whole in the Arrays
// panel's visible region without scrolling, and Pseudocode is open (not collapsed to its title bar),
// at 1280x720 and 1600x1000. Three cases: the book's Fig. 3.15 under `screen` at operation 10 (C and E);
// the same nine under `nbs` with element 3 (the book's 4) selected, in the contacts of a row (y_heads,
// Y, B, X and the element section); and NBS 3D on LIGGGHTS's pour at operation 14000, the contacts of
// row 4 of layer 1 (C, Z, B, Y, A, X). In a row's phase every array is the phase's: the operation
// tests against the x-lists (A, X) of the row's element, walked from its row's y-list (B, Y), of its
// layer's z-list (C, Z) — the lists the Arrays panel marks as the operation's.
// The share is measured from the host's own insets: the free scene rectangle (the display less the
// menu bar, the columns and the bottom dock) over the display.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <cstdio>
#include <deque>
#include <string>

#include "core/layers.hpp"
#include "io/lammps_dump.hpp"
#include "support/ui3d_fixture.hpp"
#include "support/ui_fixture.hpp"
#include "ui/panels.hpp"
#include "ui/stepper_panels.hpp"

namespace nbscope::ui {
namespace {

using testui::BookFrame;
using testui::Frame3d;
using testui::ImGuiScope;
using testui::run_frame;

// The share of the display the panels leave to the scene: the rectangle inside the insets.
double scene_share(const render::ScreenInsets& in, ImVec2 display) {
  const double w = display.x - in.left - in.right, h = display.y - in.top - in.bottom;
  return w > 0 && h > 0 ? w * h / (static_cast<double>(display.x) * display.y) : 0.0;
}

// The table the Arrays panel draws array `index` named `name` in (PushID(index), BeginTable(name)
// in its window, or in the first column of its "##layout" table beside the element), or null.
const ImGuiTable* array_table(const ImGuiWindow& arrays, int index, const char* name) {
  for (const ImGuiID parent : {arrays.ID, ImHashStr("##layout", 0, arrays.ID)}) {
    const ImGuiID seed = ImHashData(&index, sizeof index, parent);
    if (const ImGuiTable* t = ImGui::TableFindByID(ImHashStr(name, 0, seed))) return t;
  }
  return nullptr;
}

// LIGGGHTS's pour (assets/examples/pour3d, 1,000 spheres, 7 x 7 cells in 6 layers) at timestep
// 7500, as `replay --dump` shows it: the grid fitted to it, the busiest layer.
Elements pour_frame() {
  return read_dump_frames({std::string(NBSCOPE_SOURCE_DIR) + "/assets/examples/pour3d/atoms.7500.dump"}, {}).front().elements;
}

enum class Case { ScreenStep10, NbsSelected, Nbs3dPour };

struct SteppingCase {
  Case what;
  ImVec2 display;
};

// What the layout left: the scene's share, and whether each array of the trace is whole in the
// Arrays panel's visible region (its name, when not).
struct Measured {
  double share = 0;
  std::vector<std::string> cut;
};

// Opens the stepping layout on `f` (Stepper, Arrays and Pseudocode; Scenes and Overlays closed, as
// the goldens open them) at `display`, stepped to `step`, and measures it.
template <class TestFrame>
Measured lay_out(UiHost& host, StepperSession& session, TestFrame& f, ImVec2 display, std::size_t step) {
  const std::deque<FrameSummary> timeline(1);  // the run's one frame: the Timeline shows, as in the window
  f.sim.timeline = &timeline;
  f.camera.set_viewport(static_cast<int>(display.x), static_cast<int>(display.y));
  open_stepper_panels(f.state);
  f.state.panel_open["Scenes"] = false;
  f.state.panel_open["Overlays"] = false;
  for (int i = 0; i < 8; ++i) run_frame(host, f);
  EXPECT_TRUE(session.has_capture()) << session.message();
  EXPECT_EQ(session.stepper().position(), step);

  Measured m;
  const render::ScreenInsets in = host.insets(f.state);
  m.share = scene_share(in, display);
  std::printf("%gx%g: insets left %g right %g top %g bottom %g, scene %gx%g = %.3f of the window\n", display.x, display.y,
              in.left, in.right, in.top, in.bottom, display.x - in.left - in.right, display.y - in.top - in.bottom, m.share);
  const ImGuiWindow* arrays = ImGui::FindWindowByName(kArraysTitle);
  if (arrays == nullptr || !arrays->Active || arrays->Collapsed) {
    m.cut.emplace_back("(the Arrays panel is not open)");
    return m;
  }
  EXPECT_EQ(arrays->ScrollMax.y, 0.0f) << "the Arrays panel scrolls";
  const ImRect visible = arrays->InnerClipRect;
  const auto& names = session.stepper().trace().arrays();
  for (std::size_t a = 0; a < names.size(); ++a) {
    const ImGuiTable* t = array_table(*arrays, static_cast<int>(a), names[a].name.c_str());
    if (t == nullptr) {
      m.cut.push_back(names[a].name + " (not drawn)");
      continue;
    }
    const ImRect drawn(t->OuterRect.Min, ImVec2(t->OuterRect.Max.x, t->RowPosY2));
    std::printf("  %s rows %g..%g x %g..%g, visible %g..%g x %g..%g\n", names[a].name.c_str(), drawn.Min.y, drawn.Max.y,
                drawn.Min.x, drawn.Max.x, visible.Min.y, visible.Max.y, visible.Min.x, visible.Max.x);
    if (!visible.Contains(drawn) || drawn.Max.y > display.y) m.cut.push_back(names[a].name);
  }
  return m;
}

// Pseudocode's window in the last frame: open, and more than its title bar.
void expect_pseudocode_open() {
  const ImGuiWindow* pseudocode = ImGui::FindWindowByName(kPseudocodeTitle);
  ASSERT_NE(pseudocode, nullptr);
  std::printf("  Pseudocode %gx%g%s\n", pseudocode->Size.x, pseudocode->Size.y, pseudocode->Collapsed ? " (collapsed)" : "");
  EXPECT_TRUE(pseudocode->Active);
  EXPECT_FALSE(pseudocode->Collapsed) << "Pseudocode is collapsed to its title bar";
  EXPECT_GE(pseudocode->Size.y, 8 * ImGui::GetTextLineHeightWithSpacing()) << "Pseudocode shows too few lines";
}

std::string case_name(const SteppingCase& c) {
  const char* const names[] = {"ScreenStep10", "NbsSelected", "Nbs3dPour"};
  return std::string(names[static_cast<int>(c.what)]) + "_" + std::to_string(static_cast<int>(c.display.x)) + "x" +
         std::to_string(static_cast<int>(c.display.y));
}

class SteppingLayout : public testing::TestWithParam<SteppingCase> {};

TEST_P(SteppingLayout, TheSceneKeepsHalfTheWindowAndThePhasesArraysAreOnScreen) {
  ImGuiScope scope;
  const auto [what, display] = GetParam();
  ImGui::GetIO().DisplaySize = display;
  UiHost host;
  const std::size_t step = what == Case::Nbs3dPour ? 14000 : what == Case::NbsSelected ? 10 : 10;
  auto session = add_stepper_panels(host, StepperConfig{step, true});
  Measured m;
  if (what == Case::Nbs3dPour) {
    Frame3d f(pour_frame(), "atoms.7500");
    m = lay_out(host, *session, f, display, step);
    ASSERT_EQ(session->stepper().trace().arrays().size(), 6u);
    EXPECT_EQ(phase_text(*session, static_cast<std::size_t>(session->stepper().current_phase())), "contacts of row 4, layer 1");
  } else {
    BookFrame f;
    f.state.book_numbering = true;
    if (what == Case::NbsSelected) {
      f.sim.algorithm = "nbs";
      f.state.selected = 3;
    }
    m = lay_out(host, *session, f, display, step);
    if (what == Case::ScreenStep10) {
      // Whole, not windowed: C's header row and its ten rows iy; E's label and its nine entries.
      const ImGuiWindow* arrays = ImGui::FindWindowByName(kArraysTitle);
      ASSERT_NE(arrays, nullptr);
      EXPECT_EQ(array_table(*arrays, 0, "C")->CurrentRow + 1, 11);
      EXPECT_EQ(array_table(*arrays, 1, "E")->ColumnsCount, 10);
    } else {
      EXPECT_EQ(session->focus_element, 3);
      EXPECT_EQ(session->stepper().trace().arrays().size(), 4u);
    }
  }
  EXPECT_GE(m.share, 0.5);
  for (const std::string& name : m.cut) ADD_FAILURE() << name << " is not all in the Arrays panel's visible region";
  expect_pseudocode_open();
}

INSTANTIATE_TEST_SUITE_P(Displays, SteppingLayout,
                         testing::Values(SteppingCase{Case::ScreenStep10, ImVec2(1280, 720)},
                                         SteppingCase{Case::ScreenStep10, ImVec2(1600, 1000)},
                                         SteppingCase{Case::NbsSelected, ImVec2(1280, 720)},
                                         SteppingCase{Case::NbsSelected, ImVec2(1600, 1000)},
                                         SteppingCase{Case::Nbs3dPour, ImVec2(1280, 720)},
                                         SteppingCase{Case::Nbs3dPour, ImVec2(1600, 1000)}),
                         [](const testing::TestParamInfo<SteppingCase>& info) { return case_name(info.param); });

}  // namespace
}  // namespace nbscope::ui

// The Layers panel of a 3D frame without GL (book p.123: NBS works layer by layer): its Up/Down keys
// and side view set UiState::layer; its z-lists are the trace's C and Z (at the stepper's operation)
// or the book's push-front build; the stepper's current layer follows the trace; the side view's
// axis in the settings, the layer keys in Help. The other panels on 3D frames: test_panels_3d.cpp.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <memory>
#include <random>
#include <string>

#include "core/detector.hpp"
#include "core/layers.hpp"
#include "core/lists.hpp"
#include "core/traced_lists.hpp"
#include "support/ui3d_fixture.hpp"
#include "ui/layer_lists.hpp"
#include "ui/settings_json.hpp"
#include "ui/panels.hpp"
#include "ui/stepper_panels.hpp"

namespace nbscope::ui {
namespace {

using testui::Frame3d;
using testui::kDownKey;
using testui::kUpKey;
using testui::panel_text;
using testui::Recorder;
using testui::run_frame;
using testui::Scope3d;

// The side view's rectangle in the Layers window: where its dark background was drawn.
std::optional<std::pair<ImVec2, ImVec2>> side_view_rect() {
  const ImGuiWindow* w = ImGui::FindWindowByName(kLayersTitle);
  if (w == nullptr || w->DrawList == nullptr) return std::nullopt;
  const ImU32 background = IM_COL32(24, 26, 31, 255);  // panel_layers.cpp's side view background
  ImVec2 lo(1e9f, 1e9f), hi(-1e9f, -1e9f);
  for (const ImDrawVert& v : w->DrawList->VtxBuffer) {
    if (v.col != background) continue;
    lo = ImVec2(std::min(lo.x, v.pos.x), std::min(lo.y, v.pos.y));
    hi = ImVec2(std::max(hi.x, v.pos.x), std::max(hi.y, v.pos.y));
  }
  if (lo.x >= hi.x) return std::nullopt;
  return std::make_pair(lo, hi);
}

TEST(LayersPanel, KeysAndTheSideViewChooseTheLayer) {
  Scope3d scope;
  UiHost host;
  add_stepper_panels(host);
  Frame3d f;
  ASSERT_GE(f.slice.count, 4);
  run_frame(host, f);
  EXPECT_TRUE(ImGui::FindWindowByName(kLayersTitle)->Active) << "open by default on a 3D frame";
  std::string text = panel_text(host, f, kLayersTitle);
  EXPECT_NE(text.find("of " + std::to_string(f.slice.count) + ", z from"), std::string::npos) << text;
  const std::int32_t start = f.slice.layer;
  // Up: the layer above, Down twice: below it (each key a frame of its own, as the window gives them).
  const auto tap = [&](int key) {
    testui::press(key);
    run_frame(host, f);
    testui::release();
    f.follow_choice();
    run_frame(host, f);
  };
  tap(start + 1 < f.slice.count ? kUpKey : kDownKey);
  ASSERT_TRUE(f.state.layer.has_value());
  const std::int32_t after_first = *f.state.layer;
  EXPECT_EQ(after_first, start + 1 < f.slice.count ? start + 1 : start - 1);
  tap(kDownKey);
  EXPECT_EQ(*f.state.layer, after_first - 1);
  // Past the top the layer stays the top one.
  for (int i = 0; i < f.slice.count + 2; ++i) tap(kUpKey);
  EXPECT_EQ(*f.state.layer, f.slice.count - 1);

  // A press in the side view's top row picks the top layer; dragged to its bottom row, layer 0.
  const auto rect = side_view_rect();
  ASSERT_TRUE(rect.has_value());
  f.state.layer = 1;
  f.follow_choice();
  ImGuiIO& io = ImGui::GetIO();
  const float mid_x = 0.5f * (rect->first.x + rect->second.x);
  io.MousePos = ImVec2(mid_x, rect->first.y + 2);
  run_frame(host, f);  // hovered first
  io.MouseDown[0] = true;
  run_frame(host, f);
  EXPECT_EQ(f.state.layer, f.slice.count - 1);
  io.MousePos = ImVec2(mid_x, rect->second.y - 2);
  run_frame(host, f);
  EXPECT_EQ(f.state.layer, 0);
  io.MouseDown[0] = false;
  io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
  run_frame(host, f);

  // The selected element is ringed in the side view, whichever layer it is in.
  const auto ringed = [] {
    const ImGuiWindow* w = ImGui::FindWindowByName(kLayersTitle);
    for (const ImDrawVert& v : w->DrawList->VtxBuffer)
      if (v.col == IM_COL32(255, 255, 255, 235)) return true;  // panel_layers.cpp's ring
    return false;
  };
  EXPECT_FALSE(ringed());
  f.state.selected = 0;
  run_frame(host, f);
  EXPECT_TRUE(ringed());
  f.state.selected = -1;

  // The y-z toggle is the state the app reads; a 2D frame hides the panel and takes no arrow key.
  EXPECT_FALSE(f.state.side_view_yz);
  f.sim.layer = nullptr;
  f.state.layer.reset();
  run_frame(host, f);
  run_frame(host, f);
  EXPECT_EQ(ImGui::FindWindowByName(kLayersTitle)->Active, false);
  testui::press(kUpKey);
  run_frame(host, f);
  testui::release();
  EXPECT_FALSE(f.state.layer.has_value());
}

// The side view of 10,000 spheres bins them: a few thousand quads at most, never one disc per element.
TEST(LayersPanel, TheSideViewOfTenThousandSpheresStaysSmall) {
  Scope3d scope;
  UiHost host;
  add_stepper_panels(host);
  Frame3d f(10'000);
  f.sim.paused = false;  // running: nothing traced
  f.sim.algorithm = "brute";
  run_frame(host, f);
  const ImGuiWindow* w = ImGui::FindWindowByName(kLayersTitle);
  ASSERT_NE(w, nullptr);
  EXPECT_LT(w->DrawList->VtxBuffer.Size, 40'000) << "10,000 discs of 8 segments would be 90,000 vertices";
  EXPECT_GT(w->DrawList->VtxBuffer.Size, 400) << "the density image is drawn";
}

// The z-lists shown are the trace's C and Z at the stepper's operation (as the Arrays panel has
// them), and the finished ones are the book's push-front build from the layers.
TEST(LayersPanel, ZListsAreTheTracesCAndZAtTheStepperOperation) {
  Scope3d scope;
  UiHost host;
  auto session = add_stepper_panels(host);
  Frame3d f;
  open_stepper_panels(f.state);
  run_frame(host, f);
  ASSERT_TRUE(session->has_capture()) << session->message();
  Stepper& st = session->stepper();
  const int c = st.array_id("C");
  ASSERT_GE(c, 0);
  // Mid-way through the z-list pushes, and later mid-way through the layers.
  for (const std::size_t p : {std::size_t{40}, st.size() / 2}) {
    st.seek(p);
    const auto z = zlists_from_state(st.trace(), st.state());
    ASSERT_TRUE(z.has_value());
    for (std::int32_t iz = 0; iz < f.slice.count; ++iz) {
      EXPECT_EQ(z->heads[static_cast<std::size_t>(iz)], st.state()[static_cast<std::size_t>(c)][static_cast<std::size_t>(iz)]);
      EXPECT_EQ(z->chains[static_cast<std::size_t>(iz)], st.list_members(c, iz)) << "layer " << iz << " at " << p;
    }
    const std::string text = panel_text(host, f, kLayersTitle);
    EXPECT_NE(text.find("z-lists at operation " + std::to_string(p) + " of " + std::to_string(st.size())), std::string::npos) << text;
    const std::string chain = zlist_text(*z, f.slice.layer, false);
    EXPECT_NE(text.find(chain.substr(chain.find(": ") + 2)), std::string::npos) << chain << "\n" << text;
  }
  // Operation 40 is within the first loop: not every element is on a z-list yet.
  st.seek(40);
  std::size_t listed = 0;
  const ZLists early = *zlists_from_state(st.trace(), st.state());
  for (const auto& chain : early.chains) listed += chain.size();
  EXPECT_EQ(listed, 39u) << "the first phase, then one push per operation";

  const auto finished = zlists_from_trace(f.sim.trace->log);
  ASSERT_TRUE(finished.has_value());
  const ZLists book = zlists_from_layers(f.slice);
  EXPECT_EQ(finished->heads, book.heads);
  EXPECT_EQ(finished->chains, book.chains);
  // The book's loop pushes k = 0..N-1 at the front: each list runs from its highest index down.
  for (const auto& chain : book.chains) EXPECT_TRUE(std::is_sorted(chain.rbegin(), chain.rend()));
  // Without an NBS trace the panel says it built them itself.
  f.sim.algorithm = "brute";
  f.sim.trace.reset();
  f.sim.paused = false;
  run_frame(host, f);
  EXPECT_NE(panel_text(host, f, kLayersTitle).find("as the book's first loop builds them"), std::string::npos);
  EXPECT_EQ(zlist_text(book, 0, true, 2).rfind("C[1] = " + std::to_string(book.heads[0] + 1) + ": ", 0), 0u);
  EXPECT_NE(zlist_text(book, 0, false, 2).find(" -> ..."), std::string::npos);
}

// One numbering across panels: on a dump's frame (rows carry atom ids) the z-lists name rows, in
// the book's numbering when chosen, as the Stepper and the Arrays do; atom ids are not in them.
TEST(LayersPanel, ZListsOfADumpAreRowsAsInTheStepperNotAtomIds) {
  Scope3d scope;
  UiHost host;
  auto session = add_stepper_panels(host);
  Frame3d f;
  auto ids = std::make_shared<std::vector<std::int64_t>>();
  for (std::int64_t k = 0; k < f.elements.size(); ++k) ids->push_back(5000 + 7 * k);  // no atom id is a row
  f.result.ids = ids;
  f.state.book_numbering = true;
  open_stepper_panels(f.state);
  run_frame(host, f);
  ASSERT_TRUE(session->has_capture()) << session->message();
  Stepper& st = session->stepper();
  st.seek(40);  // in the first loop: element k pushed onto the z-list of its layer, C[iz] = k
  const TraceEvent& push = *st.current();
  const auto layer = session->current_layer();
  ASSERT_TRUE(layer.has_value());
  f.slice = slice_layer(f.elements, f.grid(), *layer);  // the view follows the stepper's layer, as the window's does
  const std::string head = "C[" + std::to_string(*layer + 1) + "] = " + std::to_string(push.element + 1);
  EXPECT_NE(describe_event(*session, push).find(head), std::string::npos) << head << " in " << describe_event(*session, push);
  const std::string text = panel_text(host, f, kLayersTitle);
  EXPECT_NE(text.find(head), std::string::npos) << head << " in\n" << text;
  EXPECT_NE(text.find("rows, as in Arrays"), std::string::npos) << text;
  EXPECT_EQ(text.find("= 5"), std::string::npos) << "an atom id in the z-lists:\n" << text;
}

// The stepper's layer and row, for the view to follow: nothing before the first operation or in
// 2D; in the first loop the pushed element's layer; then the layer whose pass it is (the phase
// "y-lists of layer iz" and every row phase after it) and the row of "x-lists of row iy".
TEST(StepperLayer, CurrentLayerAndRowFollowTheTrace) {
  Frame3d f;
  StepperSession s;
  s.capture(f.traced());
  ASSERT_TRUE(s.has_capture()) << s.message();
  Stepper& st = s.stepper();
  EXPECT_FALSE(s.current_layer().has_value());
  std::int32_t pass = -1, row = -1;
  std::size_t checked_rows = 0;
  for (std::size_t p = 1; p <= st.size(); ++p) {
    st.seek(p);
    const TraceEvent& e = *st.current();
    const PhaseMark& phase = st.phases()[static_cast<std::size_t>(st.current_phase())];
    const std::string label = phase.label;
    if (label == phase_label::kYListsOfLayer) pass = phase.index;
    if (label == phase_label::kXListsOfRow) row = phase.index;
    if (label == phase_label::kZLists) {
      if (e.op == TraceOp::Push)
        EXPECT_EQ(s.current_layer(), f.slice.element_layer[static_cast<std::size_t>(e.element)]) << "operation " << p;
      else
        EXPECT_FALSE(s.current_layer().has_value()) << "operation " << p;
    } else if (label != phase_label::kClearZLists) {
      ASSERT_GE(pass, 0);
      EXPECT_EQ(s.current_layer(), pass) << "operation " << p << " (" << label << ")";
    }
    if (label == phase_label::kXListsOfRow || label == phase_label::kContactsOfRow) {
      EXPECT_EQ(s.current_row(), row) << "operation " << p;
      ++checked_rows;
    }
  }
  EXPECT_GT(checked_rows, 100u);
  // The Stepper's phase list names a row's layer too (row 4 of which layer?).
  for (std::size_t i = 0; i < st.phases().size(); ++i) {
    const std::string name = phase_text(s, i);
    const TraceEvent& e = st.events()[st.phases()[i].event];
    if (std::string(st.phases()[i].label) == phase_label::kXListsOfRow) {
      EXPECT_EQ(name, "x-lists of row " + std::to_string(e.cell[1]) + ", layer " + std::to_string(e.cell[2]));
    }
    if (std::string(st.phases()[i].label) == phase_label::kYListsOfLayer) {
      EXPECT_EQ(name, "y-lists of layer " + std::to_string(e.cell[2]));
    }
  }
  // A 2D trace has no layer.
  testui::BookFrame book;
  book.sim.algorithm = "nbs";
  StepperSession flat;
  flat.capture(book.traced());
  flat.stepper().seek(flat.stepper().size() / 2);
  EXPECT_FALSE(flat.current_layer().has_value());
}

// The side view's axis persists in the settings file; a value that is not a boolean is named and
// keeps x-z.
TEST(SettingsJson, TheSideViewAxisRoundTripsAndAWrongValueIsNamed) {
  std::vector<std::string> ignored;
  SettingsValues v;
  v.side_view_yz = true;
  EXPECT_TRUE(parse_settings_json(settings_json_text(v), {}, ignored).side_view_yz);
  EXPECT_TRUE(ignored.empty());
  EXPECT_FALSE(parse_settings_json(R"({"version": 1, "side_view_yz": "yes"})", {}, ignored).side_view_yz);
  ASSERT_EQ(ignored.size(), 1u);
  EXPECT_EQ(ignored[0].rfind("side_view_yz", 0), 0u) << ignored[0];
}

// The Help menu names the layer keys beside the others.
TEST(HelpMenu, NamesTheLayerKeys) {
  std::string text;
  for (const char* line : help_lines()) text += std::string(line) + "\n";
  EXPECT_NE(text.find("Up / Down  the layer above / below"), std::string::npos) << text;
}

}  // namespace
}  // namespace nbscope::ui

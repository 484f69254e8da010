// The panels of a 3D frame without GL (book p.123: NBS works layer by layer): the Layers panel's
// Up/Down keys and side view set UiState::layer; its z-lists are the trace's C and Z (at
// the stepper's operation) or the book's push-front build; the Selection panel names an element's
// cell (ix, iy, iz), layer and list places; Arrays and Pseudocode show the 3D arrays and loops; the
// stepper's current layer follows the trace; its scene overlay leaves out the hidden layers.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <random>
#include <string>

#include "core/detector.hpp"
#include "core/layers.hpp"
#include "core/lists.hpp"
#include "core/traced_lists.hpp"
#include "support/ui_fixture.hpp"
#include "ui/layer_lists.hpp"
#include "ui/settings_json.hpp"
#include "ui/panels.hpp"
#include "ui/stepper_panels.hpp"

namespace nbscope::ui {
namespace {

using testui::ImGuiScope;
using testui::Recorder;

constexpr int kUpKey = 265, kDownKey = 264;  // GLFW's, as the window maps them

// A context with a tall display (no panel collapsed) and the arrow keys mapped as the window maps them.
struct Scope3d {
  ImGuiScope scope;
  Scope3d() {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(1600, 1600);
    io.KeyMap[ImGuiKey_UpArrow] = kUpKey;
    io.KeyMap[ImGuiKey_DownArrow] = kDownKey;
  }
};

// N random spheres in a 4 m cube, their grid, the layer view the app would hand the panels, and
// (traced()) the frame's trace by `algorithm` on that grid.
struct Frame3d {
  Elements elements;
  FrameResult result;
  LayerSlice slice;
  SimView sim;
  UiState state;
  UiRequests requests;
  render::Camera camera;
  explicit Frame3d(int n = 120, const char* algorithm = "nbs") {
    elements.dim = 3;
    std::mt19937 rng(25);
    std::uniform_real_distribution<double> at(0.0, 4.0), radius(0.2, 0.35);
    for (int k = 0; k < n; ++k) elements.push_back(at(rng), at(rng), at(rng), radius(rng));
    result.lanes.front().grid = make_grid(elements, GridOptions{});
    slice = slice_layer(elements, grid(), busiest_layer(slice_layer(elements, grid(), 0)));
    sim.scene_path = "random-3d";
    sim.elements = &elements;
    sim.frame = &result;
    sim.layer = &slice;
    sim.algorithm = algorithm;
    sim.paused = true;
    camera.set_viewport(1600, 1600);
    camera.set({2, 2}, 100.0);
  }
  const Grid& grid() const { return result.lanes.front().grid; }
  SimView& traced() {
    if (!sim.trace || sim.trace->algorithm != sim.algorithm) {
      DetectOptions o;
      o.grid.cell_size = grid().cell_size;
      o.grid.origin = std::array<double, 3>{grid().origin[0], grid().origin[1], grid().origin[2]};
      o.grid.cells = std::array<std::int64_t, 3>{grid().n[0], grid().n[1], grid().n[2]};
      sim.trace = trace_frame(*make_detector(sim.algorithm), elements, o, 0, grid());
    }
    return sim;
  }
  // What the app does between frames: the layer the user chose is the layer shown.
  void follow_choice() {
    if (state.layer) slice = slice_layer(elements, grid(), *state.layer);
  }
};

// Runs one UI frame of `host` (its keys and mouse included) and draws its scene overlay into `sink`.
void run_frame(UiHost& host, Frame3d& f, Recorder* sink = nullptr) {
  f.requests = {};
  f.traced();
  ImGui::NewFrame();
  UiContext ctx{f.sim, f.state, f.requests, f.camera};
  host.frame(ctx, true);
  if (sink != nullptr) host.draw_scene(ctx, *sink);
  ImGui::Render();
}

// Every text the panel titled `title` of `host` draws in one frame, in drawing order: the panel is
// drawn into a window of the test's own with ImGui's log on (which stops at the end of a window).
std::string panel_text(UiHost& host, Frame3d& f, const char* title) {
  Panel* panel = nullptr;
  for (const auto& p : host.panels())
    if (std::string(p->title()) == title) panel = p.get();
  if (panel == nullptr) return "(no panel " + std::string(title) + ")";
  f.requests = {};
  f.traced();
  ImGui::NewFrame();
  ImGui::SetNextWindowSize(ImVec2(700, 1500), ImGuiCond_Always);
  ImGui::Begin("##panel text", nullptr, ImGuiWindowFlags_NoSavedSettings);
  ImGui::LogToBuffer();
  UiContext ctx{f.sim, f.state, f.requests, f.camera};
  panel->draw(ctx);
  std::string text = GImGui->LogBuffer.c_str();
  ImGui::LogFinish();
  ImGui::End();
  ImGui::Render();
  return text;
}

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
    const std::string chain = zlist_text(*z, f.slice.layer, false, nullptr);
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
  EXPECT_EQ(zlist_text(book, 0, true, nullptr, 2).rfind("C[1] = " + std::to_string(book.heads[0] + 1) + ": ", 0), 0u);
  EXPECT_NE(zlist_text(book, 0, false, nullptr, 2).find(" -> ..."), std::string::npos);
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

// Selection on a 3D element: its cell (ix, iy, iz), row, layer against the one shown, and its place
// in each list of the frame's lists (the z-list C[iz], the y-list B[0][iy], the x-lists A[r][ix]).
TEST(SelectionPanel, NamesA3dElementsCellLayerAndListPlaces) {
  Scope3d scope;
  UiHost host;
  add_stepper_panels(host);
  Frame3d f;
  f.sim.paused = false;
  const std::vector<TracedList> lists = traced_lists(f.traced().trace->log, static_cast<std::size_t>(f.elements.size()));
  f.sim.lists = &lists;
  // An element of the layer below the one shown, at least second on its z-list.
  const ZLists z = zlists_from_layers(f.slice);
  ASSERT_GE(f.slice.below, 0);
  const auto& chain = z.chains[static_cast<std::size_t>(f.slice.below)];
  ASSERT_GE(chain.size(), 3u);
  const ElementId k = chain[1];
  f.state.selected = k;
  const Grid& g = f.grid();
  const std::int32_t ix = g.cell(f.elements.x[k], 0), iy = g.cell(f.elements.y[k], 1), iz = g.cell(f.elements.z[k], 2);
  ASSERT_EQ(iz, f.slice.below);
  run_frame(host, f);
  const std::string text = panel_text(host, f, "Selection");
  const auto has = [&](const std::string& what) { EXPECT_NE(text.find(what), std::string::npos) << what << "\n" << text; };
  has("cell (ix, iy, iz) = (" + std::to_string(ix) + ", " + std::to_string(iy) + ", " + std::to_string(iz) + ")");
  has("row (iy, iz) = (" + std::to_string(iy) + ", " + std::to_string(iz) + ")");
  has("in layer " + std::to_string(iz) + " (layer shown: " + std::to_string(f.slice.layer) + ")");
  has("z-list C[" + std::to_string(iz) + "]: position 2 of " + std::to_string(chain.size()));
  has("y-list B[0][" + std::to_string(iy) + "]: position");
  has("x-list A[0][" + std::to_string(ix) + "]: position");
  // With the lists overlay off, the frame's trace (paused: the stepper's) gives the same places.
  f.sim.lists = nullptr;
  const std::string from_trace = panel_text(host, f, "Selection");
  EXPECT_NE(from_trace.find("z-list C[" + std::to_string(iz) + "]: position 2 of " + std::to_string(chain.size())), std::string::npos)
      << from_trace;
  // Its own layer shown: "(shown)"; book numbering shifts every index.
  f.slice = slice_layer(f.elements, g, iz);
  f.state.book_numbering = true;
  const std::string book = panel_text(host, f, "Selection");
  EXPECT_NE(book.find("in layer " + std::to_string(iz + 1) + " (shown)"), std::string::npos) << book;
  EXPECT_NE(book.find("cell (ix, iy, iz) = (" + std::to_string(ix + 1) + ", " + std::to_string(iy + 1) + ", " + std::to_string(iz + 1) + ")"),
            std::string::npos) << book;
}

// Arrays and Pseudocode on 3D traces: NBS's C, Z, B, Y, A, X with their shapes and row names, the
// 3D loops with the current line; sort, screen and tree 3D show their own.
TEST(StepperPanels3d, ArraysAndPseudocodeShowThe3dArraysAndLoops) {
  Scope3d scope;
  UiHost host;
  auto session = add_stepper_panels(host, StepperConfig{std::size_t{0}, false});
  Frame3d f;
  open_stepper_panels(f.state);
  run_frame(host, f);
  ASSERT_TRUE(session->has_capture()) << session->message();
  const Grid& g = f.grid();
  const std::string n = std::to_string(f.elements.size());
  EXPECT_EQ(array_shapes_text(*session), "C[nz=" + std::to_string(g.n[2]) + "]  Z[N=" + n + "]  B[2][ny=" + std::to_string(g.n[1]) +
                                             "]  Y[N=" + n + "]  A[5][nx=" + std::to_string(g.n[0]) + "]  X[N=" + n + "]");
  // Mid-way through a row's contacts: the 3D lines, the arrays, the rows of A.
  Stepper& st = session->stepper();
  std::size_t contacts = 0;
  for (std::size_t i = 0; i < st.size() && contacts == 0; ++i)
    if (st.events()[i].op == TraceOp::TestPair) contacts = i + 1;
  ASSERT_GT(contacts, 0u);
  st.seek(contacts);
  const std::string text = panel_text(host, f, kPseudocodeTitle) + panel_text(host, f, kArraysTitle);
  for (const char* what : {"nbs, 3D", "add the discrete element k onto the z_iz list", "Loop over all layers iz", "[1] layer iz-1",
                           "[2] (iy-1,iz-1)", "[4] (iy+1,iz-1)", "iz ="})
    EXPECT_NE(text.find(what), std::string::npos) << what << "\n" << text;
  for (const char* algorithm : {"sort", "screen", "tree"}) {
    f.sim.algorithm = algorithm;
    run_frame(host, f);
    ASSERT_TRUE(session->has_capture()) << algorithm << ": " << session->message();
    session->stepper().seek(session->stepper().size() / 2);
    const std::string other = panel_text(host, f, kPseudocodeTitle);
    EXPECT_NE(other.find(std::string(algorithm) + ", 3D"), std::string::npos) << other;
    EXPECT_TRUE(session->current_layer().has_value() || std::string(algorithm) != "screen") << algorithm;
    if (std::string(algorithm) == "screen") {
      EXPECT_NE(other.find("C[ix][iy][iz]"), std::string::npos) << other;
      EXPECT_EQ(array_shapes_text(*session), "C[nx=" + std::to_string(g.n[0]) + "][ny=" + std::to_string(g.n[1]) + "][nz=" +
                                                  std::to_string(g.n[2]) + "]  E[N=" + n + "]");
    }
  }
}

// The stepper's scene overlay on a layer view draws nothing about an element of a hidden layer.
TEST(StepperScene3d, LeavesOutWhatTheLayerViewHides) {
  Frame3d f;
  StepperSession s;
  s.capture(f.traced());
  ASSERT_TRUE(s.has_capture());
  Stepper& st = s.stepper();
  // A push onto the z-list of an element two layers or more from the one shown.
  std::optional<std::size_t> hidden;
  for (std::size_t i = 0; i < st.size() && !hidden; ++i) {
    const TraceEvent& e = st.events()[i];
    if (e.op == TraceOp::Push && e.element >= 0 && !f.slice.visible(e.element)) hidden = i;
  }
  ASSERT_TRUE(hidden.has_value());
  st.seek(*hidden + 1);
  Recorder flat, layered;
  draw_stepper_scene(s, flat, true);
  draw_stepper_scene(s, layered, true, &f.slice);
  EXPECT_GT(flat.circles, 0) << "without a layer the element is ringed";
  EXPECT_EQ(layered.circles, 0);
  EXPECT_TRUE(layered.texts.empty());
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

// Shift+PageDown on a cell clicked in the layer view goes to an operation on that cell of that layer
// (in 3D a cell (ix, iy) alone names none); a violation's pair in a 3D frame is found in the trace.
TEST(StepperPanels3d, ACellSeekAndAViolationsPairWorkIn3d) {
  Scope3d scope;
  UiHost host;
  auto session = add_stepper_panels(host, StepperConfig{std::size_t{0}, false});
  Frame3d f;
  open_stepper_panels(f.state);
  run_frame(host, f);
  ASSERT_TRUE(session->has_capture()) << session->message();
  // A cell of the layer shown that holds an element.
  ElementId k = 0;
  while (k < f.elements.size() && f.slice.place(k) != LayerPlace::Here) ++k;
  ASSERT_LT(k, f.elements.size());
  const Grid& g = f.grid();
  const std::array<std::int32_t, 2> cell{g.cell(f.elements.x[k], 0), g.cell(f.elements.y[k], 1)};
  f.state.selected_cell = cell;
  testui::press(267, true);  // Shift+PageDown
  run_frame(host, f);
  testui::release();
  const TraceEvent* e = session->stepper().current();
  ASSERT_NE(e, nullptr) << session->status;
  EXPECT_EQ(e->cell[0], cell[0]);
  EXPECT_EQ(e->cell[1], cell[1]);
  EXPECT_EQ(e->cell[2], f.slice.layer);

  // A contact the trace found, as if A had lost it: the stepper goes to its test, in its layer's pass.
  ASSERT_FALSE(f.sim.trace->pairs.empty());
  const Pair p = f.sim.trace->pairs.front();
  session->set_target(StepperSession::PairTarget{0, p, Invariant::AEqualsR, "missing from A"});
  run_frame(host, f);
  ASSERT_TRUE(session->target_location().has_value());
  EXPECT_NE(session->target_status().find("tested against"), std::string::npos) << session->target_status();
  const TraceEvent* test = session->stepper().current();
  ASSERT_NE(test, nullptr);
  EXPECT_EQ(test->op, TraceOp::TestPair);
  EXPECT_EQ(session->current_layer(), pair_layer(f.slice, g, p));
}

// Stats counts a 3D grid's cells with all three sides (it once wrote "7 x 7 = 294" for 7 x 7 x 6).
TEST(StatsPanel, ThreeDCellsAreCountedWithTheirLayers) {
  Scope3d scope;
  UiHost host;
  Frame3d f;
  const Grid& g = f.grid();
  ASSERT_GT(g.n[2], 1);
  const std::string text = panel_text(host, f, "Stats");
  const std::string want = "cells " + std::to_string(g.n[0]) + " x " + std::to_string(g.n[1]) + " x " + std::to_string(g.n[2]) +
                           " = " + std::to_string(g.n[0] * g.n[1] * g.n[2]);
  EXPECT_NE(text.find(want), std::string::npos) << text;
}

}  // namespace
}  // namespace nbscope::ui

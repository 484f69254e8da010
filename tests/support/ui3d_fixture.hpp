// nbscope tests: a 3D frame as the panels see it, without GL: a tall ImGui context with the layer
// keys mapped, N random spheres with their grid, layer view and trace, one UI frame of a host over
// it, and the text one panel draws — for the 3D panel tests (tests/ui/test_layers_panel.cpp,
// tests/ui/test_panels_3d.cpp).
#pragma once
#include <imgui.h>
#include <imgui_internal.h>

#include <array>
#include <random>
#include <string>

#include "core/detector.hpp"
#include "core/layers.hpp"
#include "support/ui_fixture.hpp"
#include "ui/panels.hpp"

namespace nbscope::ui::testui {

inline constexpr int kUpKey = 265, kDownKey = 264;  // GLFW's, as the window maps them

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

// A 3D frame as the app would hand it to the panels: its elements, their grid, the busiest layer's
// view and (traced()) the frame's trace by `algorithm` on that grid. Frame3d(n) is N random spheres
// in a 4 m cube, looked at from above.
struct Frame3d {
  Elements elements;
  FrameResult result;
  LayerSlice slice;
  SimView sim;
  UiState state;
  UiRequests requests;
  render::Camera camera;
  explicit Frame3d(int n = 120, const char* algorithm = "nbs") : Frame3d(random_spheres(n), "random-3d", algorithm) {
    camera.set_viewport(1600, 1600);
    camera.set({2, 2}, 100.0);
  }
  // `frame` (3D) named `scene_path`, paused.
  Frame3d(Elements frame, std::string scene_path, const char* algorithm = "nbs") : elements(std::move(frame)) {
    result.lanes.front().grid = make_grid(elements, GridOptions{});
    slice = slice_layer(elements, grid(), busiest_layer(slice_layer(elements, grid(), 0)));
    sim.scene_path = std::move(scene_path);
    sim.elements = &elements;
    sim.frame = &result;
    sim.layer = &slice;
    sim.algorithm = algorithm;
    sim.paused = true;
  }
  static Elements random_spheres(int n) {
    Elements e;
    e.dim = 3;
    std::mt19937 rng(25);
    std::uniform_real_distribution<double> at(0.0, 4.0), radius(0.2, 0.35);
    for (int k = 0; k < n; ++k) e.push_back(at(rng), at(rng), at(rng), radius(rng));
    return e;
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

// Every text the panel titled `title` of `host` draws in one frame, in drawing order: the panel is
// drawn into a window of the test's own with ImGui's log on (which stops at the end of a window).
inline std::string panel_text(UiHost& host, Frame3d& f, const char* title) {
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

}  // namespace nbscope::ui::testui

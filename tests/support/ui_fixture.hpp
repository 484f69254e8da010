// nbscope tests: an ImGui context without GL, the book's Fig. 3.15 as a frame the panels see, a
// DrawSink that records, and one UI frame of a host with keys pressed — for the panel tests.
#pragma once
#include <imgui.h>

#include <string>
#include <tuple>
#include <vector>

#include "core/detector.hpp"
#include "core/frame_trace.hpp"
#include "support/draw_recorder.hpp"
#include "support/generators.hpp"
#include "ui/host.hpp"
#include "ui/model.hpp"

namespace nbscope::ui::testui {

// An ImGui context with its font atlas built and GLFW's arrow and space key codes mapped.
struct ImGuiScope {
  ImGuiScope() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    io.DisplaySize = ImVec2(1280, 720);
    io.DeltaTime = 1.0f / 60.0f;
    io.KeyMap[ImGuiKey_RightArrow] = 262;
    io.KeyMap[ImGuiKey_LeftArrow] = 263;
    io.KeyMap[ImGuiKey_Space] = 32;
    io.KeyMap[ImGuiKey_PageUp] = 266;
    io.KeyMap[ImGuiKey_PageDown] = 267;
  }
  ~ImGuiScope() { ImGui::DestroyContext(); }
};

// The book's Fig. 3.15 on its 10x10 grid of unit cells, as the frame loop would show it: the
// view points at `result`, as it points at the frame loop's own (its frame number, grid, pairs).
struct BookFrame {
  Elements elements;
  FrameResult result;
  SimView sim;
  UiState state;
  UiRequests requests;
  render::Camera camera;
  BookFrame() {
    elements = testdata::book_nine();
    result.lanes.front().grid.n[0] = result.lanes.front().grid.n[1] = 10;
    sim.scene_path = "book-fig-3-15.json";
    sim.elements = &elements;
    sim.frame = &result;
    sim.algorithm = "screen";
    sim.paused = true;
    camera.set_viewport(1280, 720);
    camera.set({5, 5}, 40.0);
  }
  // The view with this frame's trace, made as the frame loop makes it (the grid pinned to the
  // result's when sim.frame points at one) for the current algorithm, elements and frame; kept while those stay.
  SimView& traced() {
    const Grid* grid = sim.grid();
    const auto key = std::make_tuple(sim.algorithm, static_cast<const void*>(sim.elements), sim.frame_number(), grid != nullptr);
    if (sim.elements != nullptr && (!sim.trace || key != trace_key_)) {
      DetectOptions o;
      if (grid != nullptr) {
        o.grid.cell_size = grid->cell_size;
        o.grid.origin = std::array<double, 3>{grid->origin[0], grid->origin[1], grid->origin[2]};
        o.grid.cells = std::array<std::int64_t, 3>{grid->n[0], grid->n[1], grid->n[2]};
      }
      sim.trace = trace_frame(*make_detector(sim.algorithm), *sim.elements, o, sim.frame_number(), grid != nullptr ? *grid : Grid{});
      trace_key_ = key;
    }
    return sim;
  }

 private:
  std::tuple<std::string, const void*, std::int64_t, bool> trace_key_;
};

// The one recorder of the tests that draw without GL (support/draw_recorder.hpp).
using render::testdraw::Recorder;

// Runs one UI frame of `host` (its keys and mouse included) over `f` (a BookFrame, a Frame3d) and
// draws its scene overlay into `sink`.
template <class TestFrame>
void run_frame(UiHost& host, TestFrame& f, Recorder* sink = nullptr) {
  f.requests = {};
  f.traced();
  ImGui::NewFrame();
  UiContext ctx{f.sim, f.state, f.requests, f.camera};
  host.frame(ctx, true);
  if (sink != nullptr) host.draw_scene(ctx, *sink);
  ImGui::Render();
}

inline void press(int key, bool shift = false) {
  ImGuiIO& io = ImGui::GetIO();
  io.KeyShift = shift;
  io.KeysDown[key] = true;
}
inline void release() {
  ImGuiIO& io = ImGui::GetIO();
  for (bool& k : io.KeysDown) k = false;
  io.KeyShift = false;
}

}  // namespace nbscope::ui::testui

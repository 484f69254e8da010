// nbscope app (private to verify_view.cpp and verify_window.cpp): the GL side of the verify view —
// one frame of a `verify --arrays` run (the elements as discs, the grid, the user's lists, the red
// marks, the panels) into the current framebuffer, and the window's input. The screenshot and the
// window differ only in where the pixels go and whether input is live.
#pragma once
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "app/verify_view.hpp"
#include "core/layers.hpp"
#include "render/camera_framing.hpp"
#include "render/gl_context.hpp"
#include "render/imgui_layer.hpp"
#include "render/overlay_verify.hpp"
#include "render/overlays.hpp"
#include "render/renderer.hpp"
#include "ui/verify_panels.hpp"

struct GLFWwindow;

namespace nbscope {

class VerifyView {
 public:
  // Frames drawn before a scripted screenshot: ImGui sizes the panels over the first frames and the
  // camera refits to the space they leave (as GlView::kSettleFrames).
  static constexpr int kSettleFrames = 5;

  // Loads the shaders (Error when missing), applies --overlays, --panels, --select, --lists and
  // --camera (Error for an unknown name or element; --step, and --book-numbering on a file counting
  // from 0, are refused), selects the first problem and fits the camera.
  // `context` must be current; `window` is null off-screen. `run` must outlive the view.
  VerifyView(render::GlContext& context, GLFWwindow* window, const VerifyArraysRun& run, const ViewOptions& options);
  ~VerifyView();
  VerifyView(const VerifyView&) = delete;
  VerifyView& operator=(const VerifyView&) = delete;

  // Draws one frame into the current framebuffer; `live_input` lets keys and mouse act.
  void frame(bool live_input, float dt);
  // The last frame's time to draw (scene and panels), in ms.
  [[nodiscard]] double frame_ms() const { return frame_ms_; }
  // The problem selected (index into the verdict's problems, -1: none) and the marks drawn.
  [[nodiscard]] int selected_problem() const { return state_.selected_problem; }
  [[nodiscard]] const render::VerifyMarks& marks() const { return marks_; }
  [[nodiscard]] const render::Camera& camera() const { return camera_; }
  // Selects problem `index` as a click in the Problems panel does: highlighted, the camera on it.
  void go_to_problem(int index);
  // A 3D run's layer shown (--layer K, Up/Down; else auto: the selected problem's, the selected
  // element's, the busiest), as the window shows a 3D frame; null for 2D.
  [[nodiscard]] const LayerSlice* layer() const { return layer_ ? &*layer_ : nullptr; }

 private:
  void select_problem(int index);
  void step_problem(int delta);
  // Problem `index`'s elements, its link's ends (a head link: its list's first element).
  [[nodiscard]] std::vector<ElementId> problem_elements(int index) const;
  // Home (the elements fitted, or --camera's view) in the space the panels and the legend leave.
  void fit();
  // Keeps `elements` (their cells and neighbours) in view until the user moves the camera.
  void focus_on(std::vector<ElementId> elements);
  // What the panels cover (before their first frame: what they will), and that plus the legend's room.
  [[nodiscard]] render::ScreenInsets panel_insets() const;
  [[nodiscard]] render::ScreenInsets fit_insets() const;
  void handle_input(ui::VerifyUiRequests& requests);
  void draw_tooltip(ElementId k) const;
  // Slices the layer shown again: the user's (layer_option_), else auto.
  void update_layer();

  const VerifyArraysRun& run_;
  render::GlContext& context_;
  bool book_;  // numbered from 1 (the arrays file's base)
  std::unique_ptr<render::Renderer> renderer_;
  std::unique_ptr<render::ImGuiLayer> imgui_;
  render::Camera camera_;
  std::vector<TracedList> lists_;
  std::vector<std::pair<ElementId, int>> on_lists_;  // (element, list) sorted: the lists each element is on
  std::vector<render::ShapeDraw> shapes_;
  render::VerifyMarks marks_;
  ui::VerifyUiModel model_;
  ui::VerifyUiState state_;
  ui::VerifyPanelsLayout layout_;
  bool panels_seen_ = false;  // layout_ holds a drawn frame's panels
  std::optional<render::ListFilter> list_filter_;
  // Home, a problem or list the camera is kept on (until the user moves it), the refit.
  render::CameraFraming framing_;
  std::optional<std::array<std::int32_t, 2>> hovered_cell_;
  std::optional<LayerSlice> layer_;                // a 3D run's layer view (core/layers.hpp)
  std::optional<std::int32_t> layer_option_;       // --layer K or Up/Down; nullopt: auto
  double frame_ms_ = 0;
};

}  // namespace nbscope

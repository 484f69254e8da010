// nbscope render: what a window keeps its camera on between frames — Home (a world box fitted, or
// --camera's fixed view), a subject kept in view until the user moves the camera, and Home again when
// the panels change the free view. One copy for the main window (GlView) and the verify window.
#pragma once
#include <Eigen/Core>
#include <array>
#include <optional>
#include <utility>

#include "core/elements.hpp"
#include "core/grid.hpp"
#include "render/camera.hpp"

namespace nbscope::render {

// The elements' bounding box and half a cell around it (no grid, or a 3D one: the box alone), so
// that the neighbour cells and the list heads stay in view; without elements the frame's periodic
// box on its periodic axes, {0,0}..{1,1} on the others.
[[nodiscard]] WorldRect elements_box(const Elements& elements, const Grid& grid);

// How close a focus brings its subject: it spans at least 1/`widest` and at most 1/`narrowest` of
// the free view's shorter side (the camera's zoom is kept when it already does).
struct FocusZoom {
  double widest = 6;
  double narrowest = 2;
};

// A window's standing orders for its camera: where Home is (a world box fitted, or --camera's
// fixed view), a subject kept in view until the user pans or zooms, and Home again when the panels
// change the free view while the camera is there. `legend_px` is left free below a fitted box.
class CameraFraming {
 public:
  explicit CameraFraming(double legend_px = 0, FocusZoom zoom = {}) : legend_px_(legend_px), zoom_(zoom) {}

  // Home is `box` fitted with a 6 % margin into the free view.
  void set_home_box(const WorldRect& box);
  // Home is world point (x, y) at `ppm` pixels a metre in the middle of the free view (--camera).
  void set_home_view(const std::array<double, 3>& x_y_ppm);
  // Puts `camera` at Home in its viewport minus `insets` and forgets the focus.
  void go_home(Camera& camera, const ScreenInsets& insets);
  // Keeps `centre` in the middle of the viewport minus `insets`, zoomed so that a subject `span`
  // metres across fills FocusZoom's share of it, until the user moves the camera.
  void focus(Camera& camera, const Eigen::Vector2d& centre, double span, const ScreenInsets& insets);
  // Lets the camera go (a new scene).
  void forget_focus() { focus_.reset(); }
  // Once a frame, after input (not when Home was asked): the focus again (the panels may have
  // moved), else, with the camera still at Home, Home again when `insets` changed since.
  void settle(Camera& camera, const ScreenInsets& insets);

 private:
  void apply_focus(Camera& camera, const ScreenInsets& insets);

  double legend_px_;
  FocusZoom zoom_;
  std::optional<WorldRect> home_box_;
  std::optional<std::array<double, 3>> home_view_;  // replaces the box while set
  ScreenInsets fitted_insets_;                       // the free view Home was fitted to
  struct Focus {
    Eigen::Vector2d centre;
    double span = 0;
    std::optional<std::pair<Eigen::Vector2d, double>> applied;  // where the camera was put
  };
  std::optional<Focus> focus_;
};

}  // namespace nbscope::render

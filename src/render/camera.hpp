// nbscope render: the 2D camera. World in metres (y up), screen in pixels (origin top left, y down).
#pragma once
#include <Eigen/Core>

namespace nbscope::render {

// An axis-aligned world rectangle.
struct WorldRect {
  Eigen::Vector2d min{0, 0};
  Eigen::Vector2d max{0, 0};
};

// Pixels at each edge of the viewport that panels cover (the scene is fitted into the rest).
struct ScreenInsets {
  double left = 0, right = 0, top = 0, bottom = 0;
  friend bool operator==(const ScreenInsets&, const ScreenInsets&) = default;
};

class Camera {
 public:
  // Viewport size in pixels; keeps the centre and the scale.
  void set_viewport(int width, int height);
  // Shows `rect` whole, centred in the viewport minus `insets` (where panels sit), with `margin`
  // (a share of that area) left free around it; also remembers it as Home.
  void fit(const WorldRect& rect, double margin = 0.06, const ScreenInsets& insets = {});
  // Puts world point `at` in the middle of the viewport minus `insets` at `pixels_per_metre`; also
  // remembers it as Home.
  void look_at(const Eigen::Vector2d& at, double pixels_per_metre, const ScreenInsets& insets = {});
  // Back to the last fitted view.
  void home();
  // Pans (keeping the scale and Home) so that world point `p` lies inside the viewport minus
  // `insets`, at least `margin` (a share of that area's size) from its edges; no move when it does.
  void keep_in_view(const Eigen::Vector2d& p, const ScreenInsets& insets, double margin);
  // Pans (keeping the scale and Home) so that `p` is in the middle of the viewport minus `insets`.
  void centre_on(const Eigen::Vector2d& p, const ScreenInsets& insets);
  // True while the view is the last fitted one (the user has not panned or zoomed since).
  [[nodiscard]] bool at_home() const { return centre_ == home_centre_ && pixels_per_metre_ == home_pixels_per_metre_; }
  // Zooms by `factor` (> 1 zooms in) keeping the world point under `screen` where it is.
  void zoom_at(const Eigen::Vector2d& screen, double factor);
  // Moves the view by a mouse drag of `delta` pixels (the world follows the mouse).
  void pan_pixels(const Eigen::Vector2d& delta);

  // Pixel position of a world point.
  [[nodiscard]] Eigen::Vector2d to_screen(const Eigen::Vector2d& world) const;
  // World point under a pixel position.
  [[nodiscard]] Eigen::Vector2d to_world(const Eigen::Vector2d& screen) const;
  // The world rectangle in view.
  [[nodiscard]] WorldRect view() const;
  // World -> normalised device coordinates as scale and offset per axis: ndc = world * s + o.
  void ndc_transform(float scale[2], float offset[2]) const;

  [[nodiscard]] double pixels_per_metre() const { return pixels_per_metre_; }
  [[nodiscard]] const Eigen::Vector2d& centre() const { return centre_; }
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  // Sets centre and scale directly (restoring saved settings); scale is clamped to a sane range.
  void set(const Eigen::Vector2d& centre, double pixels_per_metre);

 private:
  int width_ = 1280;
  int height_ = 720;
  Eigen::Vector2d centre_{0, 0};
  double pixels_per_metre_ = 20;
  Eigen::Vector2d home_centre_{0, 0};
  double home_pixels_per_metre_ = 20;
};

}  // namespace nbscope::render

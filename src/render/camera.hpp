// nbscope render: the 2D camera. World in metres (y up), screen in pixels (origin top left, y down).
#pragma once
#include <Eigen/Core>

namespace nbscope::render {

// An axis-aligned world rectangle.
struct WorldRect {
  Eigen::Vector2d min{0, 0};
  Eigen::Vector2d max{0, 0};
};

class Camera {
 public:
  // Viewport size in pixels; keeps the centre and the scale.
  void set_viewport(int width, int height);
  // Shows `rect` whole, centred in the viewport minus `left_px`/`right_px` columns (where panels
  // sit), with `margin` (a share of that area) left free around it; also remembers it as Home.
  void fit(const WorldRect& rect, double margin = 0.06, double left_px = 0, double right_px = 0);
  // Back to the last fitted view.
  void home();
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

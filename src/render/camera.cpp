#include "render/camera.hpp"

#include <algorithm>
#include <cmath>

namespace nbscope::render {

namespace {
// From a whole continent on one pixel to a micrometre filling the screen: past these, float
// coordinates on the GPU stop being meaningful.
constexpr double kMinScale = 1e-4;
constexpr double kMaxScale = 1e7;
double clamp_scale(double s) { return std::isfinite(s) ? std::clamp(s, kMinScale, kMaxScale) : 20.0; }
}  // namespace

void Camera::set_viewport(int width, int height) {
  width_ = std::max(width, 1);
  height_ = std::max(height, 1);
}

void Camera::fit(const WorldRect& rect, double margin, const ScreenInsets& insets) {
  const Eigen::Vector2d size = (rect.max - rect.min).cwiseMax(1e-3);
  const double usable = std::max(1.0 - 2.0 * margin, 0.1);
  // Panels leaving less than a quarter of the view are ignored rather than leaving no room at all.
  double left = insets.left, right = insets.right, top = insets.top, bottom = insets.bottom;
  if (left + right > 0.75 * width_) left = right = 0;
  if (top + bottom > 0.75 * height_) top = bottom = 0;
  const double area_w = width_ - left - right, area_h = height_ - top - bottom;
  pixels_per_metre_ = clamp_scale(std::min(area_w * usable / size.x(), area_h * usable / size.y()));
  // Centre the rectangle on the middle of the free area: shift the camera by half the imbalance.
  centre_ = 0.5 * (rect.min + rect.max) - Eigen::Vector2d(0.5 * (left - right), 0.5 * (bottom - top)) / pixels_per_metre_;
  home_centre_ = centre_;
  home_pixels_per_metre_ = pixels_per_metre_;
}

void Camera::look_at(const Eigen::Vector2d& at, double pixels_per_metre, const ScreenInsets& insets) {
  pixels_per_metre_ = clamp_scale(pixels_per_metre);
  if (at.allFinite())
    centre_ = at - Eigen::Vector2d(0.5 * (insets.left - insets.right), 0.5 * (insets.bottom - insets.top)) / pixels_per_metre_;
  home_centre_ = centre_;
  home_pixels_per_metre_ = pixels_per_metre_;
}

void Camera::centre_on(const Eigen::Vector2d& p, const ScreenInsets& insets) {
  if (!p.allFinite()) return;
  centre_ = p - Eigen::Vector2d(0.5 * (insets.left - insets.right), 0.5 * (insets.bottom - insets.top)) / pixels_per_metre_;
}

void Camera::keep_in_view(const Eigen::Vector2d& p, const ScreenInsets& insets, double margin) {
  if (!p.allFinite()) return;
  // The free area in screen pixels, shrunk by the margin on each side.
  const double x0 = insets.left, x1 = width_ - insets.right, y0 = insets.top, y1 = height_ - insets.bottom;
  const double mx = margin * (x1 - x0), my = margin * (y1 - y0);
  const Eigen::Vector2d s = to_screen(p);
  if (s.x() >= x0 + mx && s.x() <= x1 - mx && s.y() >= y0 + my && s.y() <= y1 - my) return;
  centre_on(p, insets);
}

void Camera::home() {
  centre_ = home_centre_;
  pixels_per_metre_ = home_pixels_per_metre_;
}

void Camera::zoom_at(const Eigen::Vector2d& screen, double factor) {
  const Eigen::Vector2d anchor = to_world(screen);
  pixels_per_metre_ = clamp_scale(pixels_per_metre_ * factor);
  centre_ += anchor - to_world(screen);
}

void Camera::pan_pixels(const Eigen::Vector2d& delta) {
  centre_ -= Eigen::Vector2d(delta.x(), -delta.y()) / pixels_per_metre_;
}

Eigen::Vector2d Camera::to_screen(const Eigen::Vector2d& world) const {
  const Eigen::Vector2d d = (world - centre_) * pixels_per_metre_;
  return {0.5 * width_ + d.x(), 0.5 * height_ - d.y()};
}

Eigen::Vector2d Camera::to_world(const Eigen::Vector2d& screen) const {
  const Eigen::Vector2d d(screen.x() - 0.5 * width_, 0.5 * height_ - screen.y());
  return centre_ + d / pixels_per_metre_;
}

WorldRect Camera::view() const {
  const Eigen::Vector2d half = Eigen::Vector2d(width_, height_) * (0.5 / pixels_per_metre_);
  return {centre_ - half, centre_ + half};
}

void Camera::ndc_transform(float scale[2], float offset[2]) const {
  const double sx = 2.0 * pixels_per_metre_ / width_;
  const double sy = 2.0 * pixels_per_metre_ / height_;
  scale[0] = static_cast<float>(sx);
  scale[1] = static_cast<float>(sy);
  offset[0] = static_cast<float>(-centre_.x() * sx);
  offset[1] = static_cast<float>(-centre_.y() * sy);
}

void Camera::set(const Eigen::Vector2d& centre, double pixels_per_metre) {
  if (centre.allFinite()) centre_ = centre;
  pixels_per_metre_ = clamp_scale(pixels_per_metre);
}

}  // namespace nbscope::render

#include "render/camera_framing.hpp"

#include <algorithm>

namespace nbscope::render {

WorldRect elements_box(const Elements& e, const Grid& grid) {
  WorldRect box{{0, 0}, {1, 1}};
  if (e.size() == 0) {  // no atoms yet: the periodic box where the frame has one
    for (int a = 0; a < 2; ++a) {
      if (!e.box.periodic[a] || e.box.length(a) <= 0) continue;
      box.min[a] = e.box.lo[a];
      box.max[a] = e.box.hi[a];
    }
    return box;
  }
  const double d = grid.dim == 2 ? grid.cell_size : 0.0;
  box.min = Eigen::Vector2d((e.x - e.r).minCoeff(), (e.y - e.r).minCoeff()).array() - 0.5 * d;
  box.max = Eigen::Vector2d((e.x + e.r).maxCoeff(), (e.y + e.r).maxCoeff()).array() + 0.5 * d;
  return box;
}

void CameraFraming::set_home_box(const WorldRect& box) {
  home_box_ = box;
  home_view_.reset();
}

void CameraFraming::set_home_view(const std::array<double, 3>& x_y_ppm) { home_view_ = x_y_ppm; }

void CameraFraming::go_home(Camera& camera, const ScreenInsets& insets) {
  focus_.reset();
  fitted_insets_ = insets;
  if (home_view_) {
    camera.look_at({(*home_view_)[0], (*home_view_)[1]}, (*home_view_)[2], insets);
  } else if (home_box_) {
    ScreenInsets with_legend = insets;
    with_legend.bottom += legend_px_;
    camera.fit(*home_box_, 0.06, with_legend);
  }
}

void CameraFraming::focus(Camera& camera, const Eigen::Vector2d& centre, double span, const ScreenInsets& insets) {
  focus_ = Focus{centre, span, std::nullopt};
  apply_focus(camera, insets);
}

void CameraFraming::settle(Camera& camera, const ScreenInsets& insets) {
  if (focus_) {
    apply_focus(camera, insets);
  } else if (camera.at_home() && !(insets == fitted_insets_)) {
    // Panels opened, closed or resized while the camera is where Home put it: Home again in the
    // space they leave.
    go_home(camera, insets);
  }
}

void CameraFraming::apply_focus(Camera& camera, const ScreenInsets& insets) {
  if (!focus_) return;
  // The user panned or zoomed since: the camera is theirs again.
  if (focus_->applied && !(focus_->applied->first == camera.centre() && focus_->applied->second == camera.pixels_per_metre())) {
    focus_.reset();
    return;
  }
  const double free_px = std::max(100.0, std::min(camera.width() - insets.left - insets.right, camera.height() - insets.top - insets.bottom));
  double ppm = camera.pixels_per_metre();
  if (focus_->span * ppm < free_px / zoom_.widest) ppm = free_px / zoom_.widest / focus_->span;
  if (focus_->span * ppm > free_px / zoom_.narrowest) ppm = free_px / zoom_.narrowest / focus_->span;
  camera.set(camera.centre(), ppm);
  camera.centre_on(focus_->centre, insets);
  focus_->applied = std::make_pair(camera.centre(), camera.pixels_per_metre());
}

}  // namespace nbscope::render

#include "ui/window_input.hpp"

#include <imgui.h>

#include <cmath>

namespace nbscope::ui {

bool keys_reach_scene() {
  const ImGuiIO& io = ImGui::GetIO();
  return !io.WantCaptureKeyboard && !io.KeyCtrl && !io.KeyAlt && !io.KeySuper;
}

std::optional<Eigen::Vector2d> mouse_over_scene() {
  const ImGuiIO& io = ImGui::GetIO();
  const bool mouse_valid = io.MousePos.x > -1e30f && io.MousePos.y > -1e30f;
  if (io.WantCaptureMouse || !mouse_valid) return std::nullopt;
  return Eigen::Vector2d(io.MousePos.x, io.MousePos.y);
}

void move_camera_by_mouse(render::Camera& camera, const Eigen::Vector2d& mouse, bool left_button_pans) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.MouseWheel != 0.0f) camera.zoom_at(mouse, std::pow(kZoomPerNotch, static_cast<double>(io.MouseWheel)));
  const bool moved = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f;
  for (int b = left_button_pans ? 0 : 1; b < 2; ++b)
    if (io.MouseDown[b] && moved && (b == 1 || ImGui::IsMouseDragging(0, kClickSlopPx)))
      camera.pan_pixels({io.MouseDelta.x, io.MouseDelta.y});
}

void toggle_overlays_by_key(render::OverlayFlags& flags, std::string_view letters) {
  for (const render::OverlayInfo& o : render::overlay_infos())
    if ((letters.empty() || letters.find(o.key) != std::string_view::npos) && ImGui::IsKeyPressed(o.key, false))
      flags.*o.flag = !(flags.*o.flag);
}

}  // namespace nbscope::ui

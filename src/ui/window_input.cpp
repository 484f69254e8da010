#include "ui/window_input.hpp"

#include <imgui.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

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
      render::set_overlay(flags, o.flag, !(flags.*o.flag));
}

void InputReplay::add(std::span<const render::InputEvent> events) { queue_.insert(queue_.end(), events.begin(), events.end()); }

void InputReplay::apply() {
  using Kind = render::InputEvent::Kind;
  std::array<bool, kKeys> key_changed{};
  std::array<bool, kButtons> button_changed{};
  while (!queue_.empty()) {
    const render::InputEvent e = queue_.front();
    const bool key = e.kind == Kind::Key;
    // A repeat changes nothing (ImGui repeats a held key itself); an unknown code is dropped.
    if (e.action == render::InputEvent::Action::Repeat || e.code < 0 || e.code >= (key ? kKeys : kButtons)) {
      queue_.pop_front();
      continue;
    }
    const auto k = static_cast<std::size_t>(e.code);
    bool& changed = key ? key_changed[k] : button_changed[k];
    if (changed) break;  // its second change this frame: from here on, the next frame's
    changed = true;
    (key ? keys_[k] : buttons_[k]) = e.action == render::InputEvent::Action::Press;
    queue_.pop_front();
  }
  ImGuiIO& io = ImGui::GetIO();
  for (int k = 0; k < kKeys; ++k) io.KeysDown[k] = keys_[static_cast<std::size_t>(k)];
  for (int b = 0; b < kButtons; ++b) io.MouseDown[b] = buttons_[static_cast<std::size_t>(b)];
  const auto down = [&](int a, int b) { return keys_[static_cast<std::size_t>(a)] || keys_[static_cast<std::size_t>(b)]; };
  io.KeyCtrl = down(GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL);
  io.KeyShift = down(GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT);
  io.KeyAlt = down(GLFW_KEY_LEFT_ALT, GLFW_KEY_RIGHT_ALT);
  io.KeySuper = down(GLFW_KEY_LEFT_SUPER, GLFW_KEY_RIGHT_SUPER);
}

}  // namespace nbscope::ui

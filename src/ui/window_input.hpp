// nbscope ui: the mouse and keys every window reads the same way over its scene — the wheel zooms
// about the cursor, a drag pans, the overlays' letters toggle them — shared by the main window
// (UiHost) and the verify window, so that both cameras answer the same input alike. The camera's
// standing orders (Home, a focus, the refit) are render::CameraFraming.
#pragma once
#include <Eigen/Core>
#include <array>
#include <deque>
#include <optional>
#include <span>
#include <string_view>

#include "render/camera.hpp"
#include "render/gl_window.hpp"
#include "render/overlays.hpp"

namespace nbscope::ui {

// Zoom factor per wheel notch.
inline constexpr double kZoomPerNotch = 1.2;
// Pixels the mouse may move with the left button down and still click rather than drag.
inline constexpr float kClickSlopPx = 4.0f;

// True when keys reach the scene: no text field holds them and no Ctrl, Alt or Super is down.
[[nodiscard]] bool keys_reach_scene();
// The mouse in pixels when it is over the scene (known, and over no panel); else nullopt.
[[nodiscard]] std::optional<Eigen::Vector2d> mouse_over_scene();
// This frame's wheel and drag move `camera`: the wheel zooms about `mouse`, the right button drags
// the view, and with `left_button_pans` the left one too once it moved past kClickSlopPx (where a
// left drag does nothing else; the main window's drags a body).
void move_camera_by_mouse(render::Camera& camera, const Eigen::Vector2d& mouse, bool left_button_pans);
// Toggles the overlays whose letter was pressed this frame, of `letters` (empty: every overlay's).
void toggle_overlays_by_key(render::OverlayFlags& flags, std::string_view letters = {});

// The window's key and mouse-button events given to ImGui in their order, at most one change of
// each key or button a frame: a tap that begins and ends between two frames (at 9 FPS, most taps)
// is down for one frame and up the next, where ImGui's own state, polled once a frame, would miss
// it. The rest of a frame's events wait for the next frame, in order.
class InputReplay {
 public:
  static constexpr int kKeys = 512;    // ImGui 1.86's io.KeysDown (GLFW key codes)
  static constexpr int kButtons = 5;   // io.MouseDown
  // Queues the window's events, oldest first.
  void add(std::span<const render::InputEvent> events);
  // Sets io.KeysDown, the modifiers and io.MouseDown for the coming ImGui frame (call after the
  // platform backend's NewFrame, before ImGui::NewFrame).
  void apply();
  // True while events wait for a later frame (the window must draw it rather than sleep).
  [[nodiscard]] bool pending() const { return !queue_.empty(); }

 private:
  std::deque<render::InputEvent> queue_;
  std::array<bool, kKeys> keys_{};
  std::array<bool, kButtons> buttons_{};
};

}  // namespace nbscope::ui

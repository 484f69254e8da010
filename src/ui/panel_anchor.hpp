// nbscope ui: keeps a floating panel's window at a place relative to the display (e.g. bottom
// centre) until the user drags it elsewhere. Call apply() first thing in Panel::draw().
#pragma once
#include <imgui.h>

#include <algorithm>

namespace nbscope::ui {

class WindowAnchor {
 public:
  // Puts the current window so that the point (fx, fy) of it (0..1 of its size) sits at the point
  // (fx, fy) of the display, never above `top` pixels; does nothing once the user has moved it.
  void apply(float fx, float fy, float top) {
    const ImVec2 pos = ImGui::GetWindowPos();
    if (placed_ && (pos.x != last_.x || pos.y != last_.y)) moved_ = true;
    if (moved_) return;
    const ImVec2 size = ImGui::GetWindowSize();
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    last_ = ImVec2(std::max(0.0f, (display.x - size.x) * fx), std::max(top, (display.y - size.y) * fy));
    ImGui::SetWindowPos(last_, ImGuiCond_Always);
    placed_ = true;
  }

 private:
  bool placed_ = false;
  bool moved_ = false;
  ImVec2 last_{0, 0};
};

}  // namespace nbscope::ui

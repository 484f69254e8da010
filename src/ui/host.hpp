// nbscope ui: the host of all panels. Draws the menu bar and each open panel's window in its
// column, routes keys (P pause, O step, R restart, Home, overlay letters, 1..9 algorithms) and
// scene mouse input (left: select and drag a body, right-drag: pan, wheel: zoom about the cursor).
#pragma once
#include <memory>
#include <span>
#include <vector>

#include "ui/panel.hpp"

namespace nbscope::ui {

class UiHost {
 public:
  // A host with the standard panels: Controls, Scenes, Algorithm, Overlays, Stats, Selection, Metrics.
  UiHost();
  // Adds a panel after the existing ones of its column.
  void add_panel(std::unique_ptr<Panel> panel);
  [[nodiscard]] std::span<const std::unique_ptr<Panel>> panels() const { return panels_; }
  // Whether `panel` is open in `state` (its default when the user never toggled it).
  [[nodiscard]] static bool is_open(const Panel& panel, const UiState& state);

  // Draws the UI for one frame (between ImGui::NewFrame and ImGui::Render). With `accept_input`,
  // keys and mouse act on the scene and the camera; scripted runs pass false.
  void frame(UiContext& ctx, bool accept_input);
  // Lets open panels add to the scene.
  void draw_scene(const UiContext& ctx, render::DrawSink& sink) const;
  // Widths in pixels of the left and right panel columns (the camera fits the scene between them).
  [[nodiscard]] float left_width() const;
  [[nodiscard]] float right_width() const;

 private:
  void handle_keys(UiContext& ctx);
  void handle_mouse(UiContext& ctx);
  void draw_menu(UiContext& ctx);
  std::vector<std::unique_ptr<Panel>> panels_;
};

}  // namespace nbscope::ui

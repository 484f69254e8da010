// nbscope ui: the host of all panels. Draws the menu bar and each open panel's window in its place
// — a column at the left or right edge, the bottom dock between them, or floating — collapsing the
// least important panels of a column that would run off the display, and, with the Stepper and the
// Arrays open, a stepping layout (one column, the scene at least half the window); routes keys (P
// pause, O step, R restart, Home, overlay letters, 1..N algorithms) and scene mouse input (left:
// select and drag a body, right-drag: pan, wheel: zoom about the cursor); reports the part of the
// display the panels leave to the scene.
//
// Index: UiHost (panels, frame, insets) | private: column fitting, keys, mouse, menu.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "ui/panel.hpp"

namespace nbscope::ui {

// The Help menu's text, one line each: "" is a separator, "@overlays" the overlay keys (from
// render::overlay_infos()). Every key the host and the panels handle is here; --help and the
// docs/window.md's key list say the same (tests check the keys of all three).
[[nodiscard]] std::span<const char* const> help_lines();

class UiHost {
 public:
  // A host with the standard panels: Controls, Scenes, Algorithm, Overlays, Stats, Selection, Metrics,
  // Violations and the Timeline.
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
  // Pixels at each display edge the panels covered in the last frame (menu bar, columns, bottom
  // dock); before the first frame, the widths of the columns `state` opens.
  [[nodiscard]] render::ScreenInsets insets(const UiState& state) const;
  // The menu bar's and every panel window's rectangle in the last frame (labels keep clear of them).
  [[nodiscard]] const std::vector<render::PixelRect>& covered() const { return covered_; }

 private:
  // Per panel (parallel to panels_): what the column fitting knows about its window.
  struct Slot {
    enum class Pin { None, Expanded, Collapsed };
    float expanded_height = 0;  // its height when last drawn expanded (its contents', when they scrolled)
    bool collapsed = false;     // the host's decision this frame
    Pin pin = Pin::None;        // the user's own click on its title bar wins over the host
  };
  // Whether `state` opens every panel of the stepping layout (Panel::part_of_stepping_layout).
  [[nodiscard]] bool stepping_layout(const UiState& state) const;
  void fit_column(PanelPlace place, const std::vector<std::size_t>& shown, float available);
  // The height the panels after `panel` in its column (`shown`, in column order) ask for, with their gaps.
  [[nodiscard]] float height_below(std::size_t panel, PanelPlace place, const std::vector<std::size_t>& shown) const;
  // Decides the columns' collapses again only when the panels they show (but Selection), the
  // user's pins or the display's height change, and for a few frames after (new panels size
  // themselves): never because a panel's contents grew, a violation was chosen or an element clicked.
  void fit_columns_on_change(const std::vector<std::size_t>& shown, float available);
  void handle_keys(UiContext& ctx);
  void handle_mouse(UiContext& ctx);
  // Holds back a restart of a run with frames or violations until the user confirms it in a popup.
  void confirm_restart(UiContext& ctx);
  void draw_menu(UiContext& ctx);
  // The banner of an injected fault between the columns under the menu bar; returns its height
  // (0 without a fault).
  float draw_fault_banner(const UiContext& ctx, float x0, float x1, float top);
  std::vector<std::unique_ptr<Panel>> panels_;
  std::vector<Slot> slots_;
  std::optional<render::ScreenInsets> insets_;
  std::vector<render::PixelRect> covered_;
  std::array<std::int64_t, 2> restart_loses_{};  // the frames and violations the asked restart drops
  std::vector<int> layout_key_;  // what the columns' collapses were last decided for
  int refit_frames_ = 0;         // frames left to decide them again in
  bool stepping_ = false;        // this frame's layout is the stepping layout
};

}  // namespace nbscope::ui

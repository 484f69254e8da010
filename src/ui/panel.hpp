// nbscope ui: one ImGui panel. The host owns the panels, opens a window for each open one in its
// column, and gives panels a chance to draw into the scene and to take keys; a new panel (the
// stepper, an arrays view) is one more class added to the host.
#pragma once
#include "render/draw_sink.hpp"
#include "ui/model.hpp"

namespace nbscope::ui {

// Where the host puts a panel's window: a column at the left or right edge, the dock along the
// bottom between the columns (under the scene), or floating over the scene.
enum class PanelPlace { Left, Right, Bottom, Floating };

// After an item: puts the next one, `width` pixels wide, on the same line (`spacing` after it; -1:
// the style's) when it fits in the window, else leaves it on the next line (rows wrap in a
// narrowed column instead of being cut).
void same_line_if_fits(float width, float spacing = -1.0f);
// The width of a button labelled `label`.
float button_width(const char* label);

class Panel {
 public:
  virtual ~Panel() = default;
  // Window title; also its key in the settings file.
  [[nodiscard]] virtual const char* title() const = 0;
  [[nodiscard]] virtual PanelPlace place() const { return PanelPlace::Left; }
  // Its place in the stepping layout (the Stepper and the Arrays open): one column at the right, so
  // the scene keeps half the window above the Arrays; the left column's panels join it.
  [[nodiscard]] virtual PanelPlace stepping_place() const { return place() == PanelPlace::Left ? PanelPlace::Right : place(); }
  // True: the host uses the stepping layout while every panel saying so is open (Stepper, Arrays).
  [[nodiscard]] virtual bool part_of_stepping_layout() const { return false; }
  [[nodiscard]] virtual bool open_by_default() const { return true; }
  // Width of the window in pixels (columns share the widest; the bottom dock spans the space between them).
  [[nodiscard]] virtual float width() const { return 250.0f; }
  // When a column is taller than the display, the panels of lowest priority are collapsed to their
  // title bars first (a click on a title bar expands it again, and the host collapses another).
  [[nodiscard]] virtual int priority() const { return 0; }
  // Order within a column, top to bottom (the bottom dock: bottom to top); equals keep the order
  // the panels were added in. The stepper's panels come first in their column, so that neither
  // moves when a panel above would change its height (with the algorithm, the selection, ...).
  [[nodiscard]] virtual int column_order() const { return 100; }
  // False hides the window this frame even when open (e.g. Selection with nothing selected).
  [[nodiscard]] virtual bool visible(const UiContext&) const { return true; }
  // True: coming and going never collapses another panel; it takes the room left below the others
  // and scrolls (Selection, shown by a click: the panels the user reads stay as they are).
  [[nodiscard]] virtual bool takes_room_left() const { return false; }
  // A panel that can show its contents in less than their height, scrolling part of them (Pseudocode's
  // code, the current line kept in view), says how little it can take: when its column is full the host
  // gives it the room the panels under it leave, down to this, rather than collapse it. 0: it collapses.
  [[nodiscard]] virtual float least_height() const { return 0; }
  // The height its contents take whole when it drew them in less (UiContext::room); 0: the height drawn.
  [[nodiscard]] virtual float full_height() const { return 0; }
  // Draws the window's contents (the host has called Begin).
  virtual void draw(UiContext& ctx) = 0;
  // Adds to the scene, drawn after the overlays (the stepper highlights its current event).
  virtual void draw_scene(const UiContext&, render::DrawSink&) {}
  // Handles this panel's keys when no ImGui widget has the keyboard; true when a key was used.
  virtual bool handle_keys(UiContext&) { return false; }
};

}  // namespace nbscope::ui

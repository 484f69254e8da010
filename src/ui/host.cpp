#include "ui/host.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "core/cells.hpp"
#include "io/plural.hpp"
#include "ui/panels.hpp"
#include "ui/window_input.hpp"

namespace nbscope::ui {

namespace {
constexpr float kGap = 6.0f;
constexpr const char* kRestartPopup = "Restart the run?";
// The columns together take at most this share of the display's width and the bottom dock this
// share of the height below the menu bar, so that the scene keeps about half of each (the panels
// wrap their rows or scroll); a column is never narrower than kMinColumnWidth.
constexpr float kColumnsMaxShare = 0.52f;
constexpr float kMinColumnWidth = 200.0f;
constexpr float kDockMaxShare = 0.45f;
// The stepping layout: its one column is this narrow (the panels wrap), and the dock takes no more
// than leaves the scene this share of the window (the Arrays window their rows to it).
constexpr float kSteppingColumnWidth = 320.0f;
constexpr float kSteppingSceneShare = 0.5f;

PanelPlace place_in(const Panel& panel, bool stepping) { return stepping ? panel.stepping_place() : panel.place(); }

// Narrows the columns (0: not shown) so that both with their gaps take at most kColumnsMaxShare
// of `display_w`: the wider one gives way first, down to the other's width, then both alike.
void cap_column_widths(float display_w, float& left, float& right) {
  const int columns = (left > 0 ? 1 : 0) + (right > 0 ? 1 : 0);
  if (columns == 0) return;
  float excess = left + right - (kColumnsMaxShare * display_w - 2.0f * kGap * static_cast<float>(columns));
  if (excess <= 0) return;
  float& wide = left >= right ? left : right;
  const float narrow = left >= right ? right : left;
  const float first = std::min(excess, wide - std::max(narrow, kMinColumnWidth));
  if (first > 0) {
    wide -= first;
    excess -= first;
  }
  for (float* w : {&left, &right})
    if (*w > 0) *w = std::max(kMinColumnWidth, *w - excess / static_cast<float>(columns));
}
}  // namespace

void same_line_if_fits(float width, float spacing) {
  if (spacing < 0) spacing = ImGui::GetStyle().ItemSpacing.x;
  const float right = ImGui::GetItemRectMax().x + spacing + width;
  if (right <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine(0, spacing);
}

float button_width(const char* label) { return ImGui::CalcTextSize(label, nullptr, true).x + 2 * ImGui::GetStyle().FramePadding.x; }

std::span<const char* const> help_lines() {
  static constexpr const char* kLines[] = {
      "P play/pause   O single step (held: repeats)   R restart   Home: fit the scene",
      "1..N the algorithm (the Algorithm panel's order)   Esc: clear the selection   (R asks first when the run has frames or violations)",
      "",
      "Timeline: , / . one frame back / forward (held: repeats; Shift: 10)   J play backwards",
      "          P on a past frame plays on through the kept frames; Resume here re-simulates",
      "Violations: [ previous   ] next   Shift+[ the first   (none chosen: from the frame on screen)",
      "            a violation line in Stats chooses it too",
      "",
      "Stepper (a paused frame; View -> Stepper):",
      "  -> / <-  one operation forward / back (held: repeats)",
      "  Shift+-> / Shift+<-  the next / previous phase",
      "  Space  play / pause the operations",
      "  PageDown / PageUp  the operation after / before on the selected element",
      "  Shift+PageDown / Shift+PageUp  the same on the selected cell",
      "  (the go-to field: type an operation number, then Enter)",
      "",
      "Layers (a 3D frame, View -> Layers): Up / Down  the layer above / below",
      "  (or the slider; a click or drag in the side view; auto: the view chooses)",
      "",
      "@overlays",
      "",
      "left-click: select an element (or an empty cell); left-drag: pull a body (mouse joint,",
      "            live frame only)   right-drag: pan   wheel: zoom about the cursor",
  };
  return kLines;
}

UiHost::UiHost() {
  add_panel(make_controls_panel());
  add_panel(make_scenes_panel());
  add_panel(make_algorithm_panel());
  add_panel(make_overlays_panel());
  add_panel(make_stats_panel());
  add_panel(make_selection_panel());
  add_panel(make_metrics_panel());
  add_panel(make_violations_panel());
  add_panel(make_timeline_panel());
}

void UiHost::add_panel(std::unique_ptr<Panel> panel) {
  panels_.push_back(std::move(panel));
  slots_.emplace_back();
}

bool UiHost::is_open(const Panel& panel, const UiState& state) {
  const auto it = state.panel_open.find(panel.title());
  return it == state.panel_open.end() ? panel.open_by_default() : it->second;
}

bool UiHost::stepping_layout(const UiState& state) const {
  bool any = false;
  for (const auto& p : panels_) {
    if (!p->part_of_stepping_layout()) continue;
    if (!is_open(*p, state)) return false;
    any = true;
  }
  return any;
}

render::ScreenInsets UiHost::insets(const UiState& state) const {
  if (insets_) return *insets_;
  render::ScreenInsets in;
  const bool stepping = stepping_layout(state);
  for (const auto& p : panels_) {
    if (!is_open(*p, state)) continue;
    const double w = (stepping ? std::min(p->width(), kSteppingColumnWidth) : p->width()) + 2 * kGap;
    if (place_in(*p, stepping) == PanelPlace::Left) in.left = std::max(in.left, w);
    if (place_in(*p, stepping) == PanelPlace::Right) in.right = std::max(in.right, w);
  }
  return in;
}

void UiHost::draw_menu(UiContext& ctx) {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("View")) {
    for (const auto& p : panels_) {
      bool open = is_open(*p, ctx.state);
      if (ImGui::MenuItem(p->title(), nullptr, &open)) ctx.state.panel_open[p->title()] = open;
    }
    ImGui::Separator();
    ImGui::MenuItem("Book numbering (from 1)", nullptr, &ctx.state.book_numbering);
    if (ImGui::MenuItem("Home", "Home")) ctx.requests.camera_home = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    for (const char* line : help_lines()) {
      if (*line == '\0') {
        ImGui::Separator();
      } else if (std::string_view(line) == "@overlays") {
        for (const render::OverlayInfo& o : render::overlay_infos()) ImGui::Text("%c  %s", o.key, o.help);
      } else {
        ImGui::TextUnformatted(line);
      }
    }
    ImGui::EndMenu();
  }
  char where[160];
  std::snprintf(where, sizeof where, "%s  |  %s  |  %s%s", ctx.sim.scene_name.c_str(), ctx.sim.algorithm.c_str(),
                ctx.sim.frame_label(ctx.sim.frame_number()).c_str(), ctx.sim.showing_past ? " (past)" : "");
  // Right-aligned: the injected fault (red), then scene, algorithm and frame.
  const std::string fault = ctx.sim.fault_name.empty() ? "" : "FAULT: " + ctx.sim.fault_name;
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const float total = ImGui::CalcTextSize(where).x + (fault.empty() ? 0.0f : ImGui::CalcTextSize(fault.c_str()).x + spacing);
  ImGui::SameLine(std::max(ImGui::GetCursorPosX() + 20.0f, ImGui::GetWindowWidth() - total - 16.0f));
  if (!fault.empty()) {
    ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.35f, 1.0f), "%s", fault.c_str());
    ImGui::SameLine();
  }
  ImGui::TextDisabled("%s", where);
  ImGui::EndMainMenuBar();
}

// Decides which panels of one column are collapsed to their title bars: none while the column fits
// `available` pixels, else those that joined it for the stepping layout first, then the lowest
// priority first (the lower one of equals first), never one the user expanded or collapsed by
// hand; one that scrolls in less room (Panel::least_height) is kept open when shrinking it is
// enough. Heights are last frame's, so a change settles in a frame.
void UiHost::fit_column(PanelPlace place, const std::vector<std::size_t>& shown, float available) {
  const float title = ImGui::GetFrameHeight();
  float total = 0;
  std::vector<std::size_t> candidates;
  for (const std::size_t i : shown) {
    if (place_in(*panels_[i], stepping_) != place || panels_[i]->takes_room_left()) continue;
    Slot& s = slots_[i];
    s.collapsed = s.pin == Slot::Pin::Collapsed;
    total += (s.collapsed ? title : std::max(s.expanded_height, title)) + kGap;
    if (s.pin == Slot::Pin::None) candidates.push_back(i);
  }
  // Panels that joined the column for the stepping layout give way before its own.
  const auto joined = [&](std::size_t i) { return place_in(*panels_[i], stepping_) != panels_[i]->place(); };
  std::stable_sort(candidates.begin(), candidates.end(), [&](std::size_t a, std::size_t b) {
    if (joined(a) != joined(b)) return joined(a);
    return panels_[a]->priority() != panels_[b]->priority() ? panels_[a]->priority() < panels_[b]->priority() : a > b;
  });
  for (const std::size_t i : candidates) {
    if (total <= available) break;
    const float full = std::max(slots_[i].expanded_height, title);
    // One that scrolls in less room stays open when that is enough (frame() gives it the room left).
    if (const float least = panels_[i]->least_height(); least > 0 && total - full + std::min(least, full) <= available) break;
    total -= full - title;
    slots_[i].collapsed = true;
  }
}

float UiHost::height_below(std::size_t panel, PanelPlace place, const std::vector<std::size_t>& shown) const {
  const auto at = std::find(shown.begin(), shown.end(), panel);
  float below = 0;
  for (auto it = at == shown.end() ? at : at + 1; it != shown.end(); ++it) {
    if (place_in(*panels_[*it], stepping_) != place) continue;
    // At the height it asks for (not as drawn: one squeezed by this panel would stay squeezed).
    const Slot& s = slots_[*it];
    below += (s.collapsed ? ImGui::GetFrameHeight() : std::max(s.expanded_height, ImGui::GetFrameHeight())) + kGap;
  }
  return below;
}

void UiHost::fit_columns_on_change(const std::vector<std::size_t>& shown, float available) {
  constexpr int kRefitFrames = 4;  // an auto-sized window knows its height by its second or third frame
  std::vector<int> key{static_cast<int>(available), stepping_ ? 1 : 0};
  for (const std::size_t i : shown) {
    const Panel& p = *panels_[i];
    const PanelPlace place = place_in(p, stepping_);
    if ((place == PanelPlace::Left || place == PanelPlace::Right) && !p.takes_room_left())
      key.push_back(static_cast<int>(i) * 3 + static_cast<int>(slots_[i].pin));
  }
  if (key != layout_key_) {
    layout_key_ = std::move(key);
    refit_frames_ = kRefitFrames;
  }
  if (refit_frames_ > 0) {
    --refit_frames_;
    fit_column(PanelPlace::Left, shown, available);
    fit_column(PanelPlace::Right, shown, available);
  }
}

void UiHost::frame(UiContext& ctx, bool accept_input) {
  draw_menu(ctx);
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float menu = ImGui::GetFrameHeight();
  const float top = menu + kGap;
  // The columns are as wide as their widest open panel, within half the display's width (one
  // narrower column while stepping).
  stepping_ = stepping_layout(ctx.state);
  std::vector<std::size_t> shown;
  float left_w = 0, right_w = 0;
  for (std::size_t i = 0; i < panels_.size(); ++i) {
    const Panel& p = *panels_[i];
    if (!is_open(p, ctx.state) || !p.visible(ctx)) continue;
    shown.push_back(i);
    if (place_in(p, stepping_) == PanelPlace::Left) left_w = std::max(left_w, p.width());
    if (place_in(p, stepping_) == PanelPlace::Right) right_w = std::max(right_w, p.width());
  }
  if (stepping_) right_w = std::min(right_w, kSteppingColumnWidth);
  cap_column_widths(display.x, left_w, right_w);
  std::stable_sort(shown.begin(), shown.end(),
                   [&](std::size_t a, std::size_t b) { return panels_[a]->column_order() < panels_[b]->column_order(); });
  fit_columns_on_change(shown, display.y - top);
  // The bottom dock spans the space between the columns, under the scene, and leaves the scene at
  // least 55% of the height below the menu (its panels scroll).
  const float dock_x0 = left_w > 0 ? left_w + 2 * kGap : kGap;
  const float dock_x1 = display.x - (right_w > 0 ? right_w + 2 * kGap : kGap);
  float dock_max_h = kDockMaxShare * (display.y - top);
  if (stepping_) {
    // The scene's rectangle (between the columns, under the menu and the banner, above the dock)
    // keeps kSteppingSceneShare of the display; the dock's last gap and the inset's own are its.
    const float banner = insets_ ? static_cast<float>(insets_->top) - menu : 0.0f;
    const float scene_w = dock_x1 - dock_x0 + 2 * kGap;
    const float scene_h = kSteppingSceneShare * display.x * display.y / std::max(scene_w, 1.0f);
    dock_max_h = std::min(dock_max_h, std::max(display.y - menu - banner - scene_h - 2 * kGap, 3.0f * ImGui::GetFrameHeight()));
  }
  float y_left = top, y_right = top, dock_y = display.y - kGap, dock_h = 0;
  covered_.assign(1, render::PixelRect{0, 0, display.x, menu});
  // Opaque panels and title bars: the scene under them (a heat map, pair lines) never shows through the text.
  const ImVec4* colors = ImGui::GetStyle().Colors;
  const auto opaque = [](ImVec4 c) { return ImVec4(c.x, c.y, c.z, 1.0f); };
  ImGui::PushStyleColor(ImGuiCol_WindowBg, opaque(colors[ImGuiCol_WindowBg]));
  ImGui::PushStyleColor(ImGuiCol_PopupBg, opaque(colors[ImGuiCol_PopupBg]));
  ImGui::PushStyleColor(ImGuiCol_TitleBgCollapsed, opaque(colors[ImGuiCol_TitleBg]));
  for (const std::size_t i : shown) {
    Panel& p = *panels_[i];
    Slot& slot = slots_[i];
    const PanelPlace place = place_in(p, stepping_);
    ctx.room = PanelRoom{display.y, stepping_};
    ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings;
    float* column_y = nullptr;
    switch (place) {
      case PanelPlace::Floating:
        ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f - p.width() * 0.5f, top + 40.0f), ImGuiCond_FirstUseEver);
        ImGui::SetNextWindowSizeConstraints(ImVec2(p.width(), 0), ImVec2(p.width(), FLT_MAX));
        break;
      case PanelPlace::Bottom: {
        const float w = std::max(dock_x1 - dock_x0, 200.0f);
        ImGui::SetNextWindowPos(ImVec2(dock_x0, dock_y), ImGuiCond_Always, ImVec2(0, 1));
        ctx.room.height = std::max(dock_max_h - dock_h, 60.0f);
        ImGui::SetNextWindowSizeConstraints(ImVec2(w, 0), ImVec2(w, ctx.room.height));
        flags |= ImGuiWindowFlags_NoMove;
        break;
      }
      case PanelPlace::Left:
      case PanelPlace::Right: {
        const bool left = place == PanelPlace::Left;
        column_y = left ? &y_left : &y_right;
        const float w = left ? left_w : right_w;
        ImGui::SetNextWindowPos(ImVec2(left ? kGap : display.x - kGap - w, *column_y), ImGuiCond_Always);
        // No lower than the display: a panel that grew (or came) after the collapses were decided scrolls.
        float room = std::max(display.y - *column_y - kGap, 3.0f * ImGui::GetFrameHeight());
        // One that scrolls in less room leaves the panels under it theirs (a selection's panel coming
        // takes its room from it), down to its least; a column short by less than a line is left as it is.
        if (p.least_height() > 0 && !slot.collapsed) {
          const float room_left = room - height_below(i, place, shown);
          if (room_left + ImGui::GetTextLineHeight() < slot.expanded_height) room = std::max(room_left, p.least_height());
        }
        ctx.room.height = room;
        ImGui::SetNextWindowSizeConstraints(ImVec2(w, 0), ImVec2(w, room));
        if (p.takes_room_left()) slot.collapsed = slot.pin == Slot::Pin::Collapsed;  // the host never collapses it
        ImGui::SetNextWindowCollapsed(slot.collapsed, ImGuiCond_Always);
        flags |= ImGuiWindowFlags_NoMove;
        if (w < p.width()) flags |= ImGuiWindowFlags_HorizontalScrollbar;  // a narrowed column scrolls sideways
        break;
      }
    }
    bool open = true;
    float natural_height = 0;  // the height its contents ask for, above a smaller `room`
    if (ImGui::Begin(p.title(), &open, flags)) {
      p.draw(ctx);
      const ImGuiStyle& style = ImGui::GetStyle();
      natural_height = std::max(ImGui::GetCursorPosY() - style.ItemSpacing.y + style.WindowPadding.y, p.full_height());
    }
    const ImVec2 size = ImGui::GetWindowSize();
    const ImVec2 pos = ImGui::GetWindowPos();
    covered_.push_back(render::PixelRect{pos.x, pos.y, pos.x + size.x, pos.y + size.y});
    if (column_y != nullptr) {
      // The collapse arrow or a double-click since the last frame, or one click on the title bar of
      // a collapsed panel (which ImGui ignores): the user's choice stays.
      const bool collapsed = ImGui::IsWindowCollapsed();
      const bool title_clicked = collapsed && ImGui::IsWindowHovered() && ImGui::IsMouseClicked(0) && !ImGui::IsAnyItemHovered();
      if (collapsed != slot.collapsed) slot.pin = collapsed ? Slot::Pin::Collapsed : Slot::Pin::Expanded;
      else if (title_clicked) slot.pin = Slot::Pin::Expanded;
      if (!collapsed) slot.expanded_height = std::max(size.y, natural_height);
      *column_y += size.y + kGap;
    } else if (place == PanelPlace::Bottom) {
      dock_y -= size.y + kGap;
      dock_h += size.y + kGap;
    }
    ImGui::End();
    if (!open) {
      ctx.state.panel_open[p.title()] = false;
      slot.pin = Slot::Pin::None;
    }
  }
  ImGui::PopStyleColor(3);
  double bottom = dock_h > 0 ? dock_h + kGap : 0.0;
  // Live, the dock's reserved height only grows while it stays open, so the scene does not jump
  // when a wrapped line comes or goes between two steps; scripted frames reserve what the last
  // state needs, as headless does.
  if (accept_input && bottom > 0 && insets_ && insets_->bottom > 0)
    bottom = std::min<double>(std::max(bottom, insets_->bottom), dock_max_h + kGap);
  const float banner = draw_fault_banner(ctx, dock_x0, dock_x1, top);
  insets_ = render::ScreenInsets{left_w > 0 ? left_w + 2 * kGap : 0.0, right_w > 0 ? right_w + 2 * kGap : 0.0,
                                 menu + banner, bottom};
  if (accept_input) {
    handle_keys(ctx);
    handle_mouse(ctx);
  }
  confirm_restart(ctx);
}

void UiHost::confirm_restart(UiContext& ctx) {
  // A restart (R, the Controls button) drops the run's frames and violations: asked first when it
  // has any. A recording's frames stay (its restart only goes back to its first).
  const SimView& s = ctx.sim;
  if (ctx.requests.restart && !s.replaying && (s.newest_frame > 0 || s.violations_total > 0)) {
    ctx.requests.restart = false;
    restart_loses_ = {s.newest_frame, s.violations_total};
    ImGui::OpenPopup(kRestartPopup);
  }
  if (!ImGui::BeginPopupModal(kRestartPopup, nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) return;
  ImGui::Text("Restart from frame 0? The run's %s and %s are dropped.",
              plural(static_cast<long long>(restart_loses_[0]), "frame").c_str(),
              plural(static_cast<long long>(restart_loses_[1]), "violation").c_str());
  const auto key = [](ImGuiKey k) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(k), false); };
  if (ImGui::Button("Restart (Enter)") || key(ImGuiKey_Enter) || key(ImGuiKey_KeyPadEnter)) {
    ctx.requests.restart = true;
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel (Esc)") || key(ImGuiKey_Escape)) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

float UiHost::draw_fault_banner(const UiContext& ctx, float x0, float x1, float top) {
  if (ctx.sim.fault_name.empty()) return 0.0f;
  // Between the columns, under the menu bar: in the window and in every screenshot, so a failed
  // check is never blamed on the algorithm when the failure was planted.
  const float w = std::max(x1 - x0, 200.0f);
  ImGui::SetNextWindowPos(ImVec2(x0, top), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(w, 0), ImGuiCond_Always);
  ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.55f, 0.08f, 0.08f, 0.92f));
  ImGui::PushStyleColor(ImGuiCol_Border, ImVec4(1.0f, 0.35f, 0.35f, 1.0f));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoBringToFrontOnFocus;
  float height = 0;
  if (ImGui::Begin("##fault banner", nullptr, flags)) {
    ImGui::PushTextWrapPos(w - ImGui::GetStyle().WindowPadding.x);
    ImGui::TextColored(ImVec4(1.0f, 0.92f, 0.92f, 1.0f), "FAULT INJECTED: %s - the checks are meant to fail (Help: --inject-fault)",
                       ctx.sim.fault_name.c_str());
    ImGui::PopTextWrapPos();
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    covered_.push_back(render::PixelRect{pos.x, pos.y, pos.x + size.x, pos.y + size.y});
    height = size.y + kGap;
  }
  ImGui::End();
  ImGui::PopStyleColor(2);
  return height;
}

void UiHost::draw_scene(const UiContext& ctx, render::DrawSink& sink) const {
  for (const auto& p : panels_)
    if (is_open(*p, ctx.state)) p->draw_scene(ctx, sink);
}

void UiHost::handle_keys(UiContext& ctx) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!keys_reach_scene()) return;
  for (const auto& p : panels_)
    if (is_open(*p, ctx.state) && p->handle_keys(ctx)) return;
  auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  const bool shift = io.KeyShift;
  // The timeline: , and . step through the kept frames (held: repeats), J plays backwards.
  if (ImGui::IsKeyPressed(',', true)) ctx.requests.frame_delta = shift ? -10 : -1;
  if (ImGui::IsKeyPressed('.', true)) ctx.requests.frame_delta = shift ? 10 : 1;
  if (pressed('J')) ctx.requests.play = -1;
  // Violations: [ previous, ] next, Shift+[ the first.
  if (pressed('[')) ctx.requests.go_to_violation = step_violation(ctx.sim, ctx.state, shift ? 0 : -1);
  if (pressed(']')) ctx.requests.go_to_violation = step_violation(ctx.sim, ctx.state, +1);
  if (pressed('P')) ctx.requests.toggle_pause = true;
  if (ImGui::IsKeyPressed('O', true)) ctx.requests.step_once = true;
  if (pressed('R')) ctx.requests.restart = true;
  if (pressed(ImGui::GetKeyIndex(ImGuiKey_Home))) ctx.requests.camera_home = true;
  if (pressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
    ctx.state.selected = -1;
    ctx.state.selected_pair.reset();
    ctx.state.selected_cell.reset();
  }
  toggle_overlays_by_key(ctx.state.overlays);
  for (std::size_t i = 0; i < 9; ++i) {
    if (!pressed('1' + static_cast<int>(i))) continue;
    if (i < ctx.sim.algorithms.size()) {
      ctx.requests.algorithm = ctx.sim.algorithms[i];
      ctx.state.algorithm_key_note.clear();
    } else {
      ctx.state.algorithm_key_note = algorithm_key_note(i + 1, ctx.sim.algorithms.size());
    }
  }
}

void UiHost::handle_mouse(UiContext& ctx) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool mouse_valid = io.MousePos.x > -1e30f && io.MousePos.y > -1e30f;
  const Eigen::Vector2d mouse(io.MousePos.x, io.MousePos.y);
  // A drag in progress keeps the body even when the cursor crosses a panel.
  if (ctx.state.dragging) {
    if (io.MouseDown[0] && mouse_valid) {
      ctx.requests.drag_to = ctx.camera.to_world(mouse);
    } else {
      ctx.requests.drag_end = true;
      ctx.state.dragging = false;
    }
  }
  if (io.WantCaptureMouse || !mouse_valid) {
    ctx.state.hovered_cell.reset();
    ctx.state.mouse_world.reset();
    return;
  }
  const Eigen::Vector2d world = ctx.camera.to_world(mouse);
  ctx.state.mouse_world = world;
  ctx.state.hovered_cell = ctx.sim.grid() != nullptr ? cell_at(*ctx.sim.grid(), world) : std::nullopt;
  move_camera_by_mouse(ctx.camera, mouse, false);  // the left button drags a body here
  if (ImGui::IsMouseClicked(0) && !ctx.state.dragging) {
    ctx.state.selected = ctx.sim.elements != nullptr ? render::element_at(*ctx.sim.elements, world, ctx.sim.layer) : -1;
    ctx.state.selected_pair.reset();
    ctx.state.selected_cell = ctx.state.hovered_cell;
    // A past frame is looked at, not pushed: dragging a body needs the live frame (Resume here).
    if (ctx.state.selected >= 0 && !ctx.sim.showing_past && !ctx.sim.replaying) {
      ctx.requests.drag_begin = world;
      ctx.state.dragging = true;
    }
  }
}

}  // namespace nbscope::ui

#include "ui/host.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "ui/panels.hpp"

namespace nbscope::ui {

namespace {
constexpr float kGap = 6.0f;
// Wheel notches to zoom factor: 1.2x per notch.
constexpr double kZoomPerNotch = 1.2;
}  // namespace

UiHost::UiHost() {
  add_panel(make_controls_panel());
  add_panel(make_scenes_panel());
  add_panel(make_algorithm_panel());
  add_panel(make_overlays_panel());
  add_panel(make_stats_panel());
  add_panel(make_selection_panel());
  add_panel(make_metrics_panel());
}

void UiHost::add_panel(std::unique_ptr<Panel> panel) { panels_.push_back(std::move(panel)); }

bool UiHost::is_open(const Panel& panel, const UiState& state) {
  const auto it = state.panel_open.find(panel.title());
  return it == state.panel_open.end() ? panel.open_by_default() : it->second;
}

float UiHost::left_width() const {
  float w = 0;
  for (const auto& p : panels_)
    if (p->place() == PanelPlace::Left) w = std::max(w, p->width());
  return w > 0 ? w + 2 * kGap : 0;
}

float UiHost::right_width() const {
  float w = 0;
  for (const auto& p : panels_)
    if (p->place() == PanelPlace::Right) w = std::max(w, p->width());
  return w > 0 ? w + 2 * kGap : 0;
}

void UiHost::draw_menu(UiContext& ctx) {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("View")) {
    for (const auto& p : panels_) {
      bool open = is_open(*p, ctx.state);
      if (ImGui::MenuItem(p->title(), nullptr, &open)) ctx.state.panel_open[p->title()] = open;
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Home", "Home")) ctx.requests.camera_home = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    ImGui::TextUnformatted("P play/pause   O single step   R restart   Home: fit the scene");
    ImGui::TextUnformatted("1..9 algorithm   Esc: clear the selection");
    for (const render::OverlayInfo& o : render::overlay_infos()) ImGui::Text("%c  %s", o.key, o.help);
    ImGui::TextUnformatted("left-click: select an element; left-drag: pull a body (mouse joint)");
    ImGui::TextUnformatted("right-drag: pan   wheel: zoom about the cursor");
    ImGui::EndMenu();
  }
  ImGui::SameLine(ImGui::GetWindowWidth() - 360.0f);
  ImGui::TextDisabled("%s  |  %s  |  frame %lld", ctx.sim.scene_name.c_str(), ctx.sim.algorithm.c_str(),
                      static_cast<long long>(ctx.sim.frame));
  ImGui::EndMainMenuBar();
}

void UiHost::frame(UiContext& ctx, bool accept_input) {
  draw_menu(ctx);
  const float top = ImGui::GetFrameHeight() + kGap;
  const float screen_w = ImGui::GetIO().DisplaySize.x;
  float y_left = top, y_right = top;
  const float right_w = right_width() - 2 * kGap;
  for (const auto& p : panels_) {
    if (!is_open(*p, ctx.state) || !p->visible(ctx)) continue;
    ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings;
    float* column_y = nullptr;
    if (p->place() == PanelPlace::Floating) {
      ImGui::SetNextWindowPos(ImVec2(screen_w * 0.5f - p->width() * 0.5f, top + 40.0f), ImGuiCond_FirstUseEver);
    } else {
      column_y = p->place() == PanelPlace::Left ? &y_left : &y_right;
      const float x = p->place() == PanelPlace::Left ? kGap : screen_w - kGap - right_w;
      ImGui::SetNextWindowPos(ImVec2(x, *column_y), ImGuiCond_Always);
      flags |= ImGuiWindowFlags_NoMove;
    }
    const float w = p->place() == PanelPlace::Right ? right_w : p->width();
    ImGui::SetNextWindowSizeConstraints(ImVec2(w, 0), ImVec2(w, FLT_MAX));
    bool open = true;
    if (ImGui::Begin(p->title(), &open, flags)) p->draw(ctx);
    if (column_y != nullptr) *column_y += ImGui::GetWindowSize().y + kGap;
    ImGui::End();
    if (!open) ctx.state.panel_open[p->title()] = false;
  }
  if (accept_input) {
    handle_keys(ctx);
    handle_mouse(ctx);
  }
}

void UiHost::draw_scene(const UiContext& ctx, render::DrawSink& sink) const {
  for (const auto& p : panels_)
    if (is_open(*p, ctx.state)) p->draw_scene(ctx, sink);
}

void UiHost::handle_keys(UiContext& ctx) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard || io.KeyCtrl || io.KeyAlt || io.KeySuper) return;
  for (const auto& p : panels_)
    if (is_open(*p, ctx.state) && p->handle_keys(ctx)) return;
  auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (pressed('P')) ctx.requests.toggle_pause = true;
  if (ImGui::IsKeyPressed('O', true)) ctx.requests.step_once = true;
  if (pressed('R')) ctx.requests.restart = true;
  if (pressed(ImGui::GetKeyIndex(ImGuiKey_Home))) ctx.requests.camera_home = true;
  if (pressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) ctx.state.selected = -1;
  for (const render::OverlayInfo& o : render::overlay_infos())
    if (pressed(o.key)) ctx.state.overlays.*o.flag = !(ctx.state.overlays.*o.flag);
  for (std::size_t i = 0; i < ctx.sim.algorithms.size() && i < 9; ++i)
    if (pressed('1' + static_cast<int>(i))) ctx.requests.algorithm = ctx.sim.algorithms[i];
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
  ctx.state.hovered_cell = ctx.sim.grid != nullptr ? render::cell_at(*ctx.sim.grid, world) : std::nullopt;
  if (io.MouseWheel != 0.0f) ctx.camera.zoom_at(mouse, std::pow(kZoomPerNotch, static_cast<double>(io.MouseWheel)));
  if (io.MouseDown[1] && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f))
    ctx.camera.pan_pixels({io.MouseDelta.x, io.MouseDelta.y});
  if (ImGui::IsMouseClicked(0) && !ctx.state.dragging) {
    ctx.state.selected = ctx.sim.elements != nullptr ? render::element_at(*ctx.sim.elements, world) : -1;
    if (ctx.state.selected >= 0) {
      ctx.requests.drag_begin = world;
      ctx.state.dragging = true;
    }
  }
}

}  // namespace nbscope::ui

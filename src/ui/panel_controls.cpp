// The Controls panel: play/pause (P), single step (O), restart (R), time step, speed, Home.
#include <imgui.h>

#include "ui/panels.hpp"

namespace nbscope::ui {

namespace {

class ControlsPanel final : public Panel {
 public:
  [[nodiscard]] const char* title() const override { return "Controls"; }
  [[nodiscard]] int priority() const override { return 20; }

  void draw(UiContext& c) override {
    const SimView& s = c.sim;
    if (ImGui::Button(s.paused ? "Play (P)" : "Pause (P)", ImVec2(76, 0))) c.requests.toggle_pause = true;
    same_line_if_fits(button_width("Step (O)"), 4.0f);
    if (ImGui::Button("Step (O)")) c.requests.step_once = true;
    same_line_if_fits(button_width("Restart (R)"), 4.0f);
    if (ImGui::Button("Restart (R)")) c.requests.restart = true;
    ImGui::Text("%s   t = %s", s.frame_label(s.frame_number()).c_str(), s.units.time_text(s.sim_time(), "%.3f").c_str());
    if (s.paused) {
      ImGui::SameLine();
      ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "paused");
    }
    // Drags, not sliders: no grab over the value (drag sideways, or double-click and type).
    const ImGuiSliderFlags log_clamped = ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp;
    if (!s.units.name.empty()) {
      // A run in its own units (a LAMMPS run's): the time between its frames, which no drag changes.
      ImGui::Text("time step %s", s.units.time_text(s.time_step, "%.4g").c_str());
    } else {
      float step_ms = static_cast<float>(s.time_step * 1000.0);
      ImGui::SetNextItemWidth(110);
      if (ImGui::DragFloat("time step", &step_ms, 0.16f, 2.0f, 50.0f, "%.2f ms", log_clamped))
        c.requests.time_step = step_ms / 1000.0;
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("2 to 50 ms (restarts the scene): drag sideways, or double-click and type");
    }
    float speed = static_cast<float>(s.speed);
    ImGui::SetNextItemWidth(110);
    if (ImGui::DragFloat("steps/frame", &speed, 0.025f, 0.1f, 8.0f, "%.2fx", log_clamped)) c.requests.speed = speed;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("simulation steps per drawn frame, 0.1 to 8: drag sideways, or double-click and type");
    if (ImGui::Button("Home (fit the scene)")) c.requests.camera_home = true;
  }
};

}  // namespace

std::unique_ptr<Panel> make_controls_panel() { return std::make_unique<ControlsPanel>(); }

}  // namespace nbscope::ui

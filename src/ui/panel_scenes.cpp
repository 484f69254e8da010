// The Scenes panel: every scene of assets/scenes, and any scene file by path.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <filesystem>

#include "ui/panels.hpp"

namespace nbscope::ui {

namespace {

std::string stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

class ScenesPanel final : public Panel {
 public:
  [[nodiscard]] const char* title() const override { return "Scenes"; }
  // A stopped world's line (or a scene that failed to open) is shown here: while there is one the
  // panel outranks the others, so that a short window collapses them rather than it.
  [[nodiscard]] int priority() const override { return showing_error_ ? 100 : 0; }
  [[nodiscard]] bool visible(const UiContext& c) const override {
    showing_error_ = !c.sim.error.empty();  // (asked every frame before the columns are fitted)
    return true;
  }

  void draw(UiContext& c) override {
    const SimView& s = c.sim;
    const std::string current = s.scene_name.empty() ? stem(s.scene_path) : s.scene_name;
    ImGui::SetNextItemWidth(-1);
    if (ImGui::BeginCombo("##scene", current.c_str())) {
      for (const std::string& f : s.scene_files) {
        const bool is_current = std::filesystem::path(f) == std::filesystem::path(s.scene_path);
        if (ImGui::Selectable(stem(f).c_str(), is_current)) c.requests.scene = f;
      }
      ImGui::EndCombo();
    }
    ImGui::SetNextItemWidth(170);
    const bool enter = ImGui::InputTextWithHint("##open", "path/to/scene.json", &c.state.open_path,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if ((ImGui::Button("Open") || enter) && !c.state.open_path.empty()) c.requests.scene = c.state.open_path;
    if (!s.error.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.35f, 0.35f, 1.0f));
      ImGui::TextWrapped("%s", s.error.c_str());
      ImGui::PopStyleColor();
    }
  }

 private:
  mutable bool showing_error_ = false;
};

}  // namespace

std::unique_ptr<Panel> make_scenes_panel() { return std::make_unique<ScenesPanel>(); }

}  // namespace nbscope::ui

// The Algorithm panel: the detector is switched live, between two frames (keys 1..N, as numbered).
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "ui/panels.hpp"

namespace nbscope::ui {

namespace {

class AlgorithmPanel final : public Panel {
 public:
  [[nodiscard]] const char* title() const override { return "Algorithm"; }
  [[nodiscard]] int priority() const override { return 10; }

  void draw(UiContext& c) override {
    const SimView& s = c.sim;
    // Three to a row, in columns as wide as the panel allows (a name never runs into the next);
    // fewer when the column is narrowed.
    float widest = 0;
    for (std::size_t i = 0; i < s.algorithms.size(); ++i)
      widest = std::max(widest, ImGui::CalcTextSize(("9 " + s.algorithms[i]).c_str()).x);
    const ImGuiStyle& style = ImGui::GetStyle();
    const float cell = widest + ImGui::GetFrameHeight() + style.ItemInnerSpacing.x + 2 * style.CellPadding.x;
    const int columns = std::clamp(static_cast<int>(ImGui::GetContentRegionAvail().x / cell), 1, 3);
    if (!ImGui::BeginTable("algorithms", columns)) return;
    for (std::size_t i = 0; i < s.algorithms.size(); ++i) {
      const std::string& name = s.algorithms[i];
      char label[64];
      std::snprintf(label, sizeof label, "%zu %s", i + 1, name.c_str());
      ImGui::TableNextColumn();
      if (ImGui::RadioButton(label, name == s.algorithm) && name != s.algorithm) c.requests.algorithm = name;
    }
    ImGui::EndTable();
    if (!c.state.algorithm_key_note.empty()) ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.4f, 1.0f), "%s", c.state.algorithm_key_note.c_str());
  }
};

}  // namespace

std::string algorithm_key_note(std::size_t key, std::size_t offered) {
  return "key " + std::to_string(key) + ": no algorithm " + std::to_string(key) + " here; keys 1.." + std::to_string(offered) +
         " choose those above";
}

std::unique_ptr<Panel> make_algorithm_panel() { return std::make_unique<AlgorithmPanel>(); }

}  // namespace nbscope::ui

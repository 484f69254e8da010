// The Algorithm panel: the detector is switched live, between two frames (keys 1..9).
#include <imgui.h>

#include <cstdio>

#include "ui/panels.hpp"

namespace nbscope::ui {

namespace {

class AlgorithmPanel final : public Panel {
 public:
  [[nodiscard]] const char* title() const override { return "Algorithm"; }

  void draw(UiContext& c) override {
    const SimView& s = c.sim;
    for (std::size_t i = 0; i < s.algorithms.size(); ++i) {
      const std::string& name = s.algorithms[i];
      char label[64];
      std::snprintf(label, sizeof label, "%zu %s", i + 1, name.c_str());
      if (ImGui::RadioButton(label, name == s.algorithm) && name != s.algorithm) c.requests.algorithm = name;
      if (i % 3 != 2 && i + 1 < s.algorithms.size()) ImGui::SameLine(static_cast<float>((i % 3 + 1) * 78));
    }
  }
};

}  // namespace

std::unique_ptr<Panel> make_algorithm_panel() { return std::make_unique<AlgorithmPanel>(); }

}  // namespace nbscope::ui

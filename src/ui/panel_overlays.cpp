// The Overlays panel: one checkbox per overlay, each also toggled by its key, and the lists filter.
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>

#include "core/detector.hpp"
#include "ui/panels.hpp"

namespace nbscope::ui {

namespace {

class OverlaysPanel final : public Panel {
 public:
  [[nodiscard]] const char* title() const override { return "Overlays"; }
  [[nodiscard]] int priority() const override { return 20; }

  void draw(UiContext& c) override {
    if (!ImGui::BeginTable("overlays", 2)) return;
    for (const render::OverlayInfo& o : render::overlay_infos()) {
      if (o.flag == &render::OverlayFlags::subdomains && c.sim.subdomains == nullptr) continue;  // a frame with ranks only
      ImGui::TableNextColumn();
      char label[48];
      std::snprintf(label, sizeof label, "%s (%c)", o.name, o.key);
      bool on = c.state.overlays.*o.flag;
      if (ImGui::Checkbox(label, &on)) render::set_overlay(c.state.overlays, o.flag, on);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", o.help);
    }
    ImGui::EndTable();
    if (c.state.overlays.lists) {
      // Which lists are drawn; the scene's legend names the kinds this algorithm builds.
      const auto n = c.sim.elements != nullptr ? c.sim.elements->size() : 0;
      const char* automatic = n > render::kRowFilterAbove ? "auto (row: a large scene)" : "auto (all)";
      const int current = c.state.list_filter ? 1 + static_cast<int>(*c.state.list_filter) : 0;
      const char* names[] = {automatic, "all lists", "the selected element's", "the hovered or selected row"};
      ImGui::SetNextItemWidth(-1);
      if (ImGui::BeginCombo("##lists", (std::string("lists: ") + names[current]).c_str())) {
        for (int i = 0; i < 4; ++i)
          if (ImGui::Selectable(names[i], i == current))
            c.state.list_filter = i == 0 ? std::nullopt : std::optional(static_cast<render::ListFilter>(i - 1));
        ImGui::EndCombo();
      }
      if (c.sim.lists != nullptr && c.sim.lists->empty()) ImGui::TextDisabled("%s", no_lists_note(c.sim.algorithm).c_str());
    }
  }
};

}  // namespace

std::string no_lists_note(const std::string& algorithm) {
  // Empty lists of a detector that builds them: the stepper stands before its first push.
  const auto& infos = detector_infos();
  const bool builds = std::any_of(infos.begin(), infos.end(), [&](const DetectorInfo& d) { return d.name == algorithm && d.has_lists; });
  return algorithm + (builds ? " has built no lists yet" : " builds no lists");
}

std::unique_ptr<Panel> make_overlays_panel() { return std::make_unique<OverlaysPanel>(); }

}  // namespace nbscope::ui

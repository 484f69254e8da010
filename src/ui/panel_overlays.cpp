// The Overlays panel: one checkbox per overlay, each also toggled by its key.
#include <imgui.h>

#include <cstdio>

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
      ImGui::TableNextColumn();
      char label[48];
      std::snprintf(label, sizeof label, "%s (%c)", o.name, o.key);
      ImGui::Checkbox(label, &(c.state.overlays.*o.flag));
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", o.help);
    }
    ImGui::EndTable();
    if (c.state.overlays.lists) {
      // The list colours (render/palette.hpp), so arrows can be read without the manual.
      auto swatch = [](render::Rgba col, const char* text) {
        ImGui::TextColored(ImVec4(col.r / 255.0f, col.g / 255.0f, col.b / 255.0f, 1.0f), "%s", text);
      };
      swatch(render::palette::kYList, "-> y-lists of rows (Y)");
      swatch(render::palette::kXList, "-> x-lists, cells, leaves, runs");
      swatch(render::palette::kXListBelow, "-> x-lists of row below (B[1])");
    }
  }
};

}  // namespace

std::unique_ptr<Panel> make_overlays_panel() { return std::make_unique<OverlaysPanel>(); }

}  // namespace nbscope::ui

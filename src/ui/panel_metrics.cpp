// The Metrics window: nbscope inspecting itself, like ImGui's own metrics window — draw calls,
// instances and vertices per batch, GL buffer sizes, labels, ImGui's vertices, the frame time
// history and the size of the trace behind the list overlay.
#include <imgui.h>

#include <algorithm>
#include <numeric>

#include "io/plural.hpp"
#include "ui/panels.hpp"

namespace nbscope::ui {

namespace {

const char* layer_name(render::Layer l) {
  switch (l) {
    case render::Layer::Cells: return "cells";
    case render::Layer::Bodies: return "bodies";
    case render::Layer::Overlay: return "overlay";
    case render::Layer::Top: return "top";
  }
  return "?";
}

class MetricsPanel final : public Panel {
 public:
  [[nodiscard]] const char* title() const override { return "Metrics"; }
  [[nodiscard]] PanelPlace place() const override { return PanelPlace::Floating; }
  [[nodiscard]] bool open_by_default() const override { return false; }
  [[nodiscard]] float width() const override { return 380.0f; }

  void draw(UiContext& c) override {
    const SimView& s = c.sim;
    ImGui::TextWrapped("GL %s", s.gl_description.c_str());
    ImGui::Text("framebuffer %d x %d, %.2f px/m", s.width, s.height, c.camera.pixels_per_metre());
    if (s.render_stats != nullptr) {
      const render::RenderStats& r = *s.render_stats;
      ImGui::Text("scene: %s, submit %s ms", plural(r.draw_calls, "draw call").c_str(), format_ms(s, r.gpu_submit_ms).c_str());
      ImGui::Text("labels: %zu drawn, %zu dropped (limit %zu)", r.labels, r.labels_dropped, render::Renderer::kMaxLabels);
      if (ImGui::BeginTable("batches", 5, ImGuiTableFlags_BordersInnerH)) {
        for (const char* h : {"layer", "kind", "items", "vertices", "buffer"}) ImGui::TableSetupColumn(h);
        ImGui::TableHeadersRow();
        for (const render::BatchStats& b : r.batches) {
          ImGui::TableNextColumn();
          ImGui::TextUnformatted(layer_name(b.layer));
          ImGui::TableNextColumn();
          ImGui::TextUnformatted(render::batch_kind_name(b.kind));
          ImGui::TableNextColumn();
          ImGui::Text("%zu", b.items);
          ImGui::TableNextColumn();
          ImGui::Text("%zu", b.vertices);
          ImGui::TableNextColumn();
          ImGui::Text("%.1f KB", double(b.buffer_bytes) / 1024.0);
        }
        ImGui::EndTable();
      }
    }
    ImGui::Text("ImGui: %s, %s, %s", plural(s.imgui_vertices, "vertex", "vertices").c_str(),
                plural(s.imgui_indices, "index", "indices").c_str(), plural(s.imgui_lists, "draw list").c_str());
    ImGui::Text("trace: %s, %.1f KB", plural(static_cast<long long>(s.trace_events), "event").c_str(), double(s.trace_bytes) / 1024.0);
    if (s.timeline != nullptr) {
      std::size_t kept = 0;
      for (const FrameSummary& f : *s.timeline) kept += f.kept ? 1 : 0;
      ImGui::Text("history: %s, %zu kept, %.1f of %.0f MB", plural(static_cast<long long>(s.timeline->size()), "frame").c_str(), kept,
                  double(s.history_bytes) / 1048576.0, double(s.history_budget) / 1048576.0);
      ImGui::Text("violations: %zu listed (%.1f KB)", s.violations != nullptr ? s.violations->size() : std::size_t{0},
                  s.violations != nullptr ? double(s.violations->size() * sizeof(Violation)) / 1024.0 : 0.0);
    }
    if (s.elements != nullptr)
      ImGui::Text("elements: %.1f KB, pairs: %.1f KB", double(s.elements->size()) * 3 * sizeof(double) / 1024.0,
                  s.pairs() != nullptr ? double(s.pairs()->size() * sizeof(Pair)) / 1024.0 : 0.0);
    if (!s.frame_history_ms.empty() && !s.hide_timings) {
      const auto& h = s.frame_history_ms;
      const float worst = *std::max_element(h.begin(), h.end());
      const float mean = std::accumulate(h.begin(), h.end(), 0.0f) / static_cast<float>(h.size());
      char overlay[64];
      std::snprintf(overlay, sizeof overlay, "mean %.2f ms, max %.2f ms", mean, worst);
      ImGui::PlotLines("##frames", h.data(), static_cast<int>(h.size()), 0, overlay, 0.0f, std::max(worst, 1.0f),
                       ImVec2(width() - 20.0f, 60.0f));
    }
  }
};

}  // namespace

std::unique_ptr<Panel> make_metrics_panel() { return std::make_unique<MetricsPanel>(); }

}  // namespace nbscope::ui

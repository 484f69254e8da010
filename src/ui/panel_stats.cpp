// The Stats panel: sizes, pairs, the cost of each algorithm, the check status and the frame split.
#include <imgui.h>

#include <cstdio>

#include "io/plural.hpp"
#include "ui/panels.hpp"

namespace nbscope::ui {

std::string format_ms(const SimView& sim, double ms) {
  if (sim.hide_timings) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, ms < 10 ? "%.3f" : "%.1f", ms);
  return buf;
}

namespace {

std::string format_bytes(std::size_t bytes) {
  char buf[32];
  if (bytes < 10 * 1024) std::snprintf(buf, sizeof buf, "%zu B", bytes);
  else if (bytes < 10 * 1024 * 1024) std::snprintf(buf, sizeof buf, "%.1f KB", double(bytes) / 1024.0);
  else std::snprintf(buf, sizeof buf, "%.1f MB", double(bytes) / (1024.0 * 1024.0));
  return buf;
}

class StatsPanel final : public Panel {
 public:
  [[nodiscard]] const char* title() const override { return kStatsTitle; }
  [[nodiscard]] PanelPlace place() const override { return PanelPlace::Right; }
  [[nodiscard]] float width() const override { return 290.0f; }

  void draw(UiContext& c) override {
    const SimView& s = c.sim;
    const long long n = s.elements != nullptr ? static_cast<long long>(s.elements->size()) : 0;
    ImGui::Text("N = %s, %s", plural(n, "element").c_str(), plural(static_cast<long long>(s.bodies), "body", "bodies").c_str());
    if (s.grid != nullptr) {
      ImGui::Text("cells %lld x %lld = %lld, d = %.3g m", static_cast<long long>(s.grid->n[0]),
                  static_cast<long long>(s.grid->n[1]), static_cast<long long>(s.grid->cell_count()),
                  s.grid->cell_size);
    }
    ImGui::Text("pairs %zu", s.pairs != nullptr ? s.pairs->size() : std::size_t{0});

    if (!s.algorithm_stats.empty() && ImGui::BeginTable("algos", 4, ImGuiTableFlags_BordersInnerH)) {
      ImGui::TableSetupColumn("algorithm");
      ImGui::TableSetupColumn("ms");
      ImGui::TableSetupColumn("own bytes");
      ImGui::TableSetupColumn("pairs");
      ImGui::TableHeadersRow();
      for (const AlgorithmStat& a : s.algorithm_stats) {
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(a.name.c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(format_ms(s, a.detection_ms).c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(format_bytes(a.bytes).c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%zu", a.pairs);
      }
      ImGui::EndTable();
    }

    ImGui::Separator();
    if (!s.check_ran) {
      ImGui::TextDisabled("check: not run");
    } else if (s.check_ok && s.check_box2d) {
      ImGui::TextColored(ImVec4(0.4f, 0.9f, 0.5f, 1.0f), "check OK: all 4 invariants (R = %s)", s.check_reference.c_str());
      ImGui::TextDisabled("A == R, A in F, T in A, AABB in cells");
    } else if (s.check_ok) {
      ImGui::TextColored(ImVec4(0.4f, 0.9f, 0.5f, 1.0f), "check OK: A == %s", s.check_reference.c_str());
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextDisabled("no Box2D: A in F, T in A, AABB in cells not checked");
      ImGui::PopTextWrapPos();
    } else {
      ImGui::TextColored(ImVec4(1.0f, 0.3f, 0.3f, 1.0f), "check FAILED: %s",
                         plural(static_cast<long long>(s.violation_count), "violation").c_str());
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.5f, 0.5f, 1.0f));
      for (const std::string& line : s.violation_lines) ImGui::TextWrapped("%s", line.c_str());
      ImGui::PopStyleColor();
      // Never cut silently: say how many more, and where they all are.
      if (s.violation_lines_more > 0) {
        char more[96];
        std::snprintf(more, sizeof more, "+%zu more: the Violations panel lists them", s.violation_lines_more);
        if (ImGui::SmallButton(more)) c.state.panel_open[kViolationsTitle] = true;
      }
      if (!s.fault_name.empty()) ImGui::TextDisabled("(fault %s injected)", s.fault_name.c_str());
    }

    ImGui::Separator();
    if (s.hide_timings) {
      ImGui::TextDisabled("timings hidden (--no-timings)");
      return;
    }
    if (s.fps > 0)
      ImGui::Text("%.1f FPS   frame %s ms", s.fps, format_ms(s, s.drawing.frame_ms).c_str());
    else
      ImGui::TextUnformatted("off-screen frame (no FPS)");
    if (ImGui::BeginTable("split", 2)) {
      const std::pair<const char*, double> rows[] = {
          {"physics", s.timings.physics_ms}, {"detection", s.timings.detection_ms}, {"check", s.timings.check_ms},
          {"trace (lists)", s.drawing.trace_ms}, {"overlays", s.drawing.overlay_ms}, {"render", s.drawing.render_ms},
          {"panels", s.drawing.ui_ms}};
      for (const auto& [name, ms] : rows) {
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(name);
        ImGui::TableNextColumn();
        // Physics stepped on a worker thread while the frame before was drawn: not in this frame's sum.
        const bool overlapped = &ms == &rows[0].second && s.drawing.physics_overlapped;
        ImGui::Text("%s ms%s", format_ms(s, ms).c_str(), overlapped ? " (overlapped)" : "");
      }
      ImGui::EndTable();
    }
  }
};

}  // namespace

std::unique_ptr<Panel> make_stats_panel() { return std::make_unique<StatsPanel>(); }

}  // namespace nbscope::ui

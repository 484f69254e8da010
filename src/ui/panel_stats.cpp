// The Stats panel: sizes, pairs, the cost of each algorithm, the check status and the frame split.
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "io/plural.hpp"
#include "ui/frame_split.hpp"
#include "ui/panels.hpp"

namespace nbscope::ui {

std::string format_ms(const SimView& sim, double ms) {
  if (sim.hide_timings) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, ms < 10 ? "%.3f" : "%.1f", ms);
  return buf;
}

std::string violation_line(const Violation& v, bool book) {
  const auto num = [&](std::int64_t value) { return std::to_string(shown(value, book)); };
  return std::string(invariant_name(v.invariant)) + ": " + pair_text(v, book) + " " + v.what + ", cells (" +
         num(v.cell_i.ix) + "," + num(v.cell_i.iy) + ") (" + num(v.cell_j.ix) + "," + num(v.cell_j.iy) + ")";
}

std::string touching_line(Touching touching) {
  return touching == Touching::strict ? "touching: strict (<)" : "touching: inclusive (<=)";
}

namespace {

std::string format_bytes(std::size_t bytes) {
  char buf[32];
  if (bytes < 10 * 1024) std::snprintf(buf, sizeof buf, "%zu B", bytes);
  else if (bytes < 10 * 1024 * 1024) std::snprintf(buf, sizeof buf, "%.1f KB", double(bytes) / 1024.0);
  else std::snprintf(buf, sizeof buf, "%.1f MB", double(bytes) / (1024.0 * 1024.0));
  return buf;
}

// At most this many of a frame's violations are spelled out in the panel; the Violations panel lists all.
constexpr std::size_t kViolationLines = 6;

class StatsPanel final : public Panel {
 public:
  [[nodiscard]] const char* title() const override { return kStatsTitle; }
  [[nodiscard]] PanelPlace place() const override { return PanelPlace::Right; }
  [[nodiscard]] float width() const override { return 290.0f; }

  void draw(UiContext& c) override {
    const SimView& s = c.sim;
    const long long n = s.elements != nullptr ? static_cast<long long>(s.elements->size()) : 0;
    ImGui::Text("N = %s, %s", plural(n, "element").c_str(), plural(static_cast<long long>(s.bodies), "body", "bodies").c_str());
    if (const Grid* grid = s.grid()) {
      if (grid->dim == 3) {
        ImGui::Text("cells %lld x %lld x %lld = %lld, d = %s", static_cast<long long>(grid->n[0]),
                    static_cast<long long>(grid->n[1]), static_cast<long long>(grid->n[2]),
                    static_cast<long long>(grid->cell_count()), s.units.length_text(grid->cell_size).c_str());
      } else {
        ImGui::Text("cells %lld x %lld = %lld, d = %s", static_cast<long long>(grid->n[0]),
                    static_cast<long long>(grid->n[1]), static_cast<long long>(grid->cell_count()),
                    s.units.length_text(grid->cell_size).c_str());
      }
    }
    ImGui::Text("pairs %zu", s.pairs() != nullptr ? s.pairs()->size() : std::size_t{0});
    // The convention decides recorded pairs at zero gap: said for a recording, or when not the default.
    if (s.replaying || s.touching != Touching::inclusive) ImGui::TextUnformatted(touching_line(s.touching).c_str());
    if (const FrameReport* r = s.report(); r != nullptr && (r->counts.boundary > 0 || r->counts.ties > 0))
      ImGui::TextDisabled("at the boundary: %lld within precision, %lld exact %s", static_cast<long long>(r->counts.boundary),
                          static_cast<long long>(r->counts.ties), r->counts.ties == 1 ? "tie" : "ties");
    draw_costs(s);
    ImGui::Separator();
    draw_check(c);
    ImGui::Separator();
    if (s.hide_timings) {
      ImGui::TextDisabled("timings hidden (--no-timings)");
      return;
    }
    // Every part of the frame named (ui/frame_split.hpp): in a window they add up to the frame time.
    // The simulation's own rate beside FPS: the window draws at its pace while the worker steps at its own.
    const std::string rate = frame_rate_line(s.drawing, s.fps);
    const std::string sim = sim_rate_text(s.drawing, s.sim_rate);
    const float room = ImGui::GetContentRegionAvail().x;
    ImGui::TextUnformatted(rate.c_str());
    if (!sim.empty()) {
      // Beside FPS when the panel is wide enough, else under it: never cut at the panel's edge.
      const float gap = ImGui::CalcTextSize("   ").x;
      if (ImGui::CalcTextSize(rate.c_str()).x + gap + ImGui::CalcTextSize(sim.c_str()).x <= room) ImGui::SameLine(0, gap);
      ImGui::TextUnformatted(sim.c_str());
    }
    const FrameTimings timings = s.report() != nullptr ? s.report()->timings : FrameTimings{};
    if (ImGui::BeginTable("split", 2)) {
      for (const FrameSplitRow& row : frame_split_rows(s.drawing, timings)) {
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(row.name.c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%s ms%s", format_ms(s, row.ms).c_str(), row.note.empty() ? "" : (" (" + row.note + ")").c_str());
      }
      ImGui::EndTable();
    }
  }

 private:
  // The cost table: the chosen algorithm, then the check (its reference detector's), read from the frame.
  static void draw_costs(const SimView& s) {
    if (s.frame == nullptr || !ImGui::BeginTable("algos", 4, ImGuiTableFlags_BordersInnerH)) return;
    ImGui::TableSetupColumn("algorithm");
    ImGui::TableSetupColumn("ms");
    ImGui::TableSetupColumn("own bytes");
    ImGui::TableSetupColumn("pairs");
    ImGui::TableHeadersRow();
    const auto row = [&s](const std::string& name, double ms, std::size_t bytes, std::size_t pairs) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(name.c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(format_ms(s, ms).c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(format_bytes(bytes).c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%zu", pairs);
    };
    const FrameReport& report = s.frame->report();
    row(s.algorithm, report.timings.detection_ms, s.detector_bytes, s.frame->selected().pairs.size());
    if (report.checked) row("check (R: " + report.reference + ")", report.timings.check_ms, 0, s.frame->reference.size());
    ImGui::EndTable();
  }

  // The check's verdict on the frame: OK (with what it covered) or the first violations, numbered as shown.
  static void draw_check(UiContext& c) {
    const SimView& s = c.sim;
    const FrameReport* report = s.report();
    if (report == nullptr || !report->checked) {
      ImGui::TextDisabled("check: not run");
    } else if (report->ok() && report->box2d_checks) {
      // `cells` and `contract` are counted only where they apply (a plugin's own cells or walked lists; a traced frame).
      std::string covered = "A == R, A in F, T in A, AABB in cells";
      if (report->cells_checked) covered += ", cells";
      if (report->contract_checked) covered += ", contract";
      ImGui::TextColored(ImVec4(0.4f, 0.9f, 0.5f, 1.0f), "check OK: all %d invariants (R = %s)",
                         4 + (report->cells_checked ? 1 : 0) + (report->contract_checked ? 1 : 0), report->reference.c_str());
      ImGui::TextDisabled("%s", covered.c_str());
    } else if (report->ok()) {
      ImGui::TextColored(ImVec4(0.4f, 0.9f, 0.5f, 1.0f), "check OK: A == %s", report->reference.c_str());
      // A recording of a scene could have had Box2D's checks; a dump's frames never had a world (they
      // say so no more than their reports do).
      if (s.frame_unit != FrameUnit::timestep) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("no Box2D: A in F, T in A, AABB in cells not checked");
        ImGui::PopTextWrapPos();
      }
    } else {
      const auto count = static_cast<std::size_t>(report->violation_count());
      ImGui::TextColored(ImVec4(1.0f, 0.3f, 0.3f, 1.0f), "check FAILED: %s", plural(static_cast<long long>(count), "violation").c_str());
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.5f, 0.5f, 1.0f));
      const std::size_t lines = std::min(report->violations.size(), kViolationLines);
      for (std::size_t i = 0; i < lines; ++i) {
        ImGui::TextWrapped("%s", violation_line(report->violations[i], c.state.book_numbering).c_str());
        // One click from "check FAILED" to the violation: chosen as a click in the Violations panel chooses it.
        if (ImGui::IsItemHovered()) {
          ImGui::GetWindowDrawList()->AddRectFilled(ImGui::GetItemRectMin(), ImGui::GetItemRectMax(), IM_COL32(255, 90, 90, 40));
          ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
        }
        if (ImGui::IsItemClicked()) {
          if (const auto index = violation_index(s, report->violations[i])) c.requests.go_to_violation = *index;
        }
        // The line's cells are the detector's; where the grid puts the elements elsewhere, say so.
        const Violation& v = report->violations[i];
        if (const auto truth = grid_cells(s, v); truth && !(v.cell_i == (*truth)[0] && v.cell_j == (*truth)[1]))
          ImGui::TextDisabled("  true cells (the grid's): %s", cell_pair_text((*truth)[0], (*truth)[1], c.state.book_numbering, c.sim.elements != nullptr ? c.sim.elements->dim : 2).c_str());
      }
      ImGui::PopStyleColor();
      // Never cut silently: say how many more, and where they all are.
      if (count > lines) {
        char more[96];
        std::snprintf(more, sizeof more, "+%zu more: the Violations panel lists them", count - lines);
        if (ImGui::SmallButton(more)) c.state.panel_open[kViolationsTitle] = true;
      }
      if (!s.fault_name.empty()) ImGui::TextDisabled("(fault %s injected)", s.fault_name.c_str());
    }
  }
};

}  // namespace

std::unique_ptr<Panel> make_stats_panel() { return std::make_unique<StatsPanel>(); }

}  // namespace nbscope::ui

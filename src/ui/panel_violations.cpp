// The Violations panel: every violation of the run (frame, invariant, pair, both cells), filtered by
// invariant, with first / previous / next (Shift+[, [ and ]). Choosing one goes to its frame,
// selects both elements, centres the camera on them and, with the stepper open, moves the stepper
// to the operation that decided the pair (the app does it: UiRequests::go_to_violation).
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "io/plural.hpp"
#include "ui/panels.hpp"

namespace nbscope::ui {

namespace {

// The dimension of the run's frames (the frame on screen's): 3D cells carry their layer iz.
int frame_dim(const SimView& sim) { return sim.elements != nullptr ? sim.elements->dim : 2; }

// "(5,6)" and "(4,7)" joined by `between`, with iz in 3D.
std::string cells_joined(const CellIndex& a, const CellIndex& b, bool book, int dim, const char* between);

const ImVec4 kRed(1.0f, 0.4f, 0.4f, 1.0f);
const ImVec4 kOrange(1.0f, 0.65f, 0.3f, 1.0f);

// True when the violation's cells (the detector's) are `truth`.
bool same_cells(const Violation& v, const std::array<CellIndex, 2>& truth) { return v.cell_i == truth[0] && v.cell_j == truth[1]; }

class ViolationsPanel final : public Panel {
 public:
  [[nodiscard]] const char* title() const override { return kViolationsTitle; }
  [[nodiscard]] PanelPlace place() const override { return PanelPlace::Left; }
  // The debugging loop reads it beside the stepper: it keeps its column in the stepping layout too.
  [[nodiscard]] PanelPlace stepping_place() const override { return PanelPlace::Left; }
  [[nodiscard]] float width() const override { return 320.0f; }
  // Above the other panels of its column: when the column is short, they collapse first.
  [[nodiscard]] int priority() const override { return 30; }
  // Also for a frame whose recorded pairs disagree only at the boundary (listed apart, not violations).
  [[nodiscard]] bool visible(const UiContext& c) const override { return c.sim.violations_total > 0 || boundary_count(c.sim) > 0; }

  void draw(UiContext& c) override {
    const SimView& s = c.sim;
    const bool book = c.state.book_numbering;
    if (s.violations_total == 0) {
      ImGui::TextDisabled("no violations");
      draw_boundary(s, book);
      return;
    }
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(kRed, "%s in %s", plural(s.violations_total, "violation").c_str(),
                       plural(s.violation_frames, "frame").c_str());
    if (!s.fault_name.empty()) ImGui::TextDisabled("expected: the fault %s is injected", s.fault_name.c_str());
    ImGui::PopTextWrapPos();

    // Filter by invariant (only those that broke), with counts.
    for (int k = 0; k < kInvariantCount; ++k) {
      const std::int64_t n = s.violations_by_invariant[static_cast<std::size_t>(k)];
      if (n == 0) continue;
      char label[64];
      // "###": the checkbox keeps its ID while the count in its label grows.
      std::snprintf(label, sizeof label, "%s %lld###inv%d", invariant_name(static_cast<Invariant>(k)), static_cast<long long>(n), k);
      ImGui::Checkbox(label, &c.state.violation_filter[static_cast<std::size_t>(k)]);
      ImGui::SameLine();
    }
    ImGui::NewLine();

    const std::vector<Violation>& all = *s.violations;
    refresh_rows(c, all);
    const auto shown = static_cast<std::int64_t>(rows_.size());
    if (ImGui::Button("First")) go(c, step_violation(s, c.state, 0));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the first violation of the run (Shift+[)");
    ImGui::SameLine();
    if (ImGui::Button("< Prev")) go(c, step_violation(s, c.state, -1));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("previous ([)");
    ImGui::SameLine();
    if (ImGui::Button("Next >")) go(c, step_violation(s, c.state, +1));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("next (])");
    ImGui::SameLine();
    const std::int64_t at = position_of(c.state.current_violation);
    if (at >= 0) ImGui::TextDisabled("%lld / %lld", static_cast<long long>(at + 1), static_cast<long long>(shown));
    else ImGui::TextDisabled("%lld listed", static_cast<long long>(shown));

    draw_table(c, all, book);
    const std::int64_t unlisted = s.violations_total - static_cast<std::int64_t>(all.size());
    if (unlisted > 0) {
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextDisabled("+%lld more counted, not listed (200 a frame at most)", static_cast<long long>(unlisted));
      ImGui::PopTextWrapPos();
    }

    // What the chosen one is, and where the stepper found its pair.
    if (c.state.current_violation >= 0 && static_cast<std::size_t>(c.state.current_violation) < all.size()) {
      const Violation& v = all[static_cast<std::size_t>(c.state.current_violation)];
      ImGui::Separator();
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextColored(kRed, "%s", describe_violation(v, book, frame_dim(s), s.frame_unit).c_str());
      const auto truth = grid_cells(s, v);
      if (truth && !same_cells(v, *truth))
        ImGui::TextColored(kOrange, "The grid puts them in %s: the detector's cells are not the true ones.",
                           cell_pair_text((*truth)[0], (*truth)[1], book, frame_dim(s)).c_str());
      if (!s.locate_status.empty()) ImGui::TextWrapped("%s", s.locate_status.c_str());
      ImGui::PopTextWrapPos();
    }
    draw_boundary(s, book);
  }

 private:
  // The shown frame's recorded pairs at the boundary (exact count), never mixed with the violations.
  static std::int64_t boundary_count(const SimView& s) {
    const FrameReport* r = s.report();
    return r != nullptr ? r->counts.boundary + r->counts.ties : 0;
  }

  // Their own section, collapsed: one line each (FrameReport::boundary lists the first 200).
  static void draw_boundary(const SimView& s, bool book) {
    const std::int64_t n = boundary_count(s);
    if (n == 0) return;
    char title[64];
    std::snprintf(title, sizeof title, "At the boundary (%lld)###boundary", static_cast<long long>(n));
    if (!ImGui::CollapsingHeader(title)) return;
    ImGui::PushTextWrapPos(0.0f);
    const std::vector<std::int64_t>* ids = s.ids();
    for (const BoundaryPair& b : s.report()->boundary) ImGui::TextUnformatted(boundary_line(b, book, ids, &s.units).c_str());
    const std::int64_t unlisted = n - static_cast<std::int64_t>(s.report()->boundary.size());
    if (unlisted > 0) ImGui::TextDisabled("+%lld more counted, not listed", static_cast<long long>(unlisted));
    ImGui::PopTextWrapPos();
  }

  // Rows of the filtered list (indices into `all`), rebuilt only when the log or the filter changes.
  void refresh_rows(const UiContext& c, const std::vector<Violation>& all) {
    if (c.sim.violations_generation != rows_generation_ || &all != rows_source_ || c.state.violation_filter != rows_filter_) {
      rows_.clear();
      for (std::size_t k = 0; k < all.size(); ++k)
        if (c.state.violation_filter[static_cast<std::size_t>(all[k].invariant)]) rows_.push_back(k);
      rows_source_ = &all;
      rows_generation_ = c.sim.violations_generation;
      rows_filter_ = c.state.violation_filter;
    }
  }

  void draw_table(UiContext& c, const std::vector<Violation>& all, bool book) {
    // Rows take two lines while a violation of the frame on screen has detector's cells that are not
    // the grid's (a wrong integerisation): the second line gives the true ones. (The clipper needs
    // rows of one height.)
    bool two_lines = false;
    for (const std::size_t k : rows_) {
      const auto truth = grid_cells(c.sim, all[k]);
      if (truth && !same_cells(all[k], *truth)) {
        two_lines = true;
        break;
      }
    }
    const float line_h = ImGui::GetTextLineHeightWithSpacing();
    // A row is its lines plus the cell padding, which equals one line's spacing: two lines, twice a line's height.
    const float row_h = two_lines ? 2.0f * line_h : line_h;
    const float height = std::min(8.0f, static_cast<float>(rows_.size())) * row_h + line_h + 6.0f;
    const ImGuiTableFlags flags = ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                  ImGuiTableFlags_SizingFixedFit;
    if (!ImGui::BeginTable("violations", 4, flags, ImVec2(0, height))) return;
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn(frame_unit_name(c.sim.frame_unit));
    ImGui::TableSetupColumn("check");
    ImGui::TableSetupColumn("pair");
    ImGui::TableSetupColumn("detector's", ImGuiTableColumnFlags_WidthStretch);
    // The headers one by one: the cells column's says whose cells it lists (its name fits the narrow column).
    ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
    for (int column = 0; column < 4; ++column) {
      ImGui::TableSetColumnIndex(column);
      ImGui::TableHeader(ImGui::TableGetColumnName(column));
      if (column == 3 && ImGui::IsItemHovered())
        ImGui::SetTooltip("the cells the detector put the pair's elements in; for the frame on screen, a line\n"
                          "\"true\" below gives the grid's own cells (what Selection and the picture show) where they differ");
    }
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(rows_.size()));
    // Keep the chosen row in view after a jump (a key, a button, the app going to one).
    if (c.state.current_violation != scrolled_to_) {
      scrolled_to_ = c.state.current_violation;
      scroll_to_current_ = true;
    }
    if (scroll_to_current_) {
      for (std::size_t r = 0; r < rows_.size(); ++r)
        if (static_cast<std::int64_t>(rows_[r]) == c.state.current_violation)
          ImGui::SetScrollY(static_cast<float>(r) * row_h);
      scroll_to_current_ = false;
    }
    while (clipper.Step()) {
      for (int r = clipper.DisplayStart; r < clipper.DisplayEnd; ++r) {
        const std::size_t index = rows_[static_cast<std::size_t>(r)];
        const Violation& v = all[index];
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        char frame[32];
        std::snprintf(frame, sizeof frame, "%lld##v%zu", static_cast<long long>(v.frame), index);
        const bool current = static_cast<std::int64_t>(index) == c.state.current_violation;
        if (ImGui::Selectable(frame, current, ImGuiSelectableFlags_SpanAllColumns)) go(c, index);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", describe_violation(v, book, frame_dim(c.sim), c.sim.frame_unit).c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(invariant_name(v.invariant));
        const auto truth = grid_cells(c.sim, v);
        const bool wrong = truth && !same_cells(v, *truth);
        ImGui::TableNextColumn();
        // A dump's frame: its atoms' ids, which the violation carries (and their ranks, when two).
        ImGui::TextUnformatted(violation_pair_text(v, book ? 1 : 0).c_str());
        if (wrong) ImGui::TextDisabled("true");  // under the pair, beside the grid's cells
        ImGui::TableNextColumn();
        const int dim = frame_dim(c.sim);
        if (wrong) ImGui::TextColored(kOrange, "%s", cell_pair_text(v.cell_i, v.cell_j, book, dim).c_str());
        else ImGui::TextUnformatted(cell_pair_text(v.cell_i, v.cell_j, book, dim).c_str());
        if (wrong) ImGui::TextDisabled("%s", cell_pair_text((*truth)[0], (*truth)[1], book, dim).c_str());
        else if (two_lines) ImGui::TextUnformatted("");
      }
    }
    ImGui::EndTable();
  }

  void go(UiContext& c, std::optional<std::size_t> index) {
    if (!index) return;
    c.requests.go_to_violation = *index;
    scroll_to_current_ = true;
  }

  // The position of violation `index` among the rows, or -1 when it is not listed.
  [[nodiscard]] std::int64_t position_of(std::int64_t index) const {
    const auto it = std::lower_bound(rows_.begin(), rows_.end(), static_cast<std::size_t>(std::max<std::int64_t>(index, 0)));
    return index >= 0 && it != rows_.end() && static_cast<std::int64_t>(*it) == index ? it - rows_.begin() : -1;
  }

  std::vector<std::size_t> rows_;
  const std::vector<Violation>* rows_source_ = nullptr;
  std::uint64_t rows_generation_ = static_cast<std::uint64_t>(-1);
  std::array<bool, kInvariantCount> rows_filter_{};
  bool scroll_to_current_ = false;
  std::int64_t scrolled_to_ = -1;
};

}  // namespace

std::optional<std::size_t> step_violation(const SimView& sim, const UiState& state, int direction) {
  if (sim.violations == nullptr || sim.violations->empty()) return std::nullopt;
  const std::vector<Violation>& all = *sim.violations;
  const auto listed = [&](std::size_t k) { return state.violation_filter[static_cast<std::size_t>(all[k].invariant)]; };
  const std::int64_t n = static_cast<std::int64_t>(all.size());
  if (direction == 0) {
    for (std::size_t k = 0; k < all.size(); ++k)
      if (listed(k)) return k;
    return std::nullopt;
  }
  if (state.current_violation < 0 || state.current_violation >= n) {
    // None chosen yet: from the frame on screen, the first listed at or after it (Next, ]) or the
    // last at or before it (Prev, [) — not the run's first, which may be far behind.
    const std::int64_t here = sim.frame_number();
    if (direction > 0) {
      for (std::size_t k = 0; k < all.size(); ++k)
        if (all[k].frame >= here && listed(k)) return k;
    } else {
      for (std::size_t k = all.size(); k-- > 0;)
        if (all[k].frame <= here && listed(k)) return k;
    }
    return std::nullopt;
  }
  for (std::int64_t k = state.current_violation + direction; k >= 0 && k < n; k += direction)
    if (listed(static_cast<std::size_t>(k))) return static_cast<std::size_t>(k);
  return std::nullopt;
}

std::optional<std::size_t> violation_index(const SimView& sim, const Violation& v) {
  if (sim.violations == nullptr) return std::nullopt;
  const std::vector<Violation>& all = *sim.violations;
  // The log is in frame order: its frame's violations, then the one with the same pair and invariant.
  auto it = std::partition_point(all.begin(), all.end(), [&](const Violation& w) { return w.frame < v.frame; });
  for (; it != all.end() && it->frame == v.frame; ++it)
    if (it->pair == v.pair && it->invariant == v.invariant) return static_cast<std::size_t>(it - all.begin());
  return std::nullopt;
}

std::string describe_violation(const Violation& v, bool book, int dim, FrameUnit unit) {
  return std::string(invariant_name(v.invariant)) + " in " + frame_label(unit, v.frame) + ": " + pair_text(v, book) + " " + v.what +
         (std::isfinite(v.gap) ? "; " + gap_text(v.gap) : "") + "; the detector's cells " + cells_joined(v.cell_i, v.cell_j, book, dim, " and ");
}

std::string boundary_line(const BoundaryPair& b, bool book, const std::vector<std::int64_t>* ids, const Units* units) {
  return pair_text(b.pair, book, ids) + ": " + boundary_text(b, units != nullptr && !units->name.empty() ? units : nullptr) + (b.in_r ? " (R has it, A not)" : " (A has it, R not)");
}

std::optional<std::array<CellIndex, 2>> grid_cells(const SimView& sim, const Violation& v) {
  const Grid* grid = sim.grid();
  if (grid == nullptr || sim.elements == nullptr || v.frame != sim.frame_number()) return std::nullopt;
  const Elements& e = *sim.elements;
  if (v.pair.i < 0 || v.pair.j < 0 || v.pair.i >= e.size() || v.pair.j >= e.size()) return std::nullopt;
  // The grid's own integerisation (core/cells.hpp integerise_cells), as the Selection panel and the picture show it.
  const auto cell = [&](ElementId k) { return CellIndex{grid->cell(e.x[k], 0), grid->cell(e.y[k], 1), grid->dim == 3 && e.dim == 3 ? grid->cell(e.z[k], 2) : 0}; };
  return std::array<CellIndex, 2>{cell(v.pair.i), cell(v.pair.j)};
}

namespace {
std::string cells_joined(const CellIndex& a, const CellIndex& b, bool book, int dim, const char* between) {
  const auto id = [&](std::int64_t k) { return std::to_string(shown(k, book)); };
  const auto cell = [&](const CellIndex& c) { return "(" + id(c.ix) + "," + id(c.iy) + (dim == 3 ? "," + id(c.iz) : "") + ")"; };
  return cell(a) + between + cell(b);
}

}  // namespace

std::string cell_pair_text(const CellIndex& a, const CellIndex& b, bool book, int dim) { return cells_joined(a, b, book, dim, " "); }

std::unique_ptr<Panel> make_violations_panel() { return std::make_unique<ViolationsPanel>(); }

}  // namespace nbscope::ui

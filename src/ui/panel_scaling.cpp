// The Scaling panel: the plan's choices, Run/Cancel and progress, the two log-log plots, the
// legend, the skipped points and Export CSV. The run itself is the app's (ScalingRunner).
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <map>

#include "core/error.hpp"
#include "io/plural.hpp"
#include "io/scaling_csv.hpp"
#include "ui/scaling_panel.hpp"
#include "ui/scaling_plot.hpp"

namespace nbscope::ui {

namespace {

// The choices of N: decades from 1e2 to 1e7.
constexpr std::int64_t kSizes[] = {100, 1'000, 10'000, 100'000, 1'000'000, 10'000'000};
constexpr const char* kSizeLabels[] = {"1e2", "1e3", "1e4", "1e5", "1e6", "1e7"};
constexpr const char* kPerDecadeLabels[] = {"1", "2", "3", "4", "5"};
constexpr std::size_t kNotesShown = 20;  // in the tooltip
constexpr float kMinPlotWidth = 300.0f;  // a plot narrower than this is hard to read: stacked instead

// The index of the decade closest to n (from below).
int size_index(std::int64_t n) {
  int best = 0;
  for (int i = 0; i < static_cast<int>(std::size(kSizes)); ++i)
    if (kSizes[i] <= n) best = i;
  return best;
}

class ScalingPanel final : public Panel {
 public:
  explicit ScalingPanel(std::shared_ptr<ScalingRunner> runner) : runner_(std::move(runner)) {
    std::snprintf(export_path_, sizeof export_path_, "%s", kScalingExportDefault);
    for (const char* name : {"brute", "tree", "sort", "screen", "nbs"}) chosen_algorithms_[name] = true;
    chosen_layouts_.assign(scaling_layouts().size(), false);
    chosen_layouts_[0] = true;  // loose
  }

  [[nodiscard]] const char* title() const override { return kScalingTitle; }
  [[nodiscard]] PanelPlace place() const override { return PanelPlace::Bottom; }
  [[nodiscard]] bool open_by_default() const override { return false; }
  [[nodiscard]] float width() const override { return 640.0f; }

  void draw(UiContext& c) override {
    const ScalingStatus s = runner_->status();
    if (s.generation != seen_generation_) adopt(s);
    draw_choices(c.sim, s.running);
    draw_progress(c.sim, s);
    // Docked under the scene (at most 45% of the display, host.cpp): the plots side by side where
    // the dock is wide enough, and as tall as the dock leaves beside the ~8 lines of the rest.
    const float line = ImGui::GetFrameHeightWithSpacing();
    const bool side_by_side = ImGui::GetContentRegionAvail().x >= 2.0f * kMinPlotWidth;
    const float rest = line * (side_by_side ? 8.0f : 10.0f);
    const float plot_h = std::clamp((0.45f * ImGui::GetIO().DisplaySize.y - rest) / (side_by_side ? 1.0f : 2.0f), 80.0f, 150.0f);
    const char* ns_title = "ns per element (time of one detection / N)";
    const char* bytes_title = "bytes per element (the detector's own arrays / N)";
    if (side_by_side && ImGui::BeginTable("##plots", 2)) {
      ImGui::TableNextColumn();
      draw_scaling_plot(ns_title, ScalingQuantity::NsPerElement, s.result.rows, plot_h);
      ImGui::TableNextColumn();
      draw_scaling_plot(bytes_title, ScalingQuantity::BytesPerElement, s.result.rows, plot_h);
      ImGui::EndTable();
    } else {
      draw_scaling_plot(ns_title, ScalingQuantity::NsPerElement, s.result.rows, plot_h);
      draw_scaling_plot(bytes_title, ScalingQuantity::BytesPerElement, s.result.rows, plot_h);
    }
    std::vector<SeriesKey> series;
    std::vector<std::string> layouts;
    for (const ScalingRow& r : s.result.rows) {
      const SeriesKey key{r.algorithm, r.threads};
      if (std::find(series.begin(), series.end(), key) == series.end()) series.push_back(key);
      if (std::find(layouts.begin(), layouts.end(), r.layout) == layouts.end()) layouts.push_back(r.layout);
    }
    if (!s.result.rows.empty()) draw_scaling_legend(series, layouts);
    draw_export(s);
  }

 private:
  // A new run or a loaded CSV: the choices show what its rows measure.
  void adopt(const ScalingStatus& s) {
    seen_generation_ = s.generation;
    if (s.running || s.plan.algorithms.empty()) return;
    for (auto& [name, on] : chosen_algorithms_) on = false;
    for (const std::string& a : s.plan.algorithms) chosen_algorithms_[a] = true;
    std::fill(chosen_layouts_.begin(), chosen_layouts_.end(), false);
    for (Layout l : s.plan.layouts)
      for (std::size_t i = 0; i < scaling_layouts().size(); ++i)
        if (scaling_layouts()[i] == l) chosen_layouts_[i] = true;
    if (!s.plan.threads.empty()) threads_ = *std::max_element(s.plan.threads.begin(), s.plan.threads.end());  // 1 and N, or 1
    n_min_ = size_index(s.plan.n_min);
    n_max_ = std::max(n_min_, size_index(s.plan.n_max));
    per_decade_ = std::clamp(s.plan.points_per_decade, 1, static_cast<int>(std::size(kPerDecadeLabels)));
  }

  void draw_choices(const SimView& sim, bool running) {
    ImGui::BeginDisabled(running);
    ImGui::TextUnformatted("Detectors:");
    for (const std::string& name : sim.detectors) {
      bool& on = chosen_algorithms_[name];
      const float w = ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(name.c_str()).x;
      same_line_if_fits(w);
      ImGui::Checkbox(name.c_str(), &on);
    }
    ImGui::TextUnformatted("Layouts:  ");
    for (std::size_t i = 0; i < scaling_layouts().size(); ++i) {
      const std::string name = layout_name(scaling_layouts()[i]);
      const float w = ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(name.c_str()).x;
      same_line_if_fits(w);
      bool on = chosen_layouts_[i];
      if (ImGui::Checkbox(name.c_str(), &on)) chosen_layouts_[i] = on;
    }
    ImGui::TextUnformatted("N from");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(70.0f);
    ImGui::Combo("##nmin", &n_min_, kSizeLabels, static_cast<int>(std::size(kSizeLabels)));
    ImGui::SameLine();
    ImGui::TextUnformatted("to");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(70.0f);
    ImGui::Combo("##nmax", &n_max_, kSizeLabels, static_cast<int>(std::size(kSizeLabels)));
    n_max_ = std::max(n_max_, n_min_);
    ImGui::SameLine();
    ImGui::TextUnformatted("points a decade");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(50.0f);
    int per_decade_index = per_decade_ - 1;
    if (ImGui::Combo("##perdecade", &per_decade_index, kPerDecadeLabels, static_cast<int>(std::size(kPerDecadeLabels))))
      per_decade_ = per_decade_index + 1;
    ImGui::EndDisabled();
  }

  // The plan the choices make (detectors in the registry's order).
  [[nodiscard]] ScalingPlan plan_of_choices(const SimView& sim) const {
    ScalingPlan plan;
    plan.algorithms.clear();
    for (const std::string& name : sim.detectors)
      if (const auto it = chosen_algorithms_.find(name); it != chosen_algorithms_.end() && it->second) plan.algorithms.push_back(name);
    plan.layouts.clear();
    for (std::size_t i = 0; i < chosen_layouts_.size(); ++i)
      if (chosen_layouts_[i]) plan.layouts.push_back(scaling_layouts()[i]);
    plan.n_min = kSizes[n_min_];
    plan.n_max = kSizes[n_max_];
    plan.points_per_decade = per_decade_;
    // nbs at 1 and N threads (the window's --threads, or the rows shown last): two series.
    plan.threads = scaling_threads(threads_ > 0 ? threads_ : sim.threads);
    return plan;
  }

  void draw_progress(const SimView& sim, const ScalingStatus& s) {
    const ScalingPlan plan = plan_of_choices(sim);
    const bool can_run = !plan.algorithms.empty() && !plan.layouts.empty();
    ImGui::BeginDisabled(s.running || !can_run);
    if (ImGui::Button("Run")) runner_->start(plan);
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!s.running);
    if (ImGui::Button("Cancel")) runner_->cancel();
    ImGui::EndDisabled();
    ImGui::SameLine();
    char overlay[160];
    if (s.running) {
      std::snprintf(overlay, sizeof overlay, "%zu/%zu %s", s.done, s.total, s.point.c_str());
    } else {
      std::snprintf(overlay, sizeof overlay, "Run: %s", plural(static_cast<long long>(scaling_point_count(plan)), "point").c_str());
    }
    ImGui::ProgressBar(s.total > 0 ? static_cast<float>(s.done) / static_cast<float>(s.total) : 0.0f, ImVec2(-1, 0), overlay);
    const std::string rows = plural(static_cast<long long>(s.result.rows.size()), "point");
    char seconds[32] = "-";
    if (!sim.hide_timings) std::snprintf(seconds, sizeof seconds, "%.1f s", s.seconds);
    if (!s.source.empty()) {
      // The file's name only: the same picture wherever the file lives (golden screenshots).
      ImGui::TextDisabled("%s read from %s", rows.c_str(), std::filesystem::path(s.source).filename().c_str());
    } else if (s.result.cancelled && !s.running) {
      ImGui::TextDisabled("cancelled: %s of %zu measured in %s", rows.c_str(), s.total, seconds);
    } else if (s.generation > 0) {
      ImGui::TextDisabled("%s measured in %s (each: the best of a few runs, 0.05-0.2 s)", rows.c_str(), seconds);
    } else {
      ImGui::TextDisabled("Choose detectors, layouts and N, then Run (in the background; Cancel stops it).");
    }
    // The skipped points in one line (the panel keeps its height), each of them on hover.
    const auto& notes = s.result.notes;
    if (notes.empty()) return;
    const std::string line = notes.size() == 1 ? notes[0] : std::to_string(notes.size()) + " skipped: " + notes[0] + ", ...";
    ImGui::TextDisabled("%s", line.c_str());
    if (ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      for (std::size_t i = 0; i < notes.size() && i < kNotesShown; ++i) ImGui::TextUnformatted(notes[i].c_str());
      if (notes.size() > kNotesShown) ImGui::Text("and %zu more", notes.size() - kNotesShown);
      ImGui::EndTooltip();
    }
  }

  void draw_export(const ScalingStatus& s) {
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - button_width("Export CSV") - ImGui::GetStyle().ItemSpacing.x);
    ImGui::InputText("##export", export_path_, sizeof export_path_);
    ImGui::SameLine();
    ImGui::BeginDisabled(s.running || s.result.rows.empty());
    if (ImGui::Button("Export CSV")) {
      try {
        const std::string path = resolve_export_path(export_path_);
        if (path.empty()) throw Error(std::string(export_path_) + ": HOME is not set");
        if (const auto dir = std::filesystem::path(path).parent_path(); !dir.empty()) std::filesystem::create_directories(dir);
        write_scaling_csv(path, s.result.rows);
        export_message_ = "wrote " + plural(static_cast<long long>(s.result.rows.size()), "row") + " to " + path;
        export_failed_ = false;
      } catch (const std::exception& e) {  // Error, or the file system's own (never out of the window's frame)
        export_message_ = e.what();
        export_failed_ = true;
      }
    }
    ImGui::EndDisabled();
    if (!export_message_.empty()) {
      if (export_failed_) {
        ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", export_message_.c_str());
      } else {
        ImGui::TextDisabled("%s", export_message_.c_str());
      }
    }
  }

  std::shared_ptr<ScalingRunner> runner_;
  std::uint64_t seen_generation_ = 0;
  std::map<std::string, bool> chosen_algorithms_;
  std::vector<bool> chosen_layouts_;
  int n_min_ = 1, n_max_ = 3;  // 1e3 .. 1e5
  int per_decade_ = 2;
  int threads_ = 0;  // the N of 1 and N threads, once a run or a CSV set it (0: the window's --threads)
  char export_path_[512] = {};
  std::string export_message_;
  bool export_failed_ = false;
};

}  // namespace

std::string resolve_export_path(const std::string& typed) {
  const auto env = [](const char* name) {
    const char* v = std::getenv(name);
    return std::string(v != nullptr ? v : "");
  };
  const std::string xdg = "$XDG_DATA_HOME";
  if (typed.compare(0, xdg.size(), xdg) == 0) {
    std::string base = env("XDG_DATA_HOME");
    if (base.empty()) {
      if (env("HOME").empty()) return "";
      base = env("HOME") + "/.local/share";
    }
    return base + typed.substr(xdg.size());
  }
  if (typed.compare(0, 2, "~/") == 0) return env("HOME").empty() ? "" : env("HOME") + typed.substr(1);
  return typed;
}

std::unique_ptr<Panel> make_scaling_panel(std::shared_ptr<ScalingRunner> runner) {
  return std::make_unique<ScalingPanel>(std::move(runner));
}

}  // namespace nbscope::ui

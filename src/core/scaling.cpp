#include "core/scaling.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/detector.hpp"
#include "core/error.hpp"
#include "core/plugin_detector.hpp"

namespace nbscope {

namespace {

bool cancelled(const std::atomic<bool>* cancel) { return cancel != nullptr && cancel->load(std::memory_order_relaxed); }

std::string point_name(const std::string& series, Layout layout, std::int64_t n) {
  return series + " " + layout_name(layout) + " N=" + std::to_string(n);
}

// One measured curve: a detector at one thread count.
struct Series {
  std::string algorithm;
  int threads = 1;
};

// The plan's series: each detector in plan order, at each of its thread counts.
std::vector<Series> series_of(const ScalingPlan& plan) {
  std::vector<Series> out;
  for (const std::string& a : plan.algorithms)
    for (int t : threads_measured(plan, a)) out.push_back({a, t});
  return out;
}

// The size a detector's time is first measured at when a plan starts above it (for the projection).
constexpr std::int64_t kPilotN = 10'000;

// Times detect() on `elements` within the plan's bounds; false when cancelled before a timed run.
bool measure(Detector& detector, const Elements& elements, const ScalingPlan& plan, const std::atomic<bool>* cancel,
             ScalingRow& row) {
  DetectOptions options;
  options.threads = row.threads;
  options.touching = plan.touching;
  PairList pairs;
  double best = HUGE_VAL, spent = 0;
  while (row.repeats < plan.max_repeats) {
    if (cancelled(cancel)) return row.repeats > 0;
    const auto t0 = std::chrono::steady_clock::now();
    detector.detect(elements, options, pairs);
    throw_if_misbehaved(detector);  // a plugin's bug: no check here to hold it
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    best = std::min(best, s);
    spent += s;
    ++row.repeats;
    // Enough, or another run (about as long as the best) would go past the point's budget.
    if (spent >= plan.min_seconds || spent + best > plan.max_seconds) break;
  }
  // To a thousandth: finer digits are noise, and the CSV stays readable.
  const auto thousandths = [](double v) { return std::round(v * 1000.0) / 1000.0; };
  const double n = static_cast<double>(elements.size());
  row.ns_per_element = thousandths(best * 1e9 / n);
  row.bytes_per_element = thousandths(static_cast<double>(detector.own_bytes()) / n);
  row.pairs = static_cast<std::int64_t>(pairs.size());
  return true;
}

}  // namespace

const std::vector<Layout>& scaling_layouts() {
  static const std::vector<Layout> layouts = {Layout::Loose,        Layout::Dense,    Layout::Clustered, Layout::Touching,
                                              Layout::UnequalRadii, Layout::FarAway,  Layout::OnLine};
  return layouts;
}

std::vector<std::int64_t> scaling_sizes(std::int64_t n_min, std::int64_t n_max, int points_per_decade) {
  std::vector<std::int64_t> sizes;
  if (n_min < 1 || n_max < n_min || points_per_decade < 1) return sizes;
  const double first = std::log10(static_cast<double>(n_min));
  const double last = std::log10(static_cast<double>(n_max));
  for (int k = 0;; ++k) {
    const double e = first + static_cast<double>(k) / points_per_decade;
    if (e > last + 1e-9) break;
    const auto n = std::clamp(static_cast<std::int64_t>(std::llround(std::pow(10.0, e))), n_min, n_max);
    if (sizes.empty() || sizes.back() != n) sizes.push_back(n);
  }
  if (sizes.back() != n_max) sizes.push_back(n_max);
  return sizes;
}

std::vector<int> scaling_threads(int n) { return n > 1 ? std::vector<int>{1, n} : std::vector<int>{1}; }

std::vector<int> threads_measured(const ScalingPlan& plan, const std::string& algorithm) {
  if (!detector_info(algorithm).uses_threads) return {1};
  return plan.threads;
}

std::string series_name(const std::string& algorithm, int threads) {
  return threads == 1 ? algorithm : algorithm + " x" + std::to_string(threads);
}

std::size_t scaling_point_count(const ScalingPlan& plan) {
  std::size_t series = 0;
  for (const std::string& a : plan.algorithms) {
    try {
      series += threads_measured(plan, a).size();
    } catch (const Error&) {
      ++series;  // an unknown name: check_scaling_plan says so; counted once meanwhile
    }
  }
  return series * plan.layouts.size() * scaling_sizes(plan.n_min, plan.n_max, plan.points_per_decade).size();
}

void check_scaling_plan(const ScalingPlan& plan) {
  if (plan.algorithms.empty()) throw Error("scaling: no detector chosen");
  if (plan.layouts.empty()) throw Error("scaling: no layout chosen");
  for (Layout layout : plan.layouts)
    if (std::find(scaling_layouts().begin(), scaling_layouts().end(), layout) == scaling_layouts().end())
      throw Error("scaling: layout " + layout_name(layout) + " has N^2 contacts or is a rounding test; not a scaling layout");
  for (const std::string& name : plan.algorithms)
    if (!detector_info(name).dim2) throw Error("scaling: " + name + " does not handle 2D elements");
  if (plan.n_min < 1 || plan.n_max < plan.n_min || plan.n_max > kMaxElements)
    throw Error("scaling: N from " + std::to_string(plan.n_min) + " to " + std::to_string(plan.n_max) +
                " is not a range from 1 to " + std::to_string(kMaxElements));
  if (plan.points_per_decade < 1) throw Error("scaling: points per decade must be at least 1");
  if (plan.threads.empty()) throw Error("scaling: no thread count chosen");
  for (std::size_t i = 0; i < plan.threads.size(); ++i) {
    if (plan.threads[i] < 1 || plan.threads[i] > kMaxThreads)
      throw Error("scaling: " + std::to_string(plan.threads[i]) + " threads is not from 1 to " + std::to_string(kMaxThreads));
    if (std::find(plan.threads.begin(), plan.threads.begin() + static_cast<std::ptrdiff_t>(i), plan.threads[i]) !=
        plan.threads.begin() + static_cast<std::ptrdiff_t>(i))
      throw Error("scaling: " + std::to_string(plan.threads[i]) + " threads given twice");
  }
}

ScalingPlan plan_covering(const std::vector<ScalingRow>& rows) {
  ScalingPlan plan;
  plan.algorithms.clear();
  plan.layouts.clear();
  plan.threads.clear();
  if (rows.empty()) {
    plan.threads = {1};
    return plan;
  }
  plan.n_min = plan.n_max = rows.front().n;
  std::vector<std::int64_t> sizes;
  for (const ScalingRow& r : rows) {
    if (std::find(plan.algorithms.begin(), plan.algorithms.end(), r.algorithm) == plan.algorithms.end())
      plan.algorithms.push_back(r.algorithm);
    if (const auto layout = parse_layout(r.layout);
        layout && std::find(plan.layouts.begin(), plan.layouts.end(), *layout) == plan.layouts.end())
      plan.layouts.push_back(*layout);
    plan.n_min = std::min(plan.n_min, r.n);
    plan.n_max = std::max(plan.n_max, r.n);
    if (std::find(sizes.begin(), sizes.end(), r.n) == sizes.end()) sizes.push_back(r.n);
    if (std::find(plan.threads.begin(), plan.threads.end(), r.threads) == plan.threads.end()) plan.threads.push_back(r.threads);
  }
  std::sort(plan.threads.begin(), plan.threads.end());
  const double decades = std::log10(static_cast<double>(plan.n_max) / static_cast<double>(plan.n_min));
  plan.points_per_decade =
      decades > 0 ? std::max(1, static_cast<int>(std::lround(static_cast<double>(sizes.size() - 1) / decades))) : 1;
  return plan;
}

ScalingResult run_scaling(const ScalingPlan& plan, const std::function<void(const ScalingProgress&)>& progress,
                          const std::atomic<bool>* cancel) {
  check_scaling_plan(plan);
  const std::vector<std::int64_t> sizes = scaling_sizes(plan.n_min, plan.n_max, plan.points_per_decade);
  const std::vector<Series> series = series_of(plan);
  ScalingResult result;
  ScalingProgress p;
  p.total = series.size() * plan.layouts.size() * sizes.size();
  const auto report = [&](const std::string& point, const ScalingRow* row, const std::string& note) {
    ++p.done;
    p.point = point;
    p.row = row;
    p.note = note;
    if (!note.empty()) result.notes.push_back(point + ": " + note);
    if (progress) progress(p);
  };
  for (Layout layout : plan.layouts) {
    // Per series: its last measured N in this layout and the seconds of its best run there.
    std::vector<std::pair<std::int64_t, double>> last(series.size(), {0, 0.0});
    for (std::int64_t n : sizes) {
      if (cancelled(cancel)) {
        result.cancelled = true;
        return result;
      }
      const Elements elements = make_layout(layout, n, 2, plan.seed);  // once for every detector
      for (std::size_t a = 0; a < series.size(); ++a) {
        const std::string& name = series[a].algorithm;
        DetectOptions options;
        options.threads = series[a].threads;
        options.touching = plan.touching;
        const std::string point = point_name(series_name(name, options.threads), layout, n);
        if (name == "brute" && n > plan.brute_max_n) {
          report(point, nullptr, "skipped: brute force is capped at N <= " + std::to_string(plan.brute_max_n));
          continue;
        }
        if (last[a].first == 0 && n > kPilotN) {
          // A first point past the pilot size: one timed run at the pilot size, so that even the
          // first point is projected (box2d at 1e6 would otherwise run for a minute, uncancellable).
          try {
            const Elements pilot = make_layout(layout, kPilotN, 2, plan.seed);
            PairList pairs;
            const auto t0 = std::chrono::steady_clock::now();
            const std::unique_ptr<Detector> pilot_detector = make_detector(name);
            pilot_detector->detect(pilot, options, pairs);
            throw_if_misbehaved(*pilot_detector);
            last[a] = {kPilotN, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
          } catch (const PluginError&) {
            throw;  // a plugin that breaks the API ends the run, as in every command (docs/plugins.md)
          } catch (const DetectorBug&) {
            throw;  // as does its own bug
          } catch (const Error&) {
            // the point itself reports what is wrong
          }
        }
        if (const auto [last_n, last_s] = last[a]; last_n > 0) {
          const double projected = last_s * static_cast<double>(n) / static_cast<double>(last_n);
          if (projected > plan.max_run_seconds) {
            char why[200];
            std::snprintf(why, sizeof why, "skipped: one run at N=%lld took %.2f s, so here it would take over %.2f s (limit %.2f s)",
                          static_cast<long long>(last_n), last_s, projected, plan.max_run_seconds);
            report(point, nullptr, why);
            continue;
          }
        }
        ScalingRow row{name, layout_name(layout), n, 0, 0, 0, 0, options.threads};
        try {
          // A fresh detector per point: one kept across points keeps the arrays of the biggest run
          // before it, and its bytes per element would be that run's, not this point's own need.
          const std::unique_ptr<Detector> detector = make_detector(name);
          if (!measure(*detector, elements, plan, cancel, row)) {
            result.cancelled = true;
            return result;
          }
        } catch (const PluginError&) {
          throw;  // not a point to skip: the plugin broke the API
        } catch (const DetectorBug&) {
          throw;  // nor is a detector's own bug
        } catch (const Error& e) {  // e.g. screen's array past its memory limit on a sparse world
          report(point, nullptr, std::string("skipped: ") + e.what());
          continue;
        }
        last[a] = {n, row.ns_per_element * static_cast<double>(n) * 1e-9};
        result.rows.push_back(row);
        report(point, &result.rows.back(), "");
        if (cancelled(cancel)) {
          result.cancelled = true;
          return result;
        }
      }
    }
  }
  return result;
}

}  // namespace nbscope

#include "app/scaling_flags.hpp"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <chrono>
#include <cstdio>

#include "core/detector.hpp"
#include "core/error.hpp"
#include "io/plural.hpp"
#include "io/scaling_csv.hpp"

namespace nbscope {

namespace {

// A whole number ("4000") or a power of ten ("1e5"); nullopt otherwise.
std::optional<std::int64_t> parse_size_value(std::string_view text) {
  double v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v)) return std::nullopt;
  if (v != std::floor(v) || v < 1 || v > static_cast<double>(kMaxScalingN)) return std::nullopt;
  return static_cast<std::int64_t>(v);
}

// "1000", "31623", "1e6" as the table shows N.
std::string n_text(std::int64_t n) { return std::to_string(n); }

}  // namespace

std::vector<std::string> parse_scaling_algorithms(const std::string& flag, const std::string& text) {
  std::vector<std::string> names;
  if (text == "all") {
    for (const DetectorInfo& d : detector_infos())
      if (d.dim2) names.push_back(d.name);
    return names;
  }
  names = split_names(flag, text);
  for (const std::string& name : names) {
    try {
      if (!detector_info(name).dim2) throw Error(name + " does not handle 2D elements");
    } catch (const Error& e) {
      throw Error(flag + ": " + e.what());
    }
  }
  return names;
}

std::vector<Layout> parse_scaling_layouts(const std::string& flag, const std::string& text) {
  std::vector<Layout> layouts;
  for (const std::string& name : split_names(flag, text)) {
    const auto layout = parse_layout(name);
    const auto& offered = scaling_layouts();
    if (!layout || std::find(offered.begin(), offered.end(), *layout) == offered.end()) {
      std::string known;
      for (Layout l : offered) known += (known.empty() ? "" : ", ") + layout_name(l);
      throw Error(flag + ": '" + name + "' is not one of " + known);
    }
    layouts.push_back(*layout);
  }
  return layouts;
}

void parse_n_range(const std::string& flag, const std::string& text, std::int64_t& out_min, std::int64_t& out_max) {
  const std::size_t dots = text.find("..");
  const auto lo = parse_size_value(text.substr(0, dots));
  const auto hi = dots == std::string::npos ? lo : parse_size_value(text.substr(dots + 2));
  if (!lo || !hi)
    throw Error(flag + ": '" + text + "' is not MIN..MAX (whole numbers or powers like 1e5, from 1 to " +
                std::to_string(kMaxScalingN) + ")");
  if (*hi < *lo) throw Error(flag + ": '" + text + "' goes down: MAX must be at least MIN");
  out_min = *lo;
  out_max = *hi;
}

ScalingPlan take_scaling_plan_flags(Args& args, const std::string& algorithms, int threads, bool* given) {
  ScalingPlan plan;
  plan.algorithms = parse_scaling_algorithms("--algorithm", algorithms);
  plan.threads = scaling_threads(threads);
  const auto layouts = args.value("--layout");
  if (layouts) plan.layouts = parse_scaling_layouts("--layout", *layouts);
  plan.n_max = 1'000'000;
  const auto range = args.value("--n");
  if (range) parse_n_range("--n", *range, plan.n_min, plan.n_max);
  const auto per_decade = args.integer("--points-per-decade");
  plan.points_per_decade = static_cast<int>(per_decade.value_or(plan.points_per_decade));
  if (given != nullptr) *given = layouts || range || per_decade;
  return plan;
}

ScalingResult run_scaling_in_terminal(const ScalingPlan& plan, bool bar) {
  int last = -1;
  const auto erase = [&] {
    if (last >= 0) std::fputs("\r\033[K", stderr);
    last = -1;
  };
  ScalingResult result;
  try {
    result = run_scaling(
        plan,
        [&](const ScalingProgress& p) {
          if (!bar) return;
          const int width = 30;
          last = static_cast<int>(width * p.done / std::max<std::size_t>(p.total, 1));
          std::fprintf(stderr, "\r\033[K[%.*s%*s] %zu/%zu %s", last, "==============================", width - last, "", p.done,
                       p.total, p.point.c_str());
          std::fflush(stderr);
        },
        nullptr);
  } catch (...) {
    erase();
    throw;
  }
  erase();
  return result;
}

std::string scaling_table(const ScalingResult& result) {
  std::string out;
  char line[200];
  std::snprintf(line, sizeof line, "%-9s %-13s %10s %14s %14s %12s %8s %8s\n", "algorithm", "layout", "n", "ns/element", "bytes/element",
                "pairs", "repeats", "threads");
  out += line;
  for (const ScalingRow& r : result.rows) {
    std::snprintf(line, sizeof line, "%-9s %-13s %10s %14.2f %14.2f %12lld %8d %8d\n", r.algorithm.c_str(), r.layout.c_str(),
                  n_text(r.n).c_str(), r.ns_per_element, r.bytes_per_element, static_cast<long long>(r.pairs), r.repeats, r.threads);
    out += line;
  }
  for (const std::string& note : result.notes) out += "note: " + note + "\n";
  return out;
}

void check_headless_scaling(const std::string& spec, const ViewOptions& view) {
  if (spec.empty()) throw Error("--scaling: expected a CSV of nbscope scaling, or run");
  if (!view.screenshot) throw Error("--scaling: needs --screenshot (headless draws nothing without one)");
}

ScalingShown scaling_to_show(const std::string& spec, const ScalingPlan& plan, bool bar) {
  ScalingShown shown;
  if (spec == "run") {
    check_scaling_plan(plan);
    const auto t0 = std::chrono::steady_clock::now();
    shown.result = run_scaling_in_terminal(plan, bar);
    shown.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    shown.plan = plan;
    return shown;
  }
  shown.result.rows = read_scaling_csv(spec);
  shown.plan = plan_covering(shown.result.rows);
  shown.source = spec;
  return shown;
}

}  // namespace nbscope

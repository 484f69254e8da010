// nbscope core: scaling runs — how a detector's time and memory per element grow with N. For each
// (detector, layout, N) of a plan the elements are generated once per (layout, N), detect() runs a
// few times (best time kept), and one row reports ns per element, bytes per element and pairs.
// Used by `nbscope scaling` and by the Scaling panel's background run.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/layouts.hpp"
#include "core/pairs.hpp"

namespace nbscope {

// What to run. Every point is time-bounded: repeats stop after `min_seconds`, and never start
// when they would go past `max_seconds` (at least one timed run always happens); a point whose
// one run would pass `max_run_seconds` is skipped.
struct ScalingPlan {
  std::vector<std::string> algorithms = {"nbs", "sort"};
  std::vector<Layout> layouts = {Layout::Loose};
  std::int64_t n_min = 1'000;
  std::int64_t n_max = 100'000;
  int points_per_decade = 2;
  std::int64_t brute_max_n = 10'000;  // brute force (N^2/2 tests) is skipped above this N
  double min_seconds = 0.05;          // repeat a point until its runs took this long...
  double max_seconds = 0.2;           // ...but not past this
  int max_repeats = 200;
  // A detector is skipped at an N where one run would take longer than this, judged from its last
  // run at a smaller N of the same layout (time at least linear in N): no single point can stall
  // the plan (box2d's tree at 1e6 takes a minute here).
  double max_run_seconds = 2.0;
  std::uint64_t seed = 1;
  // The thread counts compared (DetectOptions::threads), each from 1 to kMaxThreads, none twice: a
  // detector that uses threads (DetectorInfo::uses_threads) is measured at each, the others once at 1.
  std::vector<int> threads = {1};
  Touching touching = Touching::inclusive;  // the contact test timed (--touching; pairs differ only at exact ties)
};

// One measured point.
struct ScalingRow {
  std::string algorithm;
  std::string layout;  // layout_name()
  std::int64_t n = 0;
  double ns_per_element = 0;     // the best run's detection time / N, to a thousandth
  double bytes_per_element = 0;  // Detector::own_bytes() / N, to a thousandth
  std::int64_t pairs = 0;
  int repeats = 0;  // timed runs of detect()
  int threads = 1;  // DetectOptions::threads of the runs
  friend bool operator==(const ScalingRow&, const ScalingRow&) = default;
};

// Progress after each point (measured, skipped or failed).
struct ScalingProgress {
  std::size_t done = 0, total = 0;
  std::string point;               // "nbs loose N=1000" ("nbs x2 loose N=1000" on 2 threads)
  const ScalingRow* row = nullptr;  // the point's row; null when it was skipped
  std::string note;                 // why it was skipped ("" when measured)
};

struct ScalingResult {
  std::vector<ScalingRow> rows;    // by layout, then N, then algorithm in plan order, then threads
  std::vector<std::string> notes;  // what was skipped and why, one line each
  bool cancelled = false;
};

// The thread counts a plan compares for --threads N: {1, N}, or {1} when N is 1.
std::vector<int> scaling_threads(int n);
// The thread counts `algorithm` is measured at under `plan`: the plan's when it uses threads, else {1}.
std::vector<int> threads_measured(const ScalingPlan& plan, const std::string& algorithm);
// A series' name in tables and plots: "nbs" on one thread, "nbs x2" on two.
std::string series_name(const std::string& algorithm, int threads);

// The layouts a scaling run offers: those whose contacts grow linearly with N (one_cell and
// one_point have N^2/2 pairs; cell_borders is a rounding test, not a workload).
const std::vector<Layout>& scaling_layouts();
// The sizes of a plan: n_min, then `points_per_decade` points per decade on a log scale (rounded
// to whole numbers, duplicates dropped), up to n_max (always included).
std::vector<std::int64_t> scaling_sizes(std::int64_t n_min, std::int64_t n_max, int points_per_decade);
// The number of (detector, threads, layout, N) points of `plan`, skipped ones included.
std::size_t scaling_point_count(const ScalingPlan& plan);
// Error naming what is wrong with `plan` (unknown detector, a 3D-only one, an empty list, a layout
// not in scaling_layouts(), a bad range, a thread count out of range or repeated); nothing when it can run.
void check_scaling_plan(const ScalingPlan& plan);
// The plan that `rows` (e.g. read from a CSV) measure: their detectors, layouts and thread counts
// (ascending) in the order they first appear, their smallest and largest N, their sizes per decade (rounded).
ScalingPlan plan_covering(const std::vector<ScalingRow>& rows);
// Runs `plan` (check_scaling_plan first). `progress` (may be empty) is called after every point;
// `cancel` (may be null) is read between runs of detect() and stops the run when set. A point a
// detector cannot run is skipped with a note; a plugin's PluginError ends the run (it is thrown).
ScalingResult run_scaling(const ScalingPlan& plan, const std::function<void(const ScalingProgress&)>& progress,
                          const std::atomic<bool>* cancel);

}  // namespace nbscope

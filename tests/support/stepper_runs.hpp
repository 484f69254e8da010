// nbscope tests: the stepper's traced runs, shared by the stepper's test files: one traced detection
// of a generated set, the traced runs of every list-based detector of the registry (every dimension
// it supports, several layouts and sizes), and a hand-written trace of two pushes onto one list.
#pragma once
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "core/detector.hpp"
#include "core/trace.hpp"
#include "support/generators.hpp"

namespace nbscope::teststepper {

using testdata::Layout;

// One traced detection of a generated set.
struct TracedRun {
  std::string what;  // "nbs 2D dense n=40 seed=3", for failure messages
  Elements elements;
  Grid grid;
  bool has_grid = false;
  TraceLog log;
};

// Traced runs of every registered detector whose trace declares arrays (the list-based ones),
// in every dimension it supports, on small sets of several layouts.
inline std::vector<TracedRun> list_based_runs(std::int64_t n_max) {
  std::vector<TracedRun> out;
  const std::vector<Layout> layouts = {Layout::Loose, Layout::Dense, Layout::Clustered, Layout::OneCell,
                                       Layout::Touching, Layout::UnequalRadii};
  for (const DetectorInfo& info : detector_infos()) {
    for (int dim : {2, 3}) {
      if ((dim == 2 && !info.dim2) || (dim == 3 && !info.dim3)) continue;
      std::uint64_t seed = 1;
      for (Layout layout : layouts) {
        for (std::int64_t n : {std::int64_t{0}, std::int64_t{1}, std::int64_t{7}, n_max}) {
          TracedRun run;
          run.elements = testdata::make_layout(layout, n, dim, seed++);
          auto detector = info.make();
          PairList pairs;
          detector->detect_traced(run.elements, DetectOptions{}, pairs, run.log);
          if (run.log.arrays().empty()) break;  // not list-based (brute): nothing to step through
          if (const Grid* g = detector->last_grid()) {
            run.grid = *g;
            run.has_grid = true;
          }
          run.what = info.name + " " + std::to_string(dim) + "D " + testdata::layout_name(layout) +
                     " n=" + std::to_string(n) + " seed=" + std::to_string(seed - 1);
          out.push_back(std::move(run));
        }
      }
    }
  }
  return out;
}

// The detectors the runs are of, in order, each once.
inline std::vector<std::string> names_of(const std::vector<TracedRun>& runs) {
  std::vector<std::string> names;
  for (const TracedRun& r : runs) {
    const std::string name = r.what.substr(0, r.what.find(' '));
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

// Two elements pushed onto list 1 of C (heads) through E (next); the second push records
// `recorded_old_head_of_second` as the head it replaced (the true old head is 0).
inline TraceLog two_pushes(std::int32_t recorded_old_head_of_second) {
  TraceLog log;
  const std::vector<std::int32_t> heads(3, -1), next(4, -1);
  const int h = log.declare_array("C", {3}, heads);
  const int e = log.declare_array("E", {4}, next);
  log.phase(0, "lists", -1);
  log.push(1, "list", h, 1, e, 0, -1, -1, 1, 0, -1);
  log.push(1, "list", h, 1, e, 2, recorded_old_head_of_second, -1, 1, 0, -1);  // true old head: 0
  return log;
}

}  // namespace nbscope::teststepper

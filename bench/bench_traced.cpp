// nbscope_bench: BM_DetectTraced/<algorithm>/<layout>/<N> — the same detections as BM_Detect, but
// through detect_traced() into a TraceLog (every book operation recorded, as the stepper needs it).
// Set beside BM_Detect, they show what tracing costs when on; BM_TraceOff (bench_trace_off.cpp)
// shows that it costs nothing when off.
// Counters: ns_per_element, events (trace events of one run), bytes_per_event.
#include <benchmark/benchmark.h>

#include <string>

#include "core/detector.hpp"
#include "support/generators.hpp"

namespace nbscope {
namespace {

using testdata::Layout;

void bm_detect_traced(benchmark::State& state, std::string algorithm, Layout layout, std::int64_t n, int dim) {
  const Elements e = testdata::make_layout(layout, n, dim, 42);  // the seed of BM_Detect
  auto detector = make_detector(algorithm);
  PairList pairs;
  TraceLog log;
  for (auto _ : state) {
    detector->detect_traced(e, DetectOptions{}, pairs, log);
    benchmark::DoNotOptimize(log.events().data());
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_element"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["events"] = static_cast<double>(log.events().size());
  state.counters["pairs"] = static_cast<double>(pairs.size());
}

// Registered at start-up, beside bench_detect.cpp's BM_Detect. Only N <= 1e4: a traced run keeps
// every event (~90 bytes each, tens per element), which is what the stepper shows for one frame.
const bool registered = [] {
  for (const DetectorInfo& info : detector_infos()) {
    if (info.name == "brute") continue;  // not list-based: its trace is one event per pair
    for (int dim : {2, 3}) {
      if ((dim == 2 && !info.dim2) || (dim == 3 && !info.dim3)) continue;
      for (Layout layout : {Layout::Loose, Layout::Dense}) {
        for (std::int64_t n : {1'000, 10'000}) {
          const std::string name = "BM_DetectTraced/" + info.name + (dim == 3 ? "3d" : "") + "/" +
                                   testdata::layout_name(layout) + "/" + std::to_string(n);
          benchmark::RegisterBenchmark(name.c_str(), bm_detect_traced, info.name, layout, n, dim)
              ->Unit(benchmark::kMillisecond);
        }
      }
    }
  }
  return true;
}();

}  // namespace
}  // namespace nbscope

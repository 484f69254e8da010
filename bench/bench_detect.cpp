// nbscope_bench: BM_Detect/<algorithm>/<layout>/<N> for every registered detector.
// Counters: ns_per_element, pairs, bytes_per_element (the detector's own arrays).
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>

#include "bench_trace_off.hpp"
#include "core/detector.hpp"
#include "core/nbs.hpp"
#include "support/generators.hpp"

namespace nbscope {
namespace {

using testdata::Layout;

// Generated once per (layout, N, dim) and shared by every algorithm.
const Elements& cached_layout(Layout layout, std::int64_t n, int dim) {
  static std::map<std::tuple<int, std::int64_t, int>, std::unique_ptr<Elements>> cache;
  auto& slot = cache[{static_cast<int>(layout), n, dim}];
  if (!slot) slot = std::make_unique<Elements>(testdata::make_layout(layout, n, dim, 42));
  return *slot;
}

// The counters of BM_Detect: ns_per_element, pairs, bytes_per_element (the detector's own arrays).
void set_detect_counters(benchmark::State& state, std::int64_t n, std::size_t pairs, std::size_t bytes) {
  state.counters["ns_per_element"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["pairs"] = static_cast<double>(pairs);
  state.counters["bytes_per_element"] = static_cast<double>(bytes) / static_cast<double>(n);
}

void bm_detect(benchmark::State& state, std::string algorithm, Layout layout, std::int64_t n, int dim) {
  const Elements& e = cached_layout(layout, n, dim);
  auto detector = make_detector(algorithm);
  PairList pairs;
  for (auto _ : state) {
    detector->detect(e, DetectOptions{}, pairs);
    benchmark::DoNotOptimize(pairs.data());
    benchmark::ClobberMemory();
  }
  set_detect_counters(state, n, pairs.size(), detector->own_bytes());
}

// The book's loops as written (NbsDetector::detect_book), beside BM_Detect/nbs (the fast path), so
// that one run gives the ratio of the two on identical inputs.
void bm_nbs_book(benchmark::State& state, Layout layout, std::int64_t n, int dim) {
  const Elements& e = cached_layout(layout, n, dim);
  NbsDetector detector;
  PairList pairs;
  for (auto _ : state) {
    detector.detect_book(e, DetectOptions{}, pairs);
    benchmark::DoNotOptimize(pairs.data());
    benchmark::ClobberMemory();
  }
  set_detect_counters(state, n, pairs.size(), detector.book_bytes());
}

void register_detect_benchmarks() {
  const Layout layouts[] = {Layout::Loose, Layout::Dense, Layout::Clustered};
  for (const DetectorInfo& info : detector_infos()) {
    for (int dim : {2, 3}) {
      if ((dim == 2 && !info.dim2) || (dim == 3 && !info.dim3)) continue;
      for (Layout layout : layouts) {
        for (std::int64_t n : {1'000, 10'000, 100'000, 1'000'000}) {
          if (info.name == "brute" && n > 10'000) continue;
          const std::string name = "BM_Detect/" + info.name + (dim == 3 ? "3d" : "") + "/" +
                                   testdata::layout_name(layout) + "/" + std::to_string(n);
          benchmark::RegisterBenchmark(name.c_str(), bm_detect, info.name, layout, n, dim)->Unit(benchmark::kMillisecond);
          if (info.name == "nbs") {
            const std::string book = "BM_Detect/nbs_book" + std::string(dim == 3 ? "3d" : "") + "/" +
                                     testdata::layout_name(layout) + "/" + std::to_string(n);
            benchmark::RegisterBenchmark(book.c_str(), bm_nbs_book, layout, n, dim)->Unit(benchmark::kMillisecond);
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace nbscope

int main(int argc, char** argv) {
  if (!nbscope::trace_off_control_agrees()) return 1;
  nbscope::register_detect_benchmarks();
  nbscope::register_trace_off_benchmarks();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

// nbscope_bench: BM_Detect/<algorithm>/<layout>/<N> for every registered detector; nbs and nbs3d also
// on threads (BM_Detect/nbs/<layout>/<N>/t<T>) and, loose and dense, at N = 1e7 (1 and 2 threads).
// Counters: ns_per_element, pairs, bytes_per_element (the detector's own arrays), threads; nbs also
// moved_bytes_per_element (NbsDetector::moved_bytes_per_element, from its packed layout).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "bench_trace_off.hpp"
#include "core/detector.hpp"
#include "core/nbs.hpp"
#include "core/threads.hpp"
#include "support/generators.hpp"

namespace nbscope {
namespace {

using testdata::Layout;

// The largest N, run by nbs alone (loose and dense, 1 and 2 threads): linearity from 1e4 to 1e7.
constexpr std::int64_t kHugeN = 10'000'000;

// Generated once per (layout, N, dim) and shared by every algorithm. Sets of 1e7 (~300 MB in 3D)
// are kept one at a time: their benchmarks are registered next to each other.
const Elements& cached_layout(Layout layout, std::int64_t n, int dim) {
  static std::map<std::tuple<int, std::int64_t, int>, std::unique_ptr<Elements>> cache;
  static std::tuple<int, std::int64_t, int> huge_key;
  static std::unique_ptr<Elements> huge;
  const std::tuple<int, std::int64_t, int> key{static_cast<int>(layout), n, dim};
  if (n >= kHugeN) {
    if (!huge || huge_key != key) {
      huge.reset();
      huge = std::make_unique<Elements>(testdata::make_layout(layout, n, dim, 42));
      huge_key = key;
    }
    return *huge;
  }
  auto& slot = cache[key];
  if (!slot) slot = std::make_unique<Elements>(testdata::make_layout(layout, n, dim, 42));
  return *slot;
}

// The counters of BM_Detect: ns_per_element (wall: on threads the main thread's CPU time, which
// Google Benchmark's rates use, would leave the bands' work out; UseRealTime would rename the rows),
// pairs, bytes_per_element (the detector's own arrays).
void set_detect_counters(benchmark::State& state, std::int64_t n, double wall_seconds, std::size_t pairs,
                         std::size_t bytes) {
  // Seconds per element, as an inverted rate stores it (scripts/bench_table.py reads both alike).
  const double iterations = static_cast<double>(std::max<benchmark::IterationCount>(state.iterations(), 1));
  state.counters["ns_per_element"] = wall_seconds / (iterations * static_cast<double>(n));
  state.counters["pairs"] = static_cast<double>(pairs);
  state.counters["bytes_per_element"] = static_cast<double>(bytes) / static_cast<double>(n);
}

// Wall seconds since `start`.
double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void bm_detect(benchmark::State& state, std::string algorithm, Layout layout, std::int64_t n, int dim, int threads) {
  const Elements& e = cached_layout(layout, n, dim);
  auto detector = make_detector(algorithm);
  DetectOptions options;
  options.threads = threads;
  PairList pairs;
  // One detection first, untimed: a simulation detects every frame with arrays already sized and
  // its threads started, and the first call's page faults are not the detector's per-frame cost.
  detector->detect(e, options, pairs);
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    detector->detect(e, options, pairs);
    benchmark::DoNotOptimize(pairs.data());
    benchmark::ClobberMemory();
  }
  set_detect_counters(state, n, seconds_since(start), pairs.size(), detector->own_bytes());
  state.counters["threads"] = threads;
  if (algorithm == "nbs")
    state.counters["moved_bytes_per_element"] = static_cast<double>(NbsDetector::moved_bytes_per_element(dim));
}

// The thread counts nbs is measured on besides 1: 2, and the machine's threads when more.
std::vector<int> nbs_thread_counts() {
  std::vector<int> counts{2};
  if (machine_threads() > 2) counts.push_back(machine_threads());
  return counts;
}

// BM_Detect/<name>/<layout>/<N>, with /t<T> when T > 1.
std::string detect_name(const std::string& name, int dim, Layout layout, std::int64_t n, int threads) {
  return "BM_Detect/" + name + (dim == 3 ? "3d" : "") + "/" + testdata::layout_name(layout) + "/" + std::to_string(n) +
         (threads > 1 ? "/t" + std::to_string(threads) : "");
}

// The book's loops as written (NbsDetector::detect_book), beside BM_Detect/nbs (the fast path), so
// that one run gives the ratio of the two on identical inputs.
void bm_nbs_book(benchmark::State& state, Layout layout, std::int64_t n, int dim) {
  const Elements& e = cached_layout(layout, n, dim);
  NbsDetector detector;
  PairList pairs;
  detector.detect_book(e, DetectOptions{}, pairs);  // untimed, as in bm_detect
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) {
    detector.detect_book(e, DetectOptions{}, pairs);
    benchmark::DoNotOptimize(pairs.data());
    benchmark::ClobberMemory();
  }
  set_detect_counters(state, n, seconds_since(start), pairs.size(), detector.book_bytes());
}

void register_detect_benchmarks() {
  const Layout layouts[] = {Layout::Loose, Layout::Dense, Layout::Clustered};
  for (const DetectorInfo& info : detector_infos()) {
    for (int dim : {2, 3}) {
      if ((dim == 2 && !info.dim2) || (dim == 3 && !info.dim3)) continue;
      for (Layout layout : layouts) {
        for (const std::int64_t n : {std::int64_t{1'000}, std::int64_t{10'000}, std::int64_t{100'000},
                                     std::int64_t{1'000'000}, kHugeN}) {
          if (info.name == "brute" && n > 10'000) continue;
          if (n == kHugeN && (info.name != "nbs" || layout == Layout::Clustered)) continue;
          const std::string name = detect_name(info.name, dim, layout, n, 1);
          benchmark::RegisterBenchmark(name.c_str(), bm_detect, info.name, layout, n, dim, 1)
              ->Unit(benchmark::kMillisecond);
          if (info.name != "nbs") continue;
          for (int threads : nbs_thread_counts()) {
            if (n == kHugeN && threads != 2) continue;
            const std::string banded = detect_name(info.name, dim, layout, n, threads);
            benchmark::RegisterBenchmark(banded.c_str(), bm_detect, info.name, layout, n, dim, threads)
                ->Unit(benchmark::kMillisecond);
          }
          if (n < kHugeN) {
            const std::string book = "BM_Detect/nbs_book" + std::string(dim == 3 ? "3d" : "") + "/" +
                                     testdata::layout_name(layout) + "/" + std::to_string(n);
            benchmark::RegisterBenchmark(book.c_str(), bm_nbs_book, layout, n, dim)
                ->Unit(benchmark::kMillisecond);
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

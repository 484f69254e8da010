// nbscope_bench: BM_PluginVsBook/<plugin|book>/<layout>/<N> — the example plugin nbs_reference.so
// (examples/detectors/, loaded as --detector-lib loads it) against the built-in book loops it copies
// (NbsDetector::detect_book), untraced, on the same frames. The plugin pays a call through a C
// function pointer for every pair and writes its cells; the book loops append to a vector. Target:
// plugin within 1.3x of book. Counters as BM_Detect: ns_per_element, pairs.
//
// BM_PluginIsolation/<none|process>/<untraced|traced>/<N> — the same plugin called in nbscope's process
// and in a host process of its own (io/plugin_host.hpp, the default): what isolation costs a frame,
// the frame and the pairs (and the trace) copied through a socket. docs/plugins.md "Isolation" quotes it.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>

#include "core/nbs.hpp"
#include "core/pair_scan.hpp"
#include "core/plugin_detector.hpp"
#include "io/plugin_host.hpp"
#include "io/plugin_library.hpp"
#include "support/generators.hpp"

namespace nbscope {
namespace {

using testdata::Layout;

const Elements& plugin_layout(Layout layout, std::int64_t n) {
  static std::map<std::pair<int, std::int64_t>, std::unique_ptr<Elements>> cache;
  auto& slot = cache[{static_cast<int>(layout), n}];
  if (!slot) slot = std::make_unique<Elements>(testdata::make_layout(layout, n, 2, 42));
  return *slot;
}

// The reference plugin's detector, in nbscope's process (loaded on first use), or null when the library is missing.
std::unique_ptr<Detector> reference_plugin() {
  static const std::string name = [] {
    try {
      set_plugin_isolation(PluginIsolation::none);
      return load_detector_plugin(NBSCOPE_EXAMPLES_DIR "/nbs_reference.so");
    } catch (const std::exception&) {
      return std::string();
    }
  }();
  return name.empty() ? nullptr : make_detector(name);
}

void bm_plugin_vs_book(benchmark::State& state, bool plugin, Layout layout, std::int64_t n) {
  const Elements& e = plugin_layout(layout, n);
  std::unique_ptr<Detector> detector = plugin ? reference_plugin() : nullptr;
  if (plugin && !detector) {
    state.SkipWithError("examples/detectors/nbs_reference.so is not built");
    return;
  }
  NbsDetector book;
  PairList pairs;
  for (auto _ : state) {
    if (plugin) detector->detect(e, DetectOptions{}, pairs);
    else book.detect_book(e, DetectOptions{}, pairs);
    benchmark::DoNotOptimize(pairs.data());
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_element"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["pairs"] = static_cast<double>(pairs.size());
}

// One plugin detection, in-process or isolated, untraced or traced.
void bm_plugin_isolation(benchmark::State& state, bool isolated, bool traced, std::int64_t n) {
  const Elements& e = plugin_layout(Layout::Dense, n);
  std::unique_ptr<Detector> detector = reference_plugin();
  if (!detector) {
    state.SkipWithError("examples/detectors/nbs_reference.so is not built");
    return;
  }
  if (isolated) {
    const auto* plugin = dynamic_cast<const PluginDetector*>(detector.get());
    detector = std::make_unique<IsolatedPluginDetector>(NBSCOPE_EXAMPLES_DIR "/nbs_reference.so", plugin->description(), 0);
  }
  PairList pairs;
  TraceLog trace;
  for (auto _ : state) {
    if (traced) detector->detect_traced(e, DetectOptions{}, pairs, trace);
    else detector->detect(e, DetectOptions{}, pairs);
    benchmark::DoNotOptimize(pairs.data());
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_element"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["pairs"] = static_cast<double>(pairs.size());
}

// The checks of a plugin's pairs after its call (scan_pairs: range, order, repeats) on the pairs the
// book loops find, as the plugin gives them.
void bm_scan_pairs(benchmark::State& state, Layout layout, std::int64_t n) {
  const Elements& e = plugin_layout(layout, n);
  NbsDetector book;
  PairList given;
  book.detect_book(e, DetectOptions{}, given);
  PairList pairs;
  PairScanScratch scratch;
  for (auto _ : state) {
    pairs = given;
    const PairScan scan = scan_pairs(pairs, n, scratch);
    benchmark::DoNotOptimize(scan);
  }
  state.counters["ns_per_pair"] =
      benchmark::Counter(static_cast<double>(given.size()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

[[maybe_unused]] const bool registered = [] {
  for (const bool plugin : {false, true})
    for (const Layout layout : {Layout::Dense, Layout::Clustered})
      for (const std::int64_t n : {1'000, 10'000, 100'000}) {
        const std::string name = std::string("BM_PluginVsBook/") + (plugin ? "plugin/" : "book/") + testdata::layout_name(layout) + "/" + std::to_string(n);
        benchmark::RegisterBenchmark(name.c_str(), bm_plugin_vs_book, plugin, layout, n)->Unit(benchmark::kMicrosecond);
      }
  for (const bool traced : {false, true})
    for (const bool isolated : {false, true})
      for (const std::int64_t n : {1'000, 100'000, 1'000'000}) {
        const std::string name = std::string("BM_PluginIsolation/") + (isolated ? "process/" : "none/") + (traced ? "traced/" : "untraced/") + std::to_string(n);
        benchmark::RegisterBenchmark(name.c_str(), bm_plugin_isolation, isolated, traced, n)->Unit(benchmark::kMicrosecond);
      }
  for (const Layout layout : {Layout::Dense, Layout::Clustered})
    for (const std::int64_t n : {1000, 100000}) {
      const std::string name = std::string("BM_ScanPairs/") + testdata::layout_name(layout) + "/" + std::to_string(n);
      benchmark::RegisterBenchmark(name.c_str(), bm_scan_pairs, layout, n)->Unit(benchmark::kMicrosecond);
    }
  return true;
}();

}  // namespace
}  // namespace nbscope

// nbscope_bench: BM_Box2DBroadphase/<layout>/<N>/<small|large> — Box2D 2.4.1's b2BroadPhase as a
// physics engine pays for it each frame: every proxy moved (MoveProxy with its displacement), then
// UpdatePairs reporting the new fat-AABB pairs. `small` motion stays inside the fat AABBs (Box2D's
// best case: nothing is re-inserted); `large` motion leaves them every frame (every proxy
// re-inserted and queried). N runs from 1e3 to 1e6 (large motion to 1e5: at 1e6 one frame takes
// tens of seconds). Counters as BM_Detect: ns_per_element, pairs (new pairs reported in the last
// frame), bytes_per_element (the tree's nodes, about 2N of them).
//
// This file also registers physics' detectors, so BM_Detect covers `box2d` as well.
#include <benchmark/benchmark.h>
#include <box2d/box2d.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "physics/box2d_detector.hpp"
#include "support/generators.hpp"

namespace nbscope {
namespace {

using testdata::Layout;

// Shared by every motion of one (layout, N).
const Elements& box2d_layout(Layout layout, std::int64_t n) {
  static std::map<std::pair<int, std::int64_t>, std::unique_ptr<Elements>> cache;
  auto& slot = cache[{static_cast<int>(layout), n}];
  if (!slot) slot = std::make_unique<Elements>(testdata::make_layout(layout, n, 2, 42));
  return *slot;
}

b2AABB circle_box(const Elements& e, std::int64_t k, double dx) {
  b2AABB box;
  box.lowerBound.Set(static_cast<float>(e.x[k] + dx - e.r[k]), static_cast<float>(e.y[k] - e.r[k]));
  box.upperBound.Set(static_cast<float>(e.x[k] + dx + e.r[k]), static_cast<float>(e.y[k] + e.r[k]));
  return box;
}

// Counts what UpdatePairs reports (Box2D calls AddPair for each new pair).
struct PairCounter {
  std::int64_t pairs = 0;
  void AddPair(void*, void*) { ++pairs; }
};

void bm_box2d_broadphase(benchmark::State& state, Layout layout, std::int64_t n, bool large) {
  const Elements& e = box2d_layout(layout, n);
  b2BroadPhase bp;
  std::vector<std::int32_t> proxies(static_cast<std::size_t>(n));
  for (std::int64_t k = 0; k < n; ++k) proxies[static_cast<std::size_t>(k)] = bp.CreateProxy(circle_box(e, k, 0), nullptr);
  PairCounter counter;
  bp.UpdatePairs(&counter);  // the initial pairs, outside the timing

  // Back and forth along x: 0.02 m stays inside the 0.1 m margin; 0.25 m always leaves it (the fat
  // AABB grows by 4x the displacement ahead of the motion, and the next frame goes the other way).
  const double step = large ? 0.25 : 0.02;
  double offset = 0;
  for (auto _ : state) {
    const double next = offset == 0 ? step : 0;
    const b2Vec2 displacement(static_cast<float>(next - offset), 0);
    for (std::int64_t k = 0; k < n; ++k) bp.MoveProxy(proxies[static_cast<std::size_t>(k)], circle_box(e, k, next), displacement);
    counter.pairs = 0;
    bp.UpdatePairs(&counter);
    offset = next;
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_element"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["pairs"] = static_cast<double>(counter.pairs);
  state.counters["bytes_per_element"] = static_cast<double>((2 * n - 1) * static_cast<std::int64_t>(sizeof(b2TreeNode))) / static_cast<double>(n);
}

bool register_box2d_benchmarks() {
  register_physics_detectors();  // BM_Detect/box2d/... (bench_detect.cpp reads the registry in main)
  const Layout layouts[] = {Layout::Loose, Layout::Dense, Layout::Clustered};
  for (Layout layout : layouts) {
    for (std::int64_t n : {1'000, 10'000, 100'000, 1'000'000}) {
      for (bool large : {false, true}) {
        if (large && n > 100'000) continue;
        const std::string name = "BM_Box2DBroadphase/" + testdata::layout_name(layout) + "/" + std::to_string(n) + "/" +
                                 (large ? "large" : "small");
        benchmark::RegisterBenchmark(name.c_str(), bm_box2d_broadphase, layout, n, large)->Unit(benchmark::kMillisecond);
      }
    }
  }
  return true;
}

// Before main: bench_detect.cpp's main only initialises and runs what is registered.
const bool kRegistered = register_box2d_benchmarks();

}  // namespace
}  // namespace nbscope

// nbscope_bench: BM_TraceOff/<variant>/<layout>/<N> — does tracing cost anything when it is off?
//
// `nbs` is NbsDetector::detect_book(), the NullTrace instantiation of the traced template. `nbs_plain`
// is the control: the same 2D loops (core/nbs.cpp) written with no trace hooks at all, as a
// detector without a stepper would be. Equal times (within the noise of repetitions) show the
// hooks compile away. The control is a deliberate copy; main() checks that it finds the same
// pairs as the detector, so it cannot drift from what it stands for.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_trace_off.hpp"
#include "core/grid.hpp"
#include "core/nbs.hpp"
#include "support/generators.hpp"

namespace nbscope {

namespace {

using testdata::Layout;

// Munjiza-NBS in 2D without any trace hook: y-lists, per row the x-lists of the row (B0) and of the
// row below (B1), the contact mask, then the heads it touched reset to -1.
class PlainNbs {
 public:
  void detect(const Elements& e, PairList& out_pairs) {
    const Grid g = make_grid(e, {});
    const auto nx = static_cast<std::int32_t>(g.n[0]), ny = static_cast<std::int32_t>(g.n[1]);
    const auto n = static_cast<ElementId>(e.size());
    y_heads_.resize(static_cast<std::size_t>(ny), -1);
    x_heads_.resize(2 * static_cast<std::size_t>(nx), -1);
    y_next_.resize(static_cast<std::size_t>(n));
    x_next_.resize(static_cast<std::size_t>(n));
    std::int32_t* const yh = y_heads_.data();
    std::int32_t* const yn = y_next_.data();
    std::int32_t* const b0 = x_heads_.data();
    std::int32_t* const b1 = x_heads_.data() + nx;
    std::int32_t* const xn = x_next_.data();
    const double* const px = e.x.data();
    const double* const py = e.y.data();
    PairCollector pairs(out_pairs, kDefaultMaxPairs);
    auto test_list = [&](ElementId k, std::int32_t m) {
      for (; m != -1; m = xn[m])
        if (in_contact(e, k, m, Touching::inclusive)) pairs.add(k, m);
    };
    for (ElementId k = 0; k < n; ++k) {
      const std::int32_t iy = g.cell(py[k], 1);
      yn[k] = yh[iy];
      yh[iy] = k;
    }
    for (std::int32_t iy = 0; iy < ny; ++iy) {
      if (yh[iy] == -1) continue;
      const bool below = iy > 0 && yh[iy - 1] != -1;
      for (std::int32_t k = yh[iy]; k != -1; k = yn[k]) {
        const std::int32_t ix = g.cell(px[k], 0);
        xn[k] = b0[ix];
        b0[ix] = k;
      }
      if (below) {
        for (std::int32_t k = yh[iy - 1]; k != -1; k = yn[k]) {
          const std::int32_t ix = g.cell(px[k], 0);
          xn[k] = b1[ix];
          b1[ix] = k;
        }
      }
      for (std::int32_t k = yh[iy]; k != -1; k = yn[k]) {
        const std::int32_t ix = g.cell(px[k], 0);
        test_list(k, xn[k]);
        if (ix > 0) test_list(k, b0[ix - 1]);
        if (below)
          for (std::int32_t jx = std::max(ix - 1, 0); jx <= std::min(ix + 1, nx - 1); ++jx) test_list(k, b1[jx]);
      }
      for (std::int32_t k = yh[iy]; k != -1; k = yn[k]) b0[g.cell(px[k], 0)] = -1;
      if (below)
        for (std::int32_t k = yh[iy - 1]; k != -1; k = yn[k]) b1[g.cell(px[k], 0)] = -1;
    }
    for (ElementId k = 0; k < n; ++k) yh[g.cell(py[k], 1)] = -1;
  }

 private:
  std::vector<std::int32_t> y_heads_, x_heads_, y_next_, x_next_;
};

void bm_trace_off(benchmark::State& state, bool plain, Layout layout, std::int64_t n) {
  const Elements e = testdata::make_layout(layout, n, 2, 42);  // the seed of BM_Detect
  NbsDetector nbs;
  PlainNbs control;
  PairList pairs;
  for (auto _ : state) {
    if (plain) {
      control.detect(e, pairs);
    } else {
      nbs.detect_book(e, DetectOptions{}, pairs);
    }
    benchmark::DoNotOptimize(pairs.data());
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_element"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["pairs"] = static_cast<double>(pairs.size());
}

}  // namespace

void register_trace_off_benchmarks() {
  for (Layout layout : {Layout::Loose, Layout::Dense}) {
    for (std::int64_t n : {10'000, 100'000}) {
      for (const bool plain : {false, true}) {
        const std::string name = std::string("BM_TraceOff/") + (plain ? "nbs_plain/" : "nbs/") + testdata::layout_name(layout) +
                                 "/" + std::to_string(n);
        benchmark::RegisterBenchmark(name.c_str(), bm_trace_off, plain, layout, n)->Unit(benchmark::kMillisecond);
      }
    }
  }
}

bool trace_off_control_agrees() {
  for (Layout layout : testdata::all_layouts()) {
    const Elements e = testdata::make_layout(layout, 3'000, 2, 7);
    PairList a, b;
    NbsDetector().detect_book(e, DetectOptions{}, a);
    PlainNbs().detect(e, b);
    sort_pairs(a);
    sort_pairs(b);
    if (a != b) {
      std::fprintf(stderr, "nbscope_bench: the untraced control differs from nbs on %s\n", testdata::layout_name(layout).c_str());
      return false;
    }
  }
  return true;
}

}  // namespace nbscope

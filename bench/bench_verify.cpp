// nbscope_bench: BM_VerifyArrays/<case>/<N> — `nbscope verify --arrays`'s walk (core/verify.hpp),
// without the files: `cycle`, one y-list of N elements whose last link closes on its head (the walk
// must stop at the repeat, never follow it), and `nbs`, nbscope's own NBS y-lists of a loose layout
// (every element placed and checked). Counter: ns_per_element; linear when it stays flat in N.
#include <benchmark/benchmark.h>

#include <string>

#include "core/verify.hpp"
#include "support/generators.hpp"

namespace nbscope {
namespace {

// The y-lists of `e` as the book builds them, or one list of every element closed into a cycle.
verify::UserArrays y_lists(const Elements& e, const Grid& g, bool cycle) {
  verify::ListFamily f;
  f.heads_name = "y_heads";
  f.next_name = "Y";
  f.next_path = "$.y_next";
  f.heads_shape = {g.n[1]};
  const auto n = static_cast<std::size_t>(e.size());
  f.next.assign(n, -1);
  std::vector<std::int32_t> heads(static_cast<std::size_t>(g.n[1]), -1);
  for (std::size_t k = 0; k < n; ++k) {
    const std::int32_t iy = cycle ? 0 : g.cell(e.y[static_cast<Eigen::Index>(k)], 1);
    f.next[k] = heads[static_cast<std::size_t>(iy)];
    heads[static_cast<std::size_t>(iy)] = static_cast<std::int32_t>(k);
  }
  if (cycle) f.next[0] = static_cast<std::int32_t>(n - 1);
  for (std::size_t iy = 0; iy < heads.size(); ++iy)
    if (heads[iy] != -1) f.lists.push_back({static_cast<std::int64_t>(iy), heads[iy], {-1, static_cast<std::int32_t>(iy), -1}, 0});
  verify::UserArrays u;
  u.algorithm = "nbs";
  u.families.push_back(std::move(f));
  return u;
}

void bm_verify(benchmark::State& state, bool cycle, std::int64_t n) {
  Elements e = make_layout(Layout::Loose, n, 2, 1);
  GridOptions options;
  if (cycle) {
    for (Eigen::Index k = 0; k < e.y.size(); ++k) e.y[k] = 0;  // one row: one list of every element
  }
  const Grid g = make_grid(e, options);
  const verify::UserArrays u = y_lists(e, g, cycle);
  std::int64_t problems = 0;
  for (auto _ : state) {
    const verify::ArraysVerdict v = verify::verify_arrays(e, g, u, true);
    problems = v.problem_count;
    benchmark::DoNotOptimize(problems);
  }
  state.counters["ns_per_element"] =
      benchmark::Counter(static_cast<double>(n) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["problems"] = static_cast<double>(problems);
}

bool register_verify_benchmarks() {
  for (const bool cycle : {true, false})
    for (const std::int64_t n : {10'000, 100'000, 1'000'000})
      benchmark::RegisterBenchmark((std::string("BM_VerifyArrays/") + (cycle ? "cycle/" : "nbs/") + std::to_string(n)).c_str(),
                                   [cycle, n](benchmark::State& s) { bm_verify(s, cycle, n); })
          ->Unit(benchmark::kMillisecond);
  return true;
}

const bool kRegistered = register_verify_benchmarks();

}  // namespace
}  // namespace nbscope

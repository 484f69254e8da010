// nbscope_bench: BM_Check/<scene> — the per-frame cross-check (FrameChecker::begin_frame + check)
// of `nbs`'s pairs on a scene of assets/scenes, after 60 frames stepped outside the timing, as
// `nbscope headless` pays for it each frame: F, G and T, the reference detector's R (beside them on a
// second thread from 5,000 elements), and the four invariants; wall time. Counters: ns_per_element, pairs (A), and the check's parts in ms of the last frame
// checked (R_ms, F_ms, G/T_ms, and one per invariant).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "check/check.hpp"
#include "check/faults.hpp"
#include "core/cells.hpp"
#include "core/detector.hpp"
#include "io/scene_json.hpp"
#include "physics/world.hpp"

namespace nbscope {
namespace {

constexpr int kFramesBefore = 60;

// A scene stepped kFramesBefore frames and nbs's pairs and cells of that frame, made once per scene.
struct SteppedScene {
  std::unique_ptr<PhysicsWorld> world;
  DetectOptions options;
  PairList pairs;
  std::vector<CellIndex> cells;
};

const SteppedScene& stepped(const std::string& name) {
  static std::map<std::string, std::unique_ptr<SteppedScene>> cache;
  auto& slot = cache[name];
  if (slot) return *slot;
  slot = std::make_unique<SteppedScene>();
  const Scene scene = read_scene_json(std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/" + name + ".json");
  slot->world = std::make_unique<PhysicsWorld>(scene);
  for (int k = 0; k < kFramesBefore; ++k) slot->world->step();
  slot->options.grid = scene.grid;
  const Elements& e = slot->world->elements();
  auto nbs = make_detector("nbs");
  nbs->detect(e, slot->options, slot->pairs);
  sort_pairs(slot->pairs);
  const Grid grid = nbs->last_grid() != nullptr ? *nbs->last_grid() : make_grid(e, slot->options.grid);
  integerise_cells(e, grid, slot->cells);
  return *slot;
}

void bm_check(benchmark::State& state, const std::string& name) {
  const SteppedScene& s = stepped(name);
  FrameChecker checker;
  FrameReport report;
  CheckInput in;
  in.algorithm = "nbs";
  in.pairs = &s.pairs;
  in.cells = &s.cells;
  for (auto _ : state) {
    checker.begin_frame(*s.world, s.options, in.algorithm);  // R beside F, G and T, as the frame loop does
    checker.check(in, report);
    benchmark::ClobberMemory();
  }
  if (!report.ok()) state.SkipWithError("the check found violations");
  const auto n = static_cast<double>(s.world->elements().size());
  state.counters["ns_per_element"] =
      benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["pairs"] = static_cast<double>(s.pairs.size());
  for (int k = 0; k < CheckTimings::kParts; ++k)
    state.counters[std::string(CheckTimings::part_name(k)) + "_ms"] = report.check_timings.part(k);
}

// Before main (bench_detect.cpp's): one benchmark per scene file, loaded only when it runs.
bool register_check_benchmarks() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes"))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  for (const std::string& name : names)
    // Wall time: from 5,000 elements R runs on a second thread, whose CPU time the main thread's omits.
    benchmark::RegisterBenchmark(("BM_Check/" + name).c_str(), bm_check, name)->Unit(benchmark::kMillisecond)->UseRealTime();
  return true;
}

const bool kRegistered = register_check_benchmarks();

}  // namespace
}  // namespace nbscope

// core/plugin_detector: the C tables of include/nbscope/detector.h as a Detector, with in-process
// C-linkage functions as the "plugin" (no .so): agreement with brute force, every broken rule named,
// the trace's shadow semantics, no trace call when untraced, the plugin's own cells.
#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <string>

#include "core/brute.hpp"
#include "core/cells.hpp"
#include "core/plugin_detector.hpp"
#include "support/generators.hpp"

namespace nbscope {
namespace {

// The body of the in-process plugin, set by each test.
using Body = std::function<int(void** state, const nbscope_frame* f, const nbscope_output* out, const nbscope_trace* t)>;
Body g_body;
int g_released = 0;

extern "C" int test_detect(void** state, const nbscope_frame* f, const nbscope_output* out, const nbscope_trace* t) {
  return g_body(state, f, out, t);
}
extern "C" void test_release(void* state) {
  ++g_released;
  delete static_cast<int*>(state);
}
extern "C" std::size_t test_own_bytes(const void* state) { return state != nullptr ? 1234 : 0; }

const char* const kLines[] = {"line zero", "line one", "line two"};

nbscope_detector_info test_info(std::uint32_t capabilities) {
  return nbscope_detector_info{NBSCOPE_DETECTOR_API_VERSION, "inproc", "in-process test plugin", capabilities, kLines, 3,
                               kLines, 3};
}

PluginSymbols test_symbols() {
  PluginSymbols s;
  s.library = "lib.so";
  s.detect = test_detect;
  s.release = test_release;
  return s;
}

constexpr std::uint32_t kAll = NBSCOPE_CAP_2D | NBSCOPE_CAP_3D | NBSCOPE_CAP_TRACES;

// Brute force through the C tables, as a plugin author would write it.
int brute_body(void**, const nbscope_frame* f, const nbscope_output* out, const nbscope_trace* t) {
  for (std::int64_t i = 0; i < f->n; ++i)
    for (std::int64_t j = i + 1; j < f->n; ++j) {
      const double dx = f->x[i] - f->x[j], dy = f->y[i] - f->y[j], dz = f->dim == 3 ? f->z[i] - f->z[j] : 0.0;
      const double rr = f->r[i] + f->r[j];
      const bool contact = dx * dx + dy * dy + dz * dz <= rr * rr;
      if (t != nullptr) t->test_pair(t->ctx, 2, static_cast<std::int32_t>(i), static_cast<std::int32_t>(j), contact);
      // Either order: the adapter normalises.
      if (contact && out->add_pair(out->ctx, static_cast<std::int32_t>(j), static_cast<std::int32_t>(i))) return 1;
    }
  return 0;
}

Elements nine() {
  Elements e;
  for (int k = 0; k < 9; ++k) e.push_back(0.4 * k, 0.3 * (k % 3), 0, 0.25);
  return e;
}

// The message of the PluginError that detecting `e` with `body` throws ("" when none).
std::string plugin_error(const Body& body, std::uint32_t capabilities = kAll, bool traced = false,
                         const Elements& e = nine()) {
  g_body = body;
  PluginDetector detector(test_symbols(), test_info(capabilities));
  DetectOptions options;
  options.frame = 7;
  PairList pairs;
  TraceLog log;
  try {
    if (traced) detector.detect_traced(e, options, pairs, log);
    else detector.detect(e, options, pairs);
  } catch (const PluginError& err) {
    return err.what();
  }
  // A plugin's own bug (a bad pair, a broken trace rule, a cell) does not throw: it is the frame's
  // misbehaviour, a `contract` violation, and the pairs keep only what can be checked.
  if (const Misbehaviour* m = detector.misbehaviour()) {
    for (const Pair& p : pairs) {
      if (p.i < 0 || p.j < 0 || p.i >= e.size() || p.j >= e.size() || p.i == p.j) ADD_FAILURE() << "a bad pair was kept";
    }
    return m->where + m->text;
  }
  return "";
}

const std::string kWhere = "lib.so (inproc): frame 7: ";

TEST(PluginDetector, AgreesWithBruteForceOnRandomAndDegenerateSets) {
  g_body = brute_body;
  PluginDetector plugin(test_symbols(), test_info(kAll));
  BruteDetector brute;
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> pos(0, 10), rad(0.05, 0.6);
  std::vector<Elements> sets;
  for (int dim : {2, 3})
    for (int n : {0, 1, 2, 50, 300}) {
      Elements e;
      e.dim = dim;
      for (int k = 0; k < n; ++k) e.push_back(pos(rng), pos(rng), pos(rng), rad(rng));
      sets.push_back(e);
      Elements one_point;  // every element at one point: every pair in contact
      one_point.dim = dim;
      for (int k = 0; k < n / 4; ++k) one_point.push_back(1, 1, 1, 0.5);
      sets.push_back(one_point);
    }
  for (const Elements& e : sets) {
    PairList got, want;
    plugin.detect(e, DetectOptions{}, got);
    brute.detect(e, DetectOptions{}, want);
    sort_pairs(got);
    sort_pairs(want);
    EXPECT_EQ(got, want) << "dim " << e.dim << ", n " << e.size();
  }
}

TEST(PluginDetector, UntracedRunMakesNoTraceCallTracedRunDoes) {
  int untraced_tables = 0, traced_tables = 0;
  g_body = [&](void** s, const nbscope_frame* f, const nbscope_output* out, const nbscope_trace* t) {
    (t == nullptr ? untraced_tables : traced_tables)++;
    return brute_body(s, f, out, t);
  };
  PluginDetector detector(test_symbols(), test_info(kAll));
  PairList pairs;
  detector.detect(nine(), DetectOptions{}, pairs);
  EXPECT_EQ(untraced_tables, 1);
  EXPECT_EQ(traced_tables, 0);
  TraceLog log;
  detector.detect_traced(nine(), DetectOptions{}, pairs, log);
  EXPECT_EQ(traced_tables, 1);
  EXPECT_EQ(log.events().size(), 36u);  // 9 * 8 / 2 tests
}

TEST(PluginDetector, SeesTheGridTheBuiltInsFit) {
  nbscope_frame seen{};
  g_body = [&](void**, const nbscope_frame* f, const nbscope_output*, const nbscope_trace*) {
    seen = *f;
    return 0;
  };
  PluginDetector detector(test_symbols(), test_info(kAll));
  PairList pairs;
  DetectOptions options;
  options.frame = 42;
  const Elements e = nine();
  detector.detect(e, options, pairs);
  const Grid grid = make_grid(e, options.grid);
  EXPECT_EQ(seen.frame, 42);
  EXPECT_EQ(seen.n, 9);
  EXPECT_EQ(seen.dim, 2);
  EXPECT_EQ(seen.z, nullptr);
  EXPECT_EQ(seen.d, grid.cell_size);
  EXPECT_EQ(seen.inv_d, grid.inv_cell_size);  // the plugins integerise with it, so cells agree bit for bit
  EXPECT_EQ(seen.origin[0], grid.origin[0]);
  EXPECT_EQ(seen.origin[1], grid.origin[1]);
  EXPECT_EQ(seen.cells[0], grid.n[0]);
  EXPECT_EQ(seen.cells[1], grid.n[1]);
  EXPECT_EQ(seen.cells[2], 1);
  EXPECT_EQ(static_cast<std::size_t>(seen.max_pairs), kDefaultMaxPairs);
  ASSERT_NE(detector.last_grid(), nullptr);
  EXPECT_EQ(detector.last_grid()->n[0], grid.n[0]);
}

TEST(PluginDetector, NamesEveryBadPair) {
  EXPECT_EQ(plugin_error([](void**, const nbscope_frame*, const nbscope_output* o, const nbscope_trace*) {
              return o->add_pair(o->ctx, 0, 9);
            }),
            kWhere + "add_pair(0, 9): element 9 is out of range [0, 9)");
  EXPECT_EQ(plugin_error([](void**, const nbscope_frame*, const nbscope_output* o, const nbscope_trace*) {
              return o->add_pair(o->ctx, -1, 3);
            }),
            kWhere + "add_pair(-1, 3): element -1 is out of range [0, 9)");
  EXPECT_EQ(plugin_error([](void**, const nbscope_frame*, const nbscope_output* o, const nbscope_trace*) {
              return o->add_pair(o->ctx, 4, 4);
            }),
            kWhere + "add_pair(4, 4): an element paired with itself");
  // Twice, far apart and in the other order: a "last partner" check would miss it.
  EXPECT_EQ(plugin_error([](void**, const nbscope_frame*, const nbscope_output* o, const nbscope_trace*) {
              return o->add_pair(o->ctx, 0, 1) + o->add_pair(o->ctx, 0, 2) + o->add_pair(o->ctx, 2, 5) +
                     o->add_pair(o->ctx, 1, 0);
            }),
            kWhere + "add_pair: pair (0, 1) given twice");
}

TEST(PluginDetector, NonzeroReturnCarriesTheFailMessage) {
  EXPECT_EQ(plugin_error([](void**, const nbscope_frame*, const nbscope_output* o, const nbscope_trace*) {
              o->fail(o->ctx, "no memory for the heads");
              return 3;
            }),
            kWhere + "nbscope_detect returned 3: no memory for the heads");
  EXPECT_EQ(plugin_error([](void**, const nbscope_frame*, const nbscope_output*, const nbscope_trace*) { return -1; }),
            kWhere + "nbscope_detect returned -1 without a reason (fail() not called)");
}

TEST(PluginDetector, PairLimitIsThePairLimitErrorNotThePlugins) {
  g_body = brute_body;
  PluginDetector detector(test_symbols(), test_info(kAll));
  Elements e;
  for (int k = 0; k < 10; ++k) e.push_back(0, 0, 0, 1);
  DetectOptions options;
  options.max_pairs = 5;
  PairList pairs;
  try {
    detector.detect(e, options, pairs);
    FAIL() << "no error past the pair limit";
  } catch (const PluginError& err) {
    FAIL() << "blamed the plugin: " << err.what();
  } catch (const Error&) {
  }
}

// A plugin with one declared array of `size` entries, then `call` made on the table.
std::string trace_error(std::int64_t size, const std::function<void(const nbscope_trace*, int id)>& call) {
  static std::vector<std::int32_t> data;
  data.assign(static_cast<std::size_t>(size), -1);
  return plugin_error(
      [&](void**, const nbscope_frame*, const nbscope_output*, const nbscope_trace* t) {
        const std::int64_t shape[1] = {size};
        const int id = t->declare_array(t->ctx, "heads", 1, shape, data.data());
        call(t, id);
        return 0;
      },
      kAll, true);
}

TEST(PluginDetector, NamesEveryBadTraceCall) {
  EXPECT_EQ(trace_error(4, [](const nbscope_trace* t, int) { t->set(t->ctx, 0, "cell", 7, 0, 0); }),
            kWhere + "trace set: array 7 was not declared (1 declared)");
  EXPECT_EQ(trace_error(4, [](const nbscope_trace* t, int id) { t->set(t->ctx, 0, "cell", id, 4, 0); }),
            kWhere + "trace set: index 4 is outside array 0 of 4 entries");
  EXPECT_EQ(trace_error(4, [](const nbscope_trace* t, int id) { t->clear(t->ctx, 1, "y", id, -1); }),
            kWhere + "trace clear: list -1 is outside array 0 of 4 entries");
  EXPECT_EQ(trace_error(4, [](const nbscope_trace* t, int id) { t->push(t->ctx, 1, "y", id, 0, id, 9, 0, 0, -1); }),
            kWhere + "trace push: element 9 is out of range [0, 9)");
  EXPECT_EQ(trace_error(4, [](const nbscope_trace* t, int id) { t->push(t->ctx, 1, "y", id, 0, id, 5, 0, 0, -1); }),
            kWhere + "trace push: element 5 is outside array 0 of 4 entries");
  EXPECT_EQ(trace_error(4, [](const nbscope_trace* t, int) { t->phase(t->ctx, 3, "beyond", -1); }),
            kWhere + "trace phase: line 3 is not one of the 3 pseudocode lines");
  EXPECT_EQ(trace_error(4, [](const nbscope_trace* t, int) { t->test_pair(t->ctx, 2, 0, 12, 1); }),
            kWhere + "trace test_pair: element 12 is out of range [0, 9)");
  EXPECT_EQ(trace_error(4, [](const nbscope_trace* t, int) { t->visit_cell(t->ctx, -2, 0, 0, 0, -1); }),
            kWhere + "trace visit_cell: line -2 is not one of the 3 pseudocode lines");
  EXPECT_EQ(trace_error(4, [](const nbscope_trace* t, int) {
              const std::int64_t shape[4] = {1, 1, 1, 1};
              std::int32_t one = 0;
              t->declare_array(t->ctx, "deep", 4, shape, &one);
            }),
            kWhere + "trace declare_array: rank 4 (from 1 to 3, with a shape)");
  EXPECT_EQ(trace_error(4, [](const nbscope_trace* t, int) {
              const std::int64_t shape[2] = {3, -2};
              std::int32_t one = 0;
              t->declare_array(t->ctx, "bad", 2, shape, &one);
            }),
            kWhere + "trace declare_array: shape entry 1 is -2, or the array is over 1073741824 entries");
  EXPECT_EQ(trace_error(4, [](const nbscope_trace*, int) {}), "");  // the harness itself is clean
}

TEST(PluginDetector, TraceRecordsTheWritesThePluginReallyMade) {
  static std::int32_t heads[2], next[3];
  char label[16] = "y-lists";
  g_body = [&](void**, const nbscope_frame*, const nbscope_output*, const nbscope_trace* t) {
    heads[0] = heads[1] = -1;
    next[0] = next[1] = next[2] = -1;
    const std::int64_t hs[1] = {2}, ns[1] = {3};
    const int h = t->declare_array(t->ctx, "heads", 1, hs, heads);
    const int n = t->declare_array(t->ctx, "next", 1, ns, next);
    t->phase(t->ctx, 0, label, -1);
    next[0] = heads[0];  // a right push of 0 onto list 0
    heads[0] = 0;
    t->push(t->ctx, 1, "y", h, 0, n, 0, -1, 0, -1);
    next[1] = -1;  // a buggy push of 1: next[1] = -1 instead of heads[0]
    heads[0] = 1;
    t->push(t->ctx, 1, "y", h, 0, n, 1, -1, 0, -1);
    heads[1] = 5;  // a buggy clear that writes 5
    t->clear(t->ctx, 2, "y", h, 1);
    return 0;
  };
  PluginDetector detector(test_symbols(), test_info(kAll));
  PairList pairs;
  TraceLog log;
  detector.detect_traced(nine(), DetectOptions{}, pairs, log);
  std::snprintf(label, sizeof label, "overwritten");  // the plugin's buffer changes; the event keeps its label
  ASSERT_EQ(log.events().size(), 4u);
  EXPECT_STREQ(log.events()[0].label, "y-lists");
  const TraceEvent& right = log.events()[1];
  EXPECT_EQ(right.writes[0].old_value, -1);  // next[0]: -1 -> -1 (the old head)
  EXPECT_EQ(right.writes[1].old_value, -1);  // heads[0]: -1 -> 0
  EXPECT_EQ(right.writes[1].new_value, 0);
  const TraceEvent& buggy = log.events()[2];
  EXPECT_EQ(buggy.writes[0].index, 1);
  EXPECT_EQ(buggy.writes[0].old_value, -1);
  EXPECT_EQ(buggy.writes[0].new_value, -1);  // as written, not the 0 a right push would write
  EXPECT_EQ(buggy.writes[1].old_value, 0);
  EXPECT_EQ(buggy.writes[1].new_value, 1);
  EXPECT_EQ(log.events()[3].writes[0].old_value, -1);
  EXPECT_EQ(log.events()[3].writes[0].new_value, 5);
  // Replaying the trace gives the arrays as the plugin left them.
  const auto end = log.state_after(log.events().size());
  EXPECT_EQ(end[0], (std::vector<std::int32_t>{1, 5}));
  EXPECT_EQ(end[1], (std::vector<std::int32_t>{-1, -1, -1}));
}

TEST(PluginDetector, OwnCellsAreThePluginsAndChecked) {
  const auto write_cells = [](std::int32_t bad_entry, std::int32_t bad_value) {
    return [=](void**, const nbscope_frame* f, const nbscope_output* o, const nbscope_trace*) {
      for (std::int64_t k = 0; k < f->n; ++k) {
        o->cells[2 * k] = static_cast<std::int32_t>(k % 3);
        o->cells[2 * k + 1] = 0;
      }
      if (bad_entry >= 0) o->cells[bad_entry] = bad_value;
      return 0;
    };
  };
  const std::uint32_t caps = kAll | NBSCOPE_CAP_CELLS;
  EXPECT_EQ(plugin_error(write_cells(5, -1), caps), kWhere + "cells: element 2's cell on y was not written (still -1)");
  const std::string nx = std::to_string(make_grid(nine(), GridOptions{}).n[0]);
  EXPECT_EQ(plugin_error(write_cells(4, 99), caps), kWhere + "cells: element 2's cell on x is 99, outside [0, " + nx + ")");
  EXPECT_EQ(plugin_error(write_cells(0, -7), caps), kWhere + "cells: element 0's cell on x is -7, outside [0, " + nx + ")");
  const std::string ny = std::to_string(make_grid(nine(), GridOptions{}).n[1]);
  EXPECT_EQ(plugin_error(write_cells(17, 99), caps), kWhere + "cells: element 8's cell on y is 99, outside [0, " + ny + ")");
  g_body = write_cells(-1, 0);
  PluginDetector detector(test_symbols(), test_info(caps));
  PairList pairs;
  detector.detect(nine(), DetectOptions{}, pairs);
  ASSERT_NE(detector.own_cells(), nullptr);
  EXPECT_EQ((*detector.own_cells())[7], (CellIndex{1, 0}));  // 7 % 3, as written
  // Without NBSCOPE_CAP_CELLS the plugin gets no cells array and reports none.
  const nbscope_output* seen = nullptr;
  std::int32_t* cells = reinterpret_cast<std::int32_t*>(1);
  g_body = [&](void**, const nbscope_frame*, const nbscope_output* o, const nbscope_trace*) {
    seen = o;
    cells = o->cells;
    return 0;
  };
  PluginDetector plain(test_symbols(), test_info(kAll));
  plain.detect(nine(), DetectOptions{}, pairs);
  EXPECT_NE(seen, nullptr);
  EXPECT_EQ(cells, nullptr);
  EXPECT_EQ(plain.own_cells(), nullptr);
}

TEST(PluginDetector, StateOwnBytesAndReleaseGoThroughTheSymbols) {
  g_released = 0;
  g_body = [](void** state, const nbscope_frame*, const nbscope_output*, const nbscope_trace*) {
    if (*state == nullptr) *state = new int(0);
    ++*static_cast<int*>(*state);
    return 0;
  };
  PluginSymbols symbols = test_symbols();
  {
    PluginDetector without(symbols, test_info(kAll));
    PairList pairs;
    without.detect(nine(), DetectOptions{}, pairs);
    EXPECT_EQ(without.own_bytes(), 0u);  // no nbscope_own_bytes
  }
  EXPECT_EQ(g_released, 1);
  symbols.own_bytes = test_own_bytes;
  PluginDetector with(symbols, test_info(kAll));
  EXPECT_EQ(with.own_bytes(), 0u);
  PairList pairs;
  with.detect(nine(), DetectOptions{}, pairs);
  with.detect(nine(), DetectOptions{}, pairs);
  EXPECT_EQ(with.own_bytes(), 1234u);
  EXPECT_EQ(with.pseudocode(2).size(), 3u);
  EXPECT_STREQ(with.pseudocode(3)[1], "line one");
}

TEST(PluginDetector, InfoIsCheckedBeforeRegistration) {
  const auto refusal = [](nbscope_detector_info info) -> std::string {
    try {
      check_plugin_info(&info);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(refusal(test_info(kAll)), "");
  nbscope_detector_info bad = test_info(kAll);
  bad.name = "Bad Name";
  EXPECT_EQ(refusal(bad), "its name 'Bad Name' is not 1 to 64 of [a-z0-9_-]");
  bad = test_info(kAll);
  bad.api_version = 2;
  EXPECT_EQ(refusal(bad), "nbscope_detector_describe() says plugin API version 2; this nbscope speaks 1");
  EXPECT_EQ(refusal(test_info(NBSCOPE_CAP_TRACES)), "its capabilities name neither NBSCOPE_CAP_2D nor NBSCOPE_CAP_3D");
  bad = test_info(kAll);
  bad.pseudocode_3d = nullptr;
  EXPECT_EQ(refusal(bad), "pseudocode_3d is NULL but pseudocode_3d_lines is 3");
  bad = test_info(kAll);
  bad.pseudocode_2d_lines = 300;
  EXPECT_EQ(refusal(bad), "pseudocode_2d_lines is 300, not from 0 to 256");
  EXPECT_THROW(check_plugin_info(nullptr), Error);
}

TEST(PluginDetector, RegistryEntryCarriesTheCapabilities) {
  const nbscope_detector_info info = test_info(NBSCOPE_CAP_2D | NBSCOPE_CAP_LISTS);
  const DetectorInfo entry = plugin_detector_info(test_symbols(), info);
  EXPECT_EQ(entry.name, "inproc");
  EXPECT_TRUE(entry.dim2);
  EXPECT_FALSE(entry.dim3);
  EXPECT_FALSE(entry.traces);
  EXPECT_TRUE(entry.has_lists);
  EXPECT_EQ(entry.make()->name(), "inproc");
}

TEST(PluginDetector, NamesARepeatedPairOnEveryCallAndKeepsItOnce) {
  g_body = [](void**, const nbscope_frame*, const nbscope_output* o, const nbscope_trace*) {
    return o->add_pair(o->ctx, 3, 8) + o->add_pair(o->ctx, 0, 1) + o->add_pair(o->ctx, 8, 3);
  };
  PluginDetector detector(test_symbols(), test_info(kAll));
  PairList pairs;
  for (int call = 0; call < 3; ++call) {
    detector.detect(nine(), DetectOptions{}, pairs);
    ASSERT_NE(detector.misbehaviour(), nullptr) << "call " << call;
    EXPECT_EQ(detector.misbehaviour()->text, "add_pair: pair (3, 8) given twice");
    EXPECT_EQ(pairs, (PairList{{0, 1}, {3, 8}})) << "each pair once, as the checks compare them";
  }
}

// The walk check: a plugin that traces its lists gets the table on a checked, untraced frame and
// each test is held against its walk's visited cell. This "plugin" visits element 0's cell and then
// tests 0 against every element: each one of another cell is a stray. Without check_walks, or
// without NBSCOPE_CAP_LISTS, the frame stays untraced (no table) and nothing is checked.
TEST(PluginDetector, TheWalkCheckFindsEveryElementTestedFromAnotherCellsList) {
  const Elements e = nine();
  int tables = 0;
  g_body = [&](void**, const nbscope_frame* f, const nbscope_output* out, const nbscope_trace* t) {
    if (t == nullptr) return 0;
    ++tables;
    const auto cell = [&](std::int64_t k, int a) {
      return static_cast<std::int32_t>(((a == 0 ? f->x : f->y)[k] - f->origin[a]) / f->d);
    };
    t->visit_cell(t->ctx, 1, 0, cell(0, 0), cell(0, 1), -1);
    for (std::int32_t j = 1; j < f->n; ++j) t->test_pair(t->ctx, 2, 0, j, 0);
    (void)out;
    return 0;
  };
  constexpr std::uint32_t kLists = NBSCOPE_CAP_2D | NBSCOPE_CAP_TRACES | NBSCOPE_CAP_LISTS;
  PluginDetector detector(test_symbols(), test_info(kLists));
  DetectOptions options;
  PairList pairs;
  detector.detect(e, options, pairs);  // not asked: no table, no check
  EXPECT_EQ(tables, 0);
  EXPECT_EQ(detector.walk_check(), nullptr);

  options.check_walks = true;
  detector.detect(e, options, pairs);
  EXPECT_EQ(tables, 1);
  ASSERT_NE(detector.walk_check(), nullptr);
  std::vector<CellIndex> cells;
  integerise_cells(e, *detector.last_grid(), cells);
  std::int64_t others = 0;
  for (std::size_t j = 1; j < cells.size(); ++j) others += cells[j] == cells[0] ? 0 : 1;
  ASSERT_GT(others, 0);
  const WalkCheck& walks = *detector.walk_check();
  EXPECT_EQ(walks.count, others);
  ASSERT_FALSE(walks.first.empty());
  for (const StrayTest& s : walks.first) {
    EXPECT_EQ(s.finder, 0);
    EXPECT_EQ(s.list_cell, cells[0]);
    EXPECT_EQ(s.own_cell, cells[static_cast<std::size_t>(s.stray)]);
    EXPECT_EQ(s.finder_cell, cells[0]);
    EXPECT_NE(s.own_cell, s.list_cell);
  }

  PluginDetector no_lists(test_symbols(), test_info(NBSCOPE_CAP_2D | NBSCOPE_CAP_TRACES));
  no_lists.detect(e, options, pairs);
  EXPECT_EQ(tables, 1);
  EXPECT_EQ(no_lists.walk_check(), nullptr);
}

}  // namespace
}  // namespace nbscope

// core/plugin_detector: what a plugin says is bounded and every call into it is bracketed. Texts
// (fail() messages, array names, trace labels, its summary and pseudocode lines) are cut to
// kMaxPluginTextBytes with the count of what was cut; an array without a name is a breach; the guard
// brackets nbscope_detect, nbscope_own_bytes and nbscope_release alike (io's guard turns a crash or a
// hang inside into one error line: tests/app/test_plugin_cli.cpp).
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/guarded_ints.hpp"
#include "core/plugin_detector.hpp"

namespace nbscope {
namespace {

using Body = std::function<int(void** state, const nbscope_frame* f, const nbscope_output* out, const nbscope_trace* t)>;
Body g_body;

extern "C" int bounds_detect(void** state, const nbscope_frame* f, const nbscope_output* out, const nbscope_trace* t) {
  if (*state == nullptr) *state = new int(0);  // a state, so that release is called
  return g_body(state, f, out, t);
}
extern "C" void bounds_release(void* state) { delete static_cast<int*>(state); }
extern "C" std::size_t bounds_own_bytes(const void*) { return 64; }

const char* const kLines[] = {"line zero", "line one", "line two"};

nbscope_detector_info info() {
  return nbscope_detector_info{NBSCOPE_DETECTOR_API_VERSION, "bounds", "bounds test plugin", NBSCOPE_CAP_2D | NBSCOPE_CAP_TRACES,
                               kLines, 3, kLines, 3};
}

// Every enter and leave, in order: "enter detect 7", "leave", ...
class RecordingGuard final : public PluginCallGuard {
 public:
  std::vector<std::string> calls;
  void enter(PluginCallKind kind, std::int64_t frame) override {
    const char* names[] = {"load", "describe", "detect", "release", "own_bytes"};
    calls.push_back(std::string("enter ") + names[static_cast<int>(kind)] +
                    (kind == PluginCallKind::detect ? " " + std::to_string(frame) : ""));
  }
  void leave() override { calls.emplace_back("leave"); }
};

PluginSymbols symbols(std::shared_ptr<PluginCallGuard> guard = nullptr) {
  PluginSymbols s;
  s.library = "lib.so";
  s.detect = bounds_detect;
  s.release = bounds_release;
  s.own_bytes = bounds_own_bytes;
  s.guard = std::move(guard);
  return s;
}

Elements three() {
  Elements e;
  for (int k = 0; k < 3; ++k) e.push_back(0.5 * k, 0, 0, 0.2);
  return e;
}

// The PluginError of one traced detection with `body`, "" when none.
std::string traced_error(const Body& body) {
  g_body = body;
  PluginDetector detector(symbols(), info());
  PairList pairs;
  TraceLog log;
  try {
    detector.detect_traced(three(), DetectOptions{}, pairs, log);
  } catch (const PluginError& e) {
    return e.what();
  }
  if (const Misbehaviour* m = detector.misbehaviour()) return m->where + m->text;  // the plugin's own bug: its frame's evidence
  return "";
}

TEST(PluginBounds, TextsAreCutWithTheCountOfWhatWasCut) {
  EXPECT_EQ(cut_plugin_text(nullptr), "");
  const std::string fits(kMaxPluginTextBytes, 'a');
  EXPECT_EQ(cut_plugin_text(fits.c_str()), fits);
  const std::string long_text(kMaxPluginTextBytes + 1'234'567, 'b');
  EXPECT_EQ(cut_plugin_text(long_text.c_str()), std::string(kMaxPluginTextBytes, 'b') + "... (1,234,567 more bytes)");
  // A two-byte character across the bound is kept whole or not at all: never half of it.
  const std::string accents = std::string(kMaxPluginTextBytes - 1, 'c') + "\xC3\xA9" + "tail";
  EXPECT_EQ(cut_plugin_text(accents.c_str()), std::string(kMaxPluginTextBytes - 1, 'c') + "... (6 more bytes)");
}

TEST(PluginBounds, AMegabyteFailMessageIsCut) {
  const std::string message(std::size_t{1} << 20, 'x');
  const std::string error = traced_error([&](void**, const nbscope_frame*, const nbscope_output* o, const nbscope_trace*) {
    o->fail(o->ctx, message.c_str());
    return 1;
  });
  EXPECT_EQ(error, "lib.so (bounds): frame 0: nbscope_detect returned 1: " + std::string(kMaxPluginTextBytes, 'x') + "... (" +
                       "1,048,276 more bytes)");  // 2^20 - 300
}

TEST(PluginBounds, AnArrayWithoutANameIsABreach) {
  for (const char* name : {static_cast<const char*>(nullptr), ""}) {
    const std::string error = traced_error([&](void**, const nbscope_frame*, const nbscope_output*, const nbscope_trace* t) {
      static std::int32_t data[3] = {-1, -1, -1};
      const std::int64_t shape[1] = {3};
      return t->declare_array(t->ctx, name, 1, shape, data) < 0 ? 0 : 1;  // refused: -1
    });
    EXPECT_EQ(error, std::string("lib.so (bounds): frame 0: trace declare_array: array 0's name is ") +
                         (name == nullptr ? "NULL" : "empty") + " (name it as the book does: heads, next, ...)");
  }
}

TEST(PluginBounds, LongArrayNamesAndLabelsAreCut) {
  const std::string long_name(5000, 'n');
  const std::string long_label(7000, 'l');
  g_body = [&](void**, const nbscope_frame*, const nbscope_output*, const nbscope_trace* t) {
    static std::int32_t data[3] = {-1, -1, -1};
    const std::int64_t shape[1] = {3};
    const int id = t->declare_array(t->ctx, long_name.c_str(), 1, shape, data);
    t->phase(t->ctx, 0, long_label.c_str(), -1);
    data[1] = 2;
    t->set(t->ctx, 1, long_label.c_str(), id, 1, 2);
    return 0;
  };
  PluginDetector detector(symbols(), info());
  PairList pairs;
  TraceLog log;
  detector.detect_traced(three(), DetectOptions{}, pairs, log);
  ASSERT_EQ(log.arrays().size(), 1u);
  EXPECT_EQ(log.arrays()[0].name, std::string(kMaxPluginTextBytes, 'n') + "... (4,700 more bytes)");
  ASSERT_EQ(log.events().size(), 2u);
  const std::string cut_label = std::string(kMaxPluginTextBytes, 'l') + "... (6,700 more bytes)";
  EXPECT_EQ(std::string(log.events()[0].label), cut_label);
  EXPECT_EQ(std::string(log.events()[1].label), cut_label);
}

TEST(PluginBounds, TheDescriptionIsCopiedAndCut) {
  const std::string long_summary(2000, 's');
  std::string line = std::string(1000, 'p');
  const char* const lines[] = {line.c_str()};
  nbscope_detector_info described = info();
  described.summary = long_summary.c_str();
  described.pseudocode_2d = lines;
  described.pseudocode_2d_lines = 1;
  const DetectorInfo entry = plugin_detector_info(symbols(), described);
  line.assign(1000, 'q');  // the plugin's memory changes after the load: nbscope kept its own copy
  const std::string cut_line = std::string(kMaxPluginTextBytes, 'p') + "... (700 more bytes)";
  EXPECT_EQ(entry.summary, std::string(kMaxPluginTextBytes, 's') + "... (1,700 more bytes) (plugin lib.so)");
  const auto detector = entry.make();
  ASSERT_EQ(detector->pseudocode(2).size(), 1u);
  EXPECT_EQ(std::string(detector->pseudocode(2)[0]), cut_line);
  EXPECT_EQ(detector->pseudocode(3).size(), 3u);
}

TEST(PluginBounds, DetectOwnBytesAndReleaseAreEachGuarded) {
  auto guard = std::make_shared<RecordingGuard>();
  g_body = [](void**, const nbscope_frame*, const nbscope_output*, const nbscope_trace*) { return 0; };
  {
    PluginDetector detector(symbols(guard), info());
    PairList pairs;
    DetectOptions options;
    options.frame = 7;
    detector.detect(three(), options, pairs);
    EXPECT_EQ(detector.own_bytes(), 64u);
    EXPECT_EQ(detector.own_bytes(), 64u);  // asked once per detection (the window asks every frame)
    options.frame = 8;
    detector.detect(three(), options, pairs);
    EXPECT_EQ(detector.own_bytes(), 64u);
  }
  EXPECT_EQ(guard->calls, (std::vector<std::string>{"enter detect 7", "leave", "enter own_bytes", "leave", "enter detect 8",
                                                    "leave", "enter own_bytes", "leave", "enter release", "leave"}));
}

// A call that traces without end (a loop that never stops) is stopped at the operation limit: its
// frame's misbehaviour says so, and nbscope goes on.
TEST(PluginBounds, ARunawayCallIsStoppedAtTheOperationLimit) {
  g_body = [](void**, const nbscope_frame*, const nbscope_output*, const nbscope_trace* t) {
    for (;;) t->phase(t->ctx, 0, "forever", -1);
    return 0;
  };
  PluginDetector detector(symbols(), info());
  detector.set_operation_limit(1000);
  PairList pairs;
  TraceLog log;
  detector.detect_traced(three(), DetectOptions{}, pairs, log);
  ASSERT_NE(detector.misbehaviour(), nullptr);
  EXPECT_EQ(detector.misbehaviour()->text.rfind("runaway: 1001 trace operations for 3 elements", 0), 0u) << detector.misbehaviour()->text;
  EXPECT_TRUE(detector.misbehaviour()->cut);
  EXPECT_EQ(log.events().size(), 1001u);
}

// A trace call that breaks a rule ends the call there: the plugin's next step (here a write past its
// array with the index it just traced wrongly, a crash in the mutants that did so) never runs.
TEST(PluginBounds, ATraceCallThatBreaksARuleEndsTheCall) {
  bool went_on = false;
  g_body = [&went_on](void**, const nbscope_frame*, const nbscope_output*, const nbscope_trace* t) {
    static const std::int32_t heads[2] = {-1, -1};
    const std::int64_t shape[1] = {2};
    const int array = t->declare_array(t->ctx, "heads", 1, shape, heads);
    t->phase(t->ctx, 0, "rows", 0);
    t->set(t->ctx, 1, "head", array, 2, -1);  // entry 2 of a 2-entry array
    went_on = true;
    return 0;
  };
  PluginDetector detector(symbols(), info());
  PairList pairs;
  TraceLog log;
  detector.detect_traced(three(), DetectOptions{}, pairs, log);
  EXPECT_FALSE(went_on);
  ASSERT_NE(detector.misbehaviour(), nullptr);
  EXPECT_EQ(detector.misbehaviour()->text, "trace set: index 2 is outside array 0 of 2 entries");
  EXPECT_TRUE(detector.misbehaviour()->cut);
  EXPECT_EQ(detector.misbehaviour()->operations, 1u) << "after the phase, where the call ended";
  EXPECT_EQ(log.events().size(), 1u);
}

// The cells a plugin writes end at a guard page: one past the end faults (where the crash report
// names the call), never the heap behind them.
TEST(PluginBounds, TheCellsBufferEndsAtAGuardPage) {
  GuardedInts cells;
  cells.assign(6, -1);
  EXPECT_EQ(cells.view().size(), 6u);
  EXPECT_EQ(cells.view()[5], -1);
  EXPECT_DEATH({ cells.data()[6] = 7; }, "");
  cells.assign(1000, 0);  // grown: a new mapping, its end at the guard again
  EXPECT_DEATH({ cells.data()[1000] = 7; }, "");
}

}  // namespace
}  // namespace nbscope

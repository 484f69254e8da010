// io/plugin_host: a plugin in a process of its own gives what it gives in nbscope's (pairs, cells,
// walk check, misbehaviour, every trace event), and a crash, an abort or a hang in its detection is
// that frame's misbehaviour, located after the last operation it traced, with nbscope still running
// and the next frame detected by a new host. io/plugin_wire's messages round-trip and refuse a cut one.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <memory>
#include <string>

#include "core/error.hpp"
#include "core/plugin_detector.hpp"
#include "io/plugin_host.hpp"
#include "io/plugin_library.hpp"
#include "io/plugin_wire.hpp"
#include "support/generators.hpp"

namespace nbscope {
namespace {

// A library's two detectors: in nbscope's process and isolated, over the same description.
struct BothWays {
  std::unique_ptr<Detector> in_process;
  std::unique_ptr<IsolatedPluginDetector> isolated;
};

std::string library(const std::string& file) {
  return file.rfind("test_", 0) == 0 ? std::string(NBSCOPE_PLUGIN_DIR) + "/" + file : std::string(NBSCOPE_EXAMPLES_DIR) + "/" + file;
}

// Loads `file` once (in-process, as the host itself does) and makes both detectors of it.
BothWays both_ways(const std::string& file, double timeout = 60) {
  static std::map<std::string, std::string> names;
  if (!names.contains(file)) {
    set_plugin_isolation(PluginIsolation::none);
    names[file] = load_detector_plugin(library(file));
  }
  BothWays both;
  both.in_process = make_detector(names[file]);
  const auto* plugin = dynamic_cast<const PluginDetector*>(both.in_process.get());
  EXPECT_NE(plugin, nullptr) << "loaded in-process, the registry makes PluginDetectors";
  both.isolated = std::make_unique<IsolatedPluginDetector>(library(file), plugin->description(), timeout);
  return both;
}

void expect_same_events(const TraceLog& a, const TraceLog& b) {
  ASSERT_EQ(a.arrays().size(), b.arrays().size());
  for (std::size_t k = 0; k < a.arrays().size(); ++k) {
    EXPECT_EQ(a.arrays()[k].name, b.arrays()[k].name);
    EXPECT_EQ(a.arrays()[k].shape, b.arrays()[k].shape);
    EXPECT_EQ(a.arrays()[k].initial, b.arrays()[k].initial);
  }
  ASSERT_EQ(a.events().size(), b.events().size());
  for (std::size_t k = 0; k < a.events().size(); ++k) {
    const TraceEvent& x = a.events()[k];
    const TraceEvent& y = b.events()[k];
    ASSERT_TRUE(x.op == y.op && x.line == y.line && x.element == y.element && x.other == y.other && x.index == y.index &&
                x.contact == y.contact && x.write_count == y.write_count && std::string(x.label) == y.label)
        << "event " << k;
    for (int w = 0; w < x.write_count; ++w)
      ASSERT_TRUE(x.writes[w].array == y.writes[w].array && x.writes[w].index == y.writes[w].index &&
                  x.writes[w].old_value == y.writes[w].old_value && x.writes[w].new_value == y.writes[w].new_value)
          << "event " << k << " write " << w;
  }
}

TEST(PluginHost, AnIsolatedPluginGivesWhatItGivesInProcessFrameAfterFrame) {
  BothWays both = both_ways("nbs_reference.so");
  for (int frame = 0; frame < 3; ++frame) {
    const Elements e = make_layout(testdata::Layout::Clustered, 600, 2, 7 + frame);
    DetectOptions options;
    options.frame = frame;
    PairList a, b;
    TraceLog ta, tb;
    both.in_process->detect_traced(e, options, a, ta);
    both.isolated->detect_traced(e, options, b, tb);
    EXPECT_EQ(a, b);
    EXPECT_GT(ta.events().size(), 600u);
    expect_same_events(ta, tb);
    ASSERT_NE(both.isolated->own_cells(), nullptr);
    EXPECT_EQ(*both.in_process->own_cells(), *both.isolated->own_cells());
    EXPECT_EQ(both.isolated->misbehaviour(), nullptr);
    EXPECT_EQ(both.in_process->own_bytes(), both.isolated->own_bytes());
    options.check_walks = true;  // untraced, its walks checked
    both.in_process->detect(e, options, a);
    both.isolated->detect(e, options, b);
    EXPECT_EQ(a, b);
    ASSERT_NE(both.isolated->walk_check(), nullptr);
    EXPECT_EQ(both.isolated->walk_check()->count, both.in_process->walk_check()->count);
  }
}

TEST(PluginHost, AMisbehaviourAndAnErrorCrossAsThemselves) {
  BothWays both = both_ways("test_plugin_self_pair.so");
  const Elements e = make_layout(testdata::Layout::Dense, 50, 2, 1);
  PairList a, b;
  both.in_process->detect(e, DetectOptions{}, a);
  both.isolated->detect(e, DetectOptions{}, b);
  ASSERT_NE(both.isolated->misbehaviour(), nullptr);
  EXPECT_EQ(both.isolated->misbehaviour()->text, both.in_process->misbehaviour()->text);
  EXPECT_EQ(both.isolated->misbehaviour()->where, both.in_process->misbehaviour()->where);
  EXPECT_EQ(a, b);
  DetectOptions few;
  few.max_pairs = 1;  // the pair limit: nbscope's Error, thrown on this side too
  EXPECT_THROW(both.isolated->detect(e, few, b), Error);
  BothWays failing = both_ways("test_plugin_long_fail.so");
  EXPECT_THROW(failing.isolated->detect(e, DetectOptions{}, b), PluginError);
}

// test_plugin_crash.so writes through NULL on frame 3: a misbehaviour of frame 3, then frame 4 is
// detected by a new host (the plugin's state starts again), and the answers are right again.
TEST(PluginHost, ACrashIsItsFramesMisbehaviourAndTheNextFrameRunsInANewHost) {
  BothWays both = both_ways("test_plugin_crash.so");
  const Elements e = make_layout(testdata::Layout::Dense, 80, 2, 3);
  PairList good, pairs;
  both.in_process->detect(e, DetectOptions{}, good);
  for (std::int64_t frame = 0; frame < 5; ++frame) {
    DetectOptions options;
    options.frame = frame;
    both.isolated->detect(e, options, pairs);
    if (frame != 3) {
      EXPECT_EQ(both.isolated->misbehaviour(), nullptr) << frame;
      EXPECT_EQ(pairs, good) << frame;
      continue;
    }
    ASSERT_NE(both.isolated->misbehaviour(), nullptr);
    const Misbehaviour& m = *both.isolated->misbehaviour();
    EXPECT_EQ(m.text.rfind("crashed with SIGSEGV in nbscope_detect() on frame 3", 0), 0u) << m.text;
    EXPECT_NE(m.text.find("the next frame starts a new host process"), std::string::npos) << m.text;
    EXPECT_TRUE(m.cut);
    EXPECT_EQ(m.where, library("test_plugin_crash.so") + " (test-crash): frame 3: ");
    EXPECT_TRUE(pairs.empty());
  }
}

// A traced crash (the reference with a visit past the grid): located after the operation it last
// traced, the trace up to there recorded again and ending there.
TEST(PluginHost, ATracedCrashIsLocatedAndItsTraceRecordedUpToIt) {
  BothWays both = both_ways("test_bug_crash_traced.so");
  const Elements e = make_layout(testdata::Layout::Dense, 400, 2, 5);
  PairList pairs;
  TraceLog trace;
  both.isolated->detect_traced(e, DetectOptions{}, pairs, trace);
  ASSERT_NE(both.isolated->misbehaviour(), nullptr);
  const Misbehaviour& m = *both.isolated->misbehaviour();
  EXPECT_NE(m.text.find("crashed with SIGSEGV in nbscope_detect() on frame 0, after operation " + std::to_string(m.operations) +
                        " of its trace (visit-cell, pseudocode line 7)"),
            std::string::npos)
      << m.text;
  EXPECT_GT(m.operations, 0u);
  EXPECT_EQ(trace.events().size(), m.operations);
  EXPECT_EQ(trace.events().back().op, TraceOp::VisitCell);
}

// A plugin that corrupts its heap (a double free: glibc aborts, a sanitizer reports and exits) takes
// only its host down; so does one that never returns, at the timeout.
TEST(PluginHost, AnAbortOrAHangEndsOnlyTheHost) {
  const Elements e = make_layout(testdata::Layout::Dense, 40, 2, 9);
  PairList pairs;
  DetectOptions options;
  options.frame = 1;
  BothWays smash = both_ways("test_plugin_heap_smash.so");
  smash.isolated->detect(e, options, pairs);
  ASSERT_NE(smash.isolated->misbehaviour(), nullptr);
  const std::string& text = smash.isolated->misbehaviour()->text;
  EXPECT_TRUE(text.find("crashed with SIGABRT in nbscope_detect() on frame 1") == 0 || text.find("its host process exited with status") == 0)
      << text;
  options.frame = 2;
  BothWays hang = both_ways("test_plugin_hang.so", 1);
  hang.isolated->detect(e, options, pairs);
  ASSERT_NE(hang.isolated->misbehaviour(), nullptr);
  EXPECT_EQ(hang.isolated->misbehaviour()->text.rfind("did not return within 1 s in nbscope_detect() on frame 2", 0), 0u)
      << hang.isolated->misbehaviour()->text;
  options.frame = 3;
  hang.isolated->detect(e, options, pairs);  // a new host, a frame it returns from
  EXPECT_EQ(hang.isolated->misbehaviour(), nullptr);
}

TEST(PluginHost, AMissingHostIsSaidAtOnce) {
  ::setenv("NBSCOPE_PLUGIN_HOST", "/nonexistent/nbscope-plugin-host", 1);
  try {
    plugin_host_path();
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "NBSCOPE_PLUGIN_HOST: /nonexistent/nbscope-plugin-host is not an executable file");
  }
  ::unsetenv("NBSCOPE_PLUGIN_HOST");
  EXPECT_NO_THROW(plugin_host_path());
}

TEST(PluginWire, ARequestAndAReplyRoundTripAndACutMessageIsRefused) {
  const Elements e = make_layout(testdata::Layout::Dense, 30, 3, 2);
  DetectRequest request;
  request.options.frame = 42;
  request.options.max_pairs = 77;
  request.options.grid.cells = std::array<std::int64_t, 3>{4, 5, 6};
  request.options.check_walks = true;
  request.traced = true;
  request.keep_tests = false;
  request.operation_limit = 9;
  WireWriter out;
  encode(e, request, out);
  WireReader in(out.bytes().data(), out.bytes().size());
  const DetectRequest back = decode_request(in);
  EXPECT_EQ(back.elements.dim, 3);
  EXPECT_TRUE((back.elements.z == e.z).all() && (back.elements.r == e.r).all());
  EXPECT_EQ(back.options.frame, 42);
  EXPECT_EQ(back.options.max_pairs, 77u);
  EXPECT_EQ(back.options.grid.cells, request.options.grid.cells);
  EXPECT_FALSE(back.options.grid.cell_size.has_value());
  EXPECT_TRUE(back.options.check_walks && back.traced && !back.keep_tests);
  EXPECT_EQ(back.operation_limit, 9);

  DetectReply reply;
  reply.pairs = {{0, 1}, {2, 5}};
  reply.misbehaviour = Misbehaviour{"add_pair(3, 3): an element paired with itself", {3, 3}, 12, true, false, -1, -1, "lib.so (x): frame 0: "};
  TraceLog trace;
  const std::int32_t heads[2] = {-1, -1};
  trace.declare_array("heads", {2}, heads);
  trace.push(1, "y-list", 0, 1, 0, 4, -1, -1, 0, 1, -1);
  trace.phase(2, "rows", 3);
  out.restart(0);
  encode(reply, &trace, out);
  std::vector<TraceEvent> scratch;
  DetectReply got;
  TraceLog got_trace;
  WireReader reply_in(out.bytes().data(), out.bytes().size());
  decode_reply(reply_in, got, &got_trace, scratch);
  EXPECT_EQ(got.pairs, reply.pairs);
  ASSERT_TRUE(got.misbehaviour.has_value());
  EXPECT_EQ(got.misbehaviour->text, reply.misbehaviour->text);
  EXPECT_EQ(got.misbehaviour->operations, 12u);
  expect_same_events(trace, got_trace);
  for (const std::size_t cut : {std::size_t{0}, std::size_t{7}, out.bytes().size() - 1}) {
    WireReader short_in(out.bytes().data(), cut);
    EXPECT_THROW(decode_reply(short_in, got, &got_trace, scratch), Error) << cut;
  }
}

}  // namespace
}  // namespace nbscope

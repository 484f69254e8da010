// The frame history: a kept past frame shows exactly what the live frame showed (elements, shapes,
// pairs, every check set and report), resuming from it reproduces the original run bit for bit,
// the memory budget drops the oldest states only, and the run's violation log follows re-checks.
#include <gtest/gtest.h>

#include <map>

#include "support/frame_facts.hpp"
#include "support/paths.hpp"
#include "app/frame_loop.hpp"
#include "check/history.hpp"
#include "core/error.hpp"
#include "io/scene_json.hpp"
#include "physics/box2d_detector.hpp"

namespace nbscope {
namespace {

const bool kRegistered = (register_physics_detectors(), true);

using testpaths::scene;

using testframes::expect_same_frame;
using testframes::facts_of;
using testframes::FrameFacts;

// Loads default.json into `loop` and steps it `frames` frames.
void run_default(FrameLoop& loop, int frames) {
  load_scene_file(loop, scene("default"));
  for (int k = 0; k < frames; ++k) loop.step();
}

TEST(PackedPairs, RoundTripsSortedPairs) {
  PairList pairs = {{0, 1}, {0, 7}, {0, 300000}, {2, 3}, {2, 200}, {150, 151}, {150, 9000}, {70000, 70001}};
  PairList back;
  PackedPairs::pack(pairs).unpack(back);
  EXPECT_EQ(back, pairs);
  PackedPairs::pack({}).unpack(back);
  EXPECT_TRUE(back.empty());
  // A dense random-ish list packs to well under 8 bytes a pair.
  PairList many;
  for (ElementId i = 0; i < 5000; ++i)
    for (ElementId d = 1; d <= 6; ++d) many.push_back({i, i + d * 3});
  const PackedPairs packed = PackedPairs::pack(many);
  packed.unpack(back);
  EXPECT_EQ(back, many);
  EXPECT_LT(packed.bytes(), many.size() * 3);
}

// Every kept frame of three scenes (circles, boxes, polygons, emitters) rebuilt from the history
// gives the live frame's elements, shapes and check sets bit for bit.
TEST(History, AKeptFrameIsTheLiveFrameAgain) {
  ASSERT_TRUE(kRegistered);
  for (const char* name : {"default", "mixed-sizes", "pile"}) {
    SCOPED_TRACE(name);
    FrameLoop loop;
    load_scene_file(loop, scene(name));
    std::map<std::int64_t, FrameFacts> live;
    live[0] = facts_of(loop);
    for (int k = 1; k <= 60; ++k) {
      loop.step();
      live[k] = facts_of(loop);
    }
    // Every fifth kept frame and the two ends, newest first (as scrubbing back goes).
    std::vector<std::int64_t> shown{60, 59};
    for (std::int64_t k = 55; k >= 0; k -= 5) shown.push_back(k);
    shown.push_back(1);
    for (const std::int64_t k : shown) {
      loop.show_frame(k);
      EXPECT_EQ(loop.source().frame(), k);
      EXPECT_EQ(loop.history().showing_past(), k != 60);
      expect_same_frame(live[k], facts_of(loop));
    }
  }
}

// Resuming from a past frame re-simulates the scene to it and continues exactly as the original run.
TEST(History, ResumingReproducesTheOriginalRun) {
  ASSERT_TRUE(kRegistered);
  for (const char* name : {"default", "pile"}) {
    SCOPED_TRACE(name);
    FrameLoop straight, rewound;
    load_scene_file(straight, scene(name));
    load_scene_file(rewound, scene(name));
    std::vector<std::uint64_t> hashes{straight.result().report().hash};
    for (int k = 1; k <= 120; ++k) {
      straight.step();
      hashes.push_back(straight.result().report().hash);
    }
    for (int k = 1; k <= 90; ++k) rewound.step();
    rewound.show_frame(30);
    ASSERT_TRUE(rewound.history().showing_past());
    rewound.resume().begin();
    ASSERT_TRUE(rewound.resume().active());
    while (!rewound.resume().advance(1.0)) {
    }
    EXPECT_FALSE(rewound.history().showing_past());
    EXPECT_FALSE(rewound.resume().divergence().has_value());
    EXPECT_EQ(rewound.source().frame(), 30);
    EXPECT_EQ(rewound.history().newest_frame(), 30);
    EXPECT_EQ(rewound.history().frames().summaries().back().frame, 30);
    EXPECT_EQ(rewound.result().report().hash, hashes[30]);
    for (int k = 31; k <= 120; ++k) {
      rewound.step();
      ASSERT_EQ(rewound.result().report().hash, hashes[static_cast<std::size_t>(k)]) << "frame " << k;
    }
  }
}

// Steps `loop` over frames [from, to): on frame 10 it grabs the last element (a dynamic circle of the
// default scene), pulls it along until frame `release_at`, lets go there.
void drive_with_drag(FrameLoop& loop, int from, int to, int release_at) {
  for (int k = from; k < to; ++k) {
    if (k == 10) {
      const Elements& e = loop.source().elements();
      ASSERT_TRUE(loop.drag().begin(e.x[e.size() - 1], e.y[e.size() - 1]));
    }
    if (k > 10 && k < release_at) loop.drag().move_to(static_cast<double>(k) * 0.1, 8.0);
    if (k == release_at) loop.drag().end();
    loop.step();
  }
}

// Drags are replayed: a run with a mouse drag, rewound past it, reaches the same frames again.
TEST(History, ResumingReplaysDrags) {
  ASSERT_TRUE(kRegistered);
  FrameLoop straight, rewound;
  for (FrameLoop* loop : {&straight, &rewound}) load_scene_file(*loop, scene("default"));
  const auto drive = [](FrameLoop& loop, int from, int to) { drive_with_drag(loop, from, to, 30); };
  drive(straight, 0, 80);
  drive(rewound, 0, 60);
  rewound.show_frame(40);
  rewound.resume().begin();
  while (!rewound.resume().advance(5.0)) {
  }
  EXPECT_FALSE(rewound.resume().divergence().has_value());
  drive(rewound, 40, 80);
  EXPECT_EQ(rewound.result().report().hash, straight.result().report().hash);
  // The drag mattered: without it frame 80 is another.
  FrameLoop undisturbed;
  run_default(undisturbed, 80);
  EXPECT_NE(undisturbed.result().report().hash, straight.result().report().hash);
}

// Leaving the live frame while a body is held lets it go, as the user's own release would, and a
// later resume replays that release too.
TEST(History, ADragHeldWhenGoingBackIsReleasedAndReplayed) {
  ASSERT_TRUE(kRegistered);
  FrameLoop straight, viewer;
  for (FrameLoop* loop : {&straight, &viewer}) load_scene_file(*loop, scene("default"));
  drive_with_drag(straight, 0, 60, 20);  // let go on frame 20
  drive_with_drag(viewer, 0, 20, 20);    // still holding the body on frame 20
  ASSERT_TRUE(viewer.drag().active());
  viewer.show_frame(15);  // still holding the body: it is let go at frame 20
  EXPECT_FALSE(viewer.drag().active());
  viewer.show_frame(20);
  EXPECT_FALSE(viewer.drag().active());
  for (int k = 20; k < 60; ++k) viewer.step();
  EXPECT_EQ(viewer.result().report().hash, straight.result().report().hash);
  // Resumed from frame 30, the re-simulation replays the drag and its release.
  viewer.show_frame(30);
  viewer.resume().begin();
  while (!viewer.resume().advance(5.0)) {
  }
  EXPECT_FALSE(viewer.resume().divergence().has_value());
  for (int k = 30; k < 60; ++k) viewer.step();
  EXPECT_EQ(viewer.result().report().hash, straight.result().report().hash);
}

// Switching the checks off does not erase what they found: the run's violations stay listed.
TEST(History, ChecksSwitchedOffKeepTheRunsViolations) {
  ASSERT_TRUE(kRegistered);
  FrameLoopOptions o;
  o.fault = Fault::DropPair;
  FrameLoop loop(o);
  run_default(loop, 10);
  const std::int64_t total = loop.history().violation_log().total();
  ASSERT_GT(total, 0);
  loop.redetect_with_checks(false);
  EXPECT_EQ(loop.history().violation_log().total(), total);
  loop.show_frame(5);
  EXPECT_EQ(loop.history().violation_log().total(), total);
  EXPECT_TRUE(loop.history().frames().at(5).checked);
  EXPECT_GT(loop.history().frames().at(5).violations, 0);
}

TEST(History, ThePastIsReadOnlyUntilResumed) {
  ASSERT_TRUE(kRegistered);
  FrameLoop loop;
  run_default(loop, 20);
  loop.show_frame(5);
  const Elements& e = loop.source().elements();
  EXPECT_FALSE(loop.drag().begin(e.x[e.size() - 1], e.y[e.size() - 1]));  // resume first
  loop.step();  // moves through the kept frames, simulates nothing
  EXPECT_EQ(loop.source().frame(), 6);
  EXPECT_EQ(loop.history().newest_frame(), 20);
  loop.show_frame(20);
  EXPECT_FALSE(loop.history().showing_past());
  loop.step();
  EXPECT_EQ(loop.history().newest_frame(), 21);
}

TEST(History, TheBudgetDropsTheOldestStatesOnly) {
  ASSERT_TRUE(kRegistered);
  FrameLoop loop;
  run_default(loop, 50);
  const std::size_t all = loop.history().frames().bytes();
  loop.history().set_budget(all / 4);
  EXPECT_LE(loop.history().frames().bytes(), all / 4 + 51 * sizeof(FrameSummary));
  EXPECT_EQ(loop.history().frames().size(), 51u);  // every summary stays
  const auto first = loop.history().frames().first_kept();
  ASSERT_TRUE(first.has_value());
  EXPECT_GT(*first, 0);
  EXPECT_FALSE(loop.history().can_show(0));
  EXPECT_TRUE(loop.history().can_show(50));
  EXPECT_THROW(loop.show_frame(0), Error);
  try {
    loop.show_frame(1);
  } catch (const Error& err) {
    EXPECT_NE(std::string(err.what()).find("not kept"), std::string::npos) << err.what();
  }
  loop.show_frame(*first);
  EXPECT_EQ(loop.history().neighbour(-1), std::nullopt);  // nothing older can be shown
  EXPECT_EQ(loop.history().neighbour(-10), std::nullopt);
  EXPECT_EQ(loop.history().neighbour(+3), *first + 3);
  loop.history().set_budget(0);  // only the newest stays
  EXPECT_EQ(loop.history().frames().first_kept(), 50);
}

TEST(History, TheViolationLogFollowsTheRun) {
  ASSERT_TRUE(kRegistered);
  FrameLoopOptions o;
  o.fault = Fault::DropPair;
  FrameLoop loop(o);
  run_default(loop, 30);
  const ViolationLog& log = loop.history().violation_log();
  EXPECT_GT(log.total(), 0);
  EXPECT_EQ(log.total(), static_cast<std::int64_t>(log.listed().size()));
  for (std::size_t k = 1; k < log.listed().size(); ++k) EXPECT_LE(log.listed()[k - 1].frame, log.listed()[k].frame);
  const std::int64_t total = log.total();
  // Showing a frame again checks it again: its violations are replaced, not added.
  loop.show_frame(10);
  EXPECT_EQ(log.total(), total);
  loop.redetect_with_fault(Fault::None);  // frame 10 re-checked without the fault
  EXPECT_LT(log.total(), total);
  for (const Violation& v : log.listed()) EXPECT_NE(v.frame, 10);
  // Resuming from frame 10 drops the later frames' violations.
  loop.resume().begin();
  while (!loop.resume().advance(5.0)) {
  }
  for (const Violation& v : log.listed()) EXPECT_LT(v.frame, 10);
  EXPECT_EQ(loop.history().frames().summaries().back().frame, 10);
}

// A replay scrubbed back, frame by frame, shows the pairs and check results it showed played forwards.
TEST(History, AReplayScrubbedBackShowsWhatItShowedForwards) {
  ASSERT_TRUE(kRegistered);
  FrameLoop source;
  load_scene_file(source, scene("mixed-sizes"));
  Recording rec;
  rec.path = "mixed.nbsrec";
  for (int k = 0; k <= 40; ++k) {
    if (k > 0) source.step();
    RecordedFrame f;
    f.number = source.source().frame();
    f.time = source.source().time();
    f.elements = source.source().elements();
    rec.frames.push_back(std::move(f));
  }
  FrameLoopOptions o;
  o.fault = Fault::DropMaskCell;  // violations too, so the check results are compared as well
  FrameLoop loop(o);
  loop.load_recording(rec);
  std::map<std::int64_t, std::pair<PairList, std::array<std::int64_t, kInvariantCount>>> forwards;
  forwards[loop.source().frame()] = {loop.result().selected().pairs, loop.result().report().broken};
  while (!loop.source().at_end()) {
    loop.step();
    forwards[loop.source().frame()] = {loop.result().selected().pairs, loop.result().report().broken};
  }
  ASSERT_EQ(forwards.size(), 41u);
  std::int64_t broken = 0;
  for (std::int64_t k = 40; k >= 0; --k) {
    if (k < 40) {
      const auto previous = loop.history().neighbour(-1);
      ASSERT_TRUE(previous.has_value());
      loop.show_frame(*previous);
    }
    ASSERT_EQ(loop.source().frame(), k);
    EXPECT_EQ(loop.result().selected().pairs, forwards[k].first) << "frame " << k;
    EXPECT_EQ(loop.result().report().broken, forwards[k].second) << "frame " << k;
    for (const std::int64_t b : loop.result().report().broken) broken += b;
  }
  EXPECT_GT(broken, 0);
  EXPECT_EQ(loop.history().neighbour(-1), std::nullopt);
}

TEST(History, ARecordingIsItsOwnHistory) {
  ASSERT_TRUE(kRegistered);
  Recording rec;
  rec.path = "mem.nbsrec";
  for (int f = 0; f < 5; ++f) {
    RecordedFrame frame;
    frame.number = f * 2;
    frame.time = f * 0.1;
    frame.elements = make_elements_2d(Eigen::ArrayXd::LinSpaced(4, 0, 3) + 0.1 * f, Eigen::ArrayXd::Zero(4),
                                      Eigen::ArrayXd::Constant(4, 0.6));
    rec.frames.push_back(frame);
  }
  FrameLoop loop;
  loop.load_recording(rec);
  EXPECT_EQ(loop.history().frames().size(), 5u);
  EXPECT_TRUE(loop.history().frames().at(0).checked);
  EXPECT_FALSE(loop.history().frames().at(3).checked);  // not shown yet
  EXPECT_EQ(loop.history().newest_frame(), 8);
  loop.show_frame(6);
  EXPECT_EQ(loop.source().frame(), 6);
  EXPECT_TRUE(loop.history().frames().at(3).checked);
  EXPECT_EQ(loop.history().neighbour(-1), 4);
  EXPECT_EQ(loop.history().neighbour(+5), 8);
  EXPECT_FALSE(loop.history().showing_past());  // recorded frames are all "recorded", none is live
  loop.resume().begin();                // nothing to resume
  EXPECT_FALSE(loop.resume().active());
  std::vector<std::array<double, 2>> path;
  loop.history().element_path(1, 0, 8, path);
  ASSERT_EQ(path.size(), 5u);
  EXPECT_DOUBLE_EQ(path[4][0], 1.4);
}

}  // namespace
}  // namespace nbscope

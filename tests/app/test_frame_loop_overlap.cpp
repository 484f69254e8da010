// The overlapped step the window uses (FrameLoop::begin_step, then step() adopts it): every frame
// equals the plain step()'s bit for bit (elements, shapes, pairs, every check set and report); while
// the step is in flight the accessors keep showing the current frame; every call that needs the
// world adopts the step first; drags, faults, history and loads behave as with plain steps. The
// window's asynchronous use (draw the newest frame until step_ready(), then adopt; pause, single
// steps and Timeline jumps at a frame boundary) gives the plain run's frames too.
#include <gtest/gtest.h>

#include <functional>
#include <thread>

#include "support/frame_facts.hpp"
#include "support/paths.hpp"
#include "app/frame_loop.hpp"
#include "core/error.hpp"
#include "physics/box2d_detector.hpp"

namespace nbscope {
namespace {

const bool kRegistered = (register_physics_detectors(), true);

using testpaths::scene;

using testframes::expect_same_frame;
using testframes::facts_of;
using testframes::same_elements;
using Facts = testframes::FrameFacts;

// Runs `frames` frames of `name` twice, with plain steps and overlapped ones, calling `on_frame`
// on both loops at every frame (before the next step is begun), and compares every frame.
void compare_runs(const std::string& name, int frames, FrameLoopOptions options,
                  const std::function<void(FrameLoop&, int)>& on_frame = {}) {
  SCOPED_TRACE(name);
  FrameLoop plain(options), overlapped(options);
  load_scene_file(plain, scene(name));
  load_scene_file(overlapped, scene(name));
  expect_same_frame(facts_of(plain), facts_of(overlapped));
  for (int k = 1; k <= frames; ++k) {
    if (on_frame) {
      on_frame(plain, k - 1);
      on_frame(overlapped, k - 1);
    }
    plain.step();
    overlapped.begin_step();
    ASSERT_TRUE(overlapped.source().step_pending());
    overlapped.step();
    ASSERT_FALSE(overlapped.source().step_pending());
    EXPECT_TRUE(overlapped.source().physics_overlapped());
    EXPECT_FALSE(plain.source().physics_overlapped());
    EXPECT_TRUE(overlapped.source().detection_overlapped()) << "detected and checked on the worker too";
    EXPECT_FALSE(plain.source().detection_overlapped());
    EXPECT_GE(overlapped.result().report().timings.physics_ms, 0);
    expect_same_frame(facts_of(plain), facts_of(overlapped));
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_EQ(plain.history().frames().size(), overlapped.history().frames().size());
  EXPECT_EQ(plain.history().violation_log().total(), overlapped.history().violation_log().total());
}

// Circles, boxes and polygons, emitters (default.json adds bodies as it runs), a pile.
TEST(FrameLoopOverlap, OverlappedStepsGiveThePlainStepsFrames) {
  ASSERT_TRUE(kRegistered);
  for (const char* name : {"default", "mixed-sizes", "pile"}) compare_runs(name, 60, {});
}

TEST(FrameLoopOverlap, SameFramesWithEveryFaultAndAComparisonLane) {
  for (const Fault fault : {Fault::StalePositions, Fault::DropPair, Fault::OffByOneCell, Fault::DropBox2dContact}) {
    SCOPED_TRACE(fault_name(fault));
    FrameLoopOptions options;
    options.fault = fault;
    compare_runs("default", 25, options, [](FrameLoop& loop, int k) {
      if (k == 0) loop.redetect_with_comparisons({"screen", "box2d"});
      if (k == 10) loop.redetect_with_checks(false);
      if (k == 15) loop.redetect_with_checks(true);
    });
  }
}

// A drag made while the step is in flight acts on the newest frame, as it does between plain steps.
TEST(FrameLoopOverlap, DragsGiveThePlainRunsFrames) {
  FrameLoop plain, overlapped;
  load_scene_file(plain, scene("default"));
  load_scene_file(overlapped, scene("default"));
  for (int k = 0; k < 20; ++k) {
    plain.step();
    overlapped.begin_step();
    overlapped.step();
  }
  // A dynamic body to grab, at the newest frame.
  std::vector<BodyShape> shapes;
  plain.source().body_shapes(shapes);
  const auto grabbed = std::find_if(shapes.begin(), shapes.end(),
                                    [](const BodyShape& s) { return s.body_type == BodyType::Dynamic && s.form == ShapeForm::Circle; });
  ASSERT_NE(grabbed, shapes.end());
  const Vec2 at = grabbed->centre;
  for (int k = 0; k < 30; ++k) {
    overlapped.begin_step();
    // Plain: the step, then the drag on the frame it made. Overlapped: the drag asked for while the
    // step runs adopts it first, so it lands on the same frame.
    plain.step();
    if (k == 0) {
      EXPECT_TRUE(plain.drag().begin(at.x, at.y));
      EXPECT_TRUE(overlapped.drag().begin(at.x, at.y));
    }
    if (k > 0 && k < 20) {
      plain.drag().move_to(at.x + 0.2 * k, at.y + 0.1 * k);
      overlapped.drag().move_to(at.x + 0.2 * k, at.y + 0.1 * k);
    }
    if (k == 20) {
      plain.drag().end();
      overlapped.drag().end();
    }
    if (overlapped.source().step_pending()) overlapped.step();  // frames without a drag call
    EXPECT_EQ(plain.drag().active(), overlapped.drag().active());
    expect_same_frame(facts_of(plain), facts_of(overlapped));
    if (HasFailure()) return;
  }
}

// The step in flight is detected and checked on the worker: once it is done, and before it is
// adopted, the result the window reads is still the shown frame's (pairs, report, trace), and the
// adopted frame's result is the plain step's, pair for pair.
TEST(FrameLoopOverlap, TheStepInFlightIsDetectedOnTheWorkerWhileTheShownResultStays) {
  FrameLoop plain, loop;
  load_scene_file(plain, scene("default"));
  load_scene_file(loop, scene("default"));
  for (int k = 0; k < 5; ++k) {
    plain.step();
    loop.step();
  }
  const PairList shown = loop.result().selected().pairs;
  loop.begin_step();
  ASSERT_TRUE(loop.source().step_pending());
  while (!loop.source().step_ready()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_EQ(loop.result().frame, 5) << "the worker's detection is not what the window reads";
  EXPECT_EQ(loop.result().selected().pairs, shown);
  const auto trace = loop.pipeline().frame_trace();
  ASSERT_NE(trace, nullptr);
  EXPECT_EQ(trace->frame, 5);
  PairList traced = trace->pairs;  // in the book's loop order
  sort_pairs(traced);
  EXPECT_EQ(traced, shown) << "the shown frame's trace, made beside the worker";
  loop.step();
  plain.step();
  EXPECT_EQ(loop.result().frame, 6);
  EXPECT_EQ(loop.result().selected().pairs, plain.result().selected().pairs);
  EXPECT_EQ(loop.result().report().violation_count(), plain.result().report().violation_count());
  EXPECT_EQ(loop.result().reference, plain.result().reference);
}

// Between begin_step() and the adoption every accessor shows the current frame, although the world
// underneath is already being stepped to the next.
TEST(FrameLoopOverlap, WhileTheStepRunsTheCurrentFrameIsShown) {
  FrameLoop loop;
  load_scene_file(loop, scene("default"));
  for (int k = 0; k < 10; ++k) loop.step();
  const Facts before = facts_of(loop);
  const std::size_t kept = loop.history().frames().size();
  loop.begin_step();
  ASSERT_TRUE(loop.source().step_pending());
  expect_same_frame(before, facts_of(loop));
  EXPECT_EQ(loop.history().newest_frame(), 10);
  EXPECT_TRUE(loop.history().can_show(10));
  EXPECT_FALSE(loop.history().can_show(11));
  EXPECT_EQ(loop.history().frames().size(), kept);
  EXPECT_EQ(loop.source().element_sources().size(), static_cast<std::size_t>(before.elements.size()));
  EXPECT_FALSE(loop.drag().active());
  std::vector<std::array<double, 2>> path;
  loop.history().element_path(0, 0, 10, path);
  EXPECT_EQ(path.size(), 11u);
  EXPECT_EQ(path.back()[0], before.elements.x[0]);
  const auto trace = loop.pipeline().frame_trace();
  ASSERT_NE(trace, nullptr);
  EXPECT_EQ(trace->frame, 10);
  EXPECT_TRUE(same_elements(trace->elements, before.elements));
  loop.begin_step();  // already pending: nothing more
  EXPECT_EQ(loop.source().frame(), 10);
  loop.step();
  EXPECT_EQ(loop.source().frame(), 11);
  std::vector<std::array<double, 2>> settled;
  loop.history().element_path(0, 0, 10, settled);
  EXPECT_EQ(path, settled) << "a trail read while the worker stepped is the one read after";
  EXPECT_EQ(loop.history().frames().size(), kept + 1);
  EXPECT_EQ(loop.history().newest_frame(), 11);
}

// A view reads the selection's trail at every draw, also while the worker steps the world (whose
// emitters add fixtures meanwhile): the path comes from the kept states and the snapshot, never from
// the world, so it neither waits for the step nor races it (the TSan build runs this), and it is
// the path a settled loop gives.
TEST(FrameLoopOverlap, TheTrailIsReadWhileTheWorkerStepsWithoutWaiting) {
  FrameLoop loop;
  load_scene_file(loop, scene("default"));  // its emitter pours bodies in over the first frames
  for (int k = 0; k < 30; ++k) {
    loop.begin_step();
    ASSERT_TRUE(loop.source().step_pending());
    const std::int64_t shown = loop.source().frame();
    const ElementId last = loop.source().elements().size() - 1;  // the newest body's, the latest to exist
    std::vector<std::array<double, 2>> during, after;
    for (const ElementId e : {ElementId{0}, last}) {
      loop.history().element_path(e, shown - 239, shown, during);
      EXPECT_TRUE(loop.source().step_pending() || loop.source().step_ready());
      ASSERT_FALSE(during.empty());
      EXPECT_EQ(during.back()[0], loop.source().elements().x[e]) << "ends at the frame shown";
    }
    loop.step();
    loop.history().element_path(last, shown - 239, shown, after);
    EXPECT_EQ(during, after) << "frame " << shown;
  }
}

// Calls that need the world adopt the step first: the run stays whole and nothing is lost.
TEST(FrameLoopOverlap, CallsThatNeedTheWorldAdoptTheStepFirst) {
  FrameLoop plain, loop;
  load_scene_file(plain, scene("default"));
  load_scene_file(loop, scene("default"));
  for (int k = 0; k < 10; ++k) {
    plain.step();
    loop.step();
  }
  // A new algorithm: the adopted frame is detected with it.
  plain.step();
  plain.redetect_with_algorithm("screen");
  loop.begin_step();
  loop.redetect_with_algorithm("screen");
  EXPECT_FALSE(loop.source().step_pending());
  expect_same_frame(facts_of(plain), facts_of(loop));
  EXPECT_TRUE(loop.source().physics_overlapped());
  // A past frame: the newest is adopted into the history first.
  loop.begin_step();
  loop.show_frame(5);
  EXPECT_EQ(loop.source().frame(), 5);
  EXPECT_EQ(loop.history().newest_frame(), 12);
  EXPECT_TRUE(loop.history().showing_past());
  loop.begin_step();  // nothing on a past frame
  EXPECT_FALSE(loop.source().step_pending());
  loop.show_frame(12);
  // Redetect, a fault, a restart, another scene, the destructor: none leaves a step behind.
  loop.begin_step();
  loop.redetect();
  EXPECT_EQ(loop.source().frame(), 13);
  loop.begin_step();
  loop.redetect_with_fault(Fault::DropPair);
  EXPECT_EQ(loop.source().frame(), 14);
  loop.begin_step();
  loop.restart();
  EXPECT_FALSE(loop.source().step_pending());
  EXPECT_EQ(loop.source().frame(), 0);
  loop.begin_step();
  load_scene_file(loop, scene("pile"));
  EXPECT_EQ(loop.source().frame(), 0);
  EXPECT_EQ(loop.source().scene().name, "pile");
  loop.begin_step();
  // A scene that is refused keeps the old one, and its step still pending.
  EXPECT_THROW(load_scene_file(loop, scene("no-such-scene")), Error);
  EXPECT_TRUE(loop.source().step_pending());
  loop.step();
  EXPECT_EQ(loop.source().frame(), 1);
  loop.begin_step();  // destroyed with the step in flight
}

// The window's own use: it never waits for the worker. Until step_ready() it draws the newest
// completed frame (the accessors keep it), then adopts the step; pause, single steps, Timeline
// jumps and algorithm changes come between, each adopting the step in flight first (plain: the
// step, then the action). Every frame, the history and the violation log equal the plain run's.
void compare_async(const std::string& name, int frames, FrameLoopOptions options) {
  SCOPED_TRACE(name);
  FrameLoop plain(options), async(options);
  load_scene_file(plain, scene(name));
  load_scene_file(async, scene(name));
  bool paused = false;
  for (int k = 1; k <= frames; ++k) {
    SCOPED_TRACE("frame " + std::to_string(k));
    if (!paused) {
      const Facts shown = facts_of(async);
      async.begin_step();
      ASSERT_TRUE(async.source().step_pending());
      int polls = 0;
      while (!async.source().step_ready()) {
        if (++polls == 1) expect_same_frame(shown, facts_of(async));  // what a UI frame draws meanwhile
        std::this_thread::yield();
      }
      EXPECT_TRUE(async.source().step_pending());  // ready, not yet adopted
      if (k % 7 == 0) {
        // A Timeline jump while the step is in flight: the step is adopted first, then the past
        // frame shown, then the newest frame again (the simulation resumes live).
        plain.step();
        plain.show_frame(k - 3);
        async.show_frame(k - 3);
        expect_same_frame(facts_of(plain), facts_of(async));
        plain.show_frame(plain.history().newest_frame());
        async.show_frame(async.history().newest_frame());
      } else if (k % 11 == 0) {
        // Another algorithm for a frame, and back: the adopted frame is detected with it.
        plain.step();
        plain.redetect_with_algorithm("screen");
        async.redetect_with_algorithm("screen");
        expect_same_frame(facts_of(plain), facts_of(async));
        plain.redetect_with_algorithm("nbs");
        async.redetect_with_algorithm("nbs");
      } else {
        plain.step();
        async.step();  // adopted: no wait
        EXPECT_TRUE(async.source().physics_overlapped());
      }
    } else {
      // Paused: single steps (O) are plain steps.
      plain.step();
      async.step();
    }
    ASSERT_FALSE(async.source().step_pending());
    expect_same_frame(facts_of(plain), facts_of(async));
    if (::testing::Test::HasFailure()) return;
    if (k % 13 == 0) paused = !paused;  // pause (the step in flight was adopted), later play again
  }
  EXPECT_EQ(plain.history().frames().size(), async.history().frames().size());
  for (std::size_t i = 0; i < plain.history().frames().size(); ++i) {
    EXPECT_EQ(plain.history().frames().at(i).hash, async.history().frames().at(i).hash) << "summary " << i;
    EXPECT_EQ(plain.history().frames().at(i).pairs, async.history().frames().at(i).pairs) << "summary " << i;
    EXPECT_EQ(plain.history().frames().at(i).violations, async.history().frames().at(i).violations) << "summary " << i;
  }
  EXPECT_EQ(plain.history().violation_log().total(), async.history().violation_log().total());
}

TEST(FrameLoopOverlap, TheWindowsAsyncUseGivesThePlainRunsFrames) {
  compare_async("default", 30, {});
  compare_async("pile", 20, {});
  for (const Fault fault : {Fault::StalePositions, Fault::DropBox2dContact}) {
    SCOPED_TRACE(fault_name(fault));
    FrameLoopOptions options;
    options.fault = fault;
    compare_async("default", 20, options);
  }
}

TEST(FrameLoopOverlap, RecordingsAndEmptyLoopsStepPlainly) {
  FrameLoop empty;
  empty.begin_step();
  EXPECT_FALSE(empty.source().step_pending());
  EXPECT_FALSE(empty.source().step_ready());
  Recording rec;
  rec.path = "two.nbsrec";
  for (int k = 0; k < 2; ++k) {
    RecordedFrame f;
    f.number = k;
    f.time = k * 0.1;
    f.elements.resize(2);
    f.elements.x << 0, 0.5 + 0.1 * k;
    f.elements.y << 0, 0;
    f.elements.r << 0.3, 0.3;
    rec.frames.push_back(f);
  }
  FrameLoop loop;
  loop.load_recording(rec);
  loop.begin_step();
  EXPECT_FALSE(loop.source().step_pending());
  loop.step();
  EXPECT_EQ(loop.source().frame(), 1);
  EXPECT_FALSE(loop.source().physics_overlapped());
}

}  // namespace
}  // namespace nbscope

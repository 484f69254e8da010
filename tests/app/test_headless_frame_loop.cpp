// FrameLoop, the pipeline the window and the headless command share: one consistent frame after
// load and after every step, live switches (algorithm, fault, checks), comparison lanes, shapes,
// dragging, tracing, and errors that leave the loop usable.
#include <gtest/gtest.h>

#include "support/paths.hpp"
#include "support/generators.hpp"

#include "app/frame_loop.hpp"
#include "core/brute.hpp"
#include "core/error.hpp"
#include "io/recording.hpp"
#include "io/scene_json.hpp"
#include "physics/box2d_detector.hpp"

namespace nbscope {
namespace {

const bool kRegistered = (register_physics_detectors(), true);

using testpaths::scene;

using testdata::brute_pairs;

TEST(FrameLoop, EmptyUntilASceneIsLoaded) {
  FrameLoop loop;
  EXPECT_FALSE(loop.source().has_scene());
  loop.step();  // no effect
  EXPECT_EQ(loop.source().frame(), 0);
  EXPECT_EQ(loop.source().elements().size(), 0);
  std::vector<BodyShape> shapes;
  loop.source().body_shapes(shapes);
  EXPECT_TRUE(shapes.empty());
  EXPECT_FALSE(loop.drag().begin(0, 0));
}

// The generation moves whenever the frame shown (or what was found in it) changes, and only then,
// with the kind of change: the views derive trails, flashes and the camera from it.
TEST(FrameLoop, GenerationCountsEveryChangeOfTheShownFrame) {
  ASSERT_TRUE(kRegistered);
  using Kind = FrameChange::Kind;
  FrameLoop loop;
  const std::uint64_t empty = loop.change().generation;
  EXPECT_EQ(loop.change().kind, Kind::none);
  load_scene_file(loop, scene("default"));
  std::uint64_t g = loop.change().generation;
  EXPECT_GT(g, empty);
  EXPECT_EQ(loop.change().kind, Kind::loaded);
  EXPECT_EQ(loop.change().loaded_at, g);
  const auto moved = [&](Kind kind) {
    const bool m = loop.change().generation == g + 1 && loop.change().kind == kind && loop.change().frame == loop.source().frame();
    g = loop.change().generation;
    return m;
  };
  loop.step();
  EXPECT_TRUE(moved(Kind::stepped)) << "step";
  loop.begin_step();
  EXPECT_EQ(loop.change().generation, g) << "a step begun shows the same frame";
  loop.step();
  EXPECT_TRUE(moved(Kind::stepped)) << "the step adopted";
  EXPECT_EQ(loop.result().frame, 2);
  loop.show_frame(1);
  EXPECT_TRUE(moved(Kind::shown)) << "a past frame shown";
  loop.step();
  EXPECT_TRUE(moved(Kind::stepped)) << "forwards through the kept frames is a step";
  EXPECT_TRUE(loop.step_back());
  EXPECT_TRUE(moved(Kind::shown)) << "step_back";
  loop.resume().begin();
  while (!loop.resume().advance(1000)) {
  }
  EXPECT_TRUE(moved(Kind::shown)) << "resumed";
  EXPECT_EQ(loop.change().moved_at, g);
  loop.redetect();
  EXPECT_TRUE(moved(Kind::redetected)) << "redetect";
  loop.redetect_with_algorithm("sort");
  EXPECT_TRUE(moved(Kind::redetected)) << "algorithm";
  EXPECT_EQ(loop.change().moved_at, g - 2) << "a redetect does not move the frame shown";
  loop.begin_step();
  loop.redetect();
  EXPECT_TRUE(moved(Kind::stepped)) << "a redetect adopts the step in flight";
  loop.restart();
  EXPECT_TRUE(moved(Kind::loaded)) << "restart";
  EXPECT_EQ(loop.change().loaded_at, g);
  EXPECT_EQ(loop.change().frame, 0);
  loop.show_frame(0);
  EXPECT_EQ(loop.change().generation, g) << "nothing happened";
}

// A frame whose detection throws is not published: the views stay on the last whole frame. A load
// whose first detection threw is carried by the next change published, so no view misses it.
TEST(FrameLoop, AChangeIsPublishedOnlyOnceTheFrameIsDetected) {
  using Kind = FrameChange::Kind;
  // Two recorded frames; the second spreads its elements past any grid's cell limit at cell size 1.
  Recording rec;
  rec.path = "spread.nbsrec";
  rec.grid.cell_size = 1.0;
  RecordedFrame near, far;
  far.number = 1;
  far.time = 0.1;
  near.elements.push_back(0, 0, 0, 0.25);
  near.elements.push_back(2, 0, 0, 0.25);
  far.elements.push_back(0, 0, 0, 0.25);
  far.elements.push_back(1e12, 0, 0, 0.25);
  RecordedFrame near_again = near;  // frame numbers increase, as the recording reader demands
  near_again.number = 2;
  near_again.time = 0.2;
  rec.frames = {near, far, near_again};
  FrameLoop loop;
  loop.load_recording(rec);
  const FrameChange loaded = loop.change();
  EXPECT_EQ(loaded.kind, Kind::loaded);
  EXPECT_THROW(loop.step(), Error);
  EXPECT_EQ(loop.change().generation, loaded.generation) << "the frame that could not be detected";
  // Starting from the far frame: the load's own detection throws; the next change carries the load.
  RecordedFrame far_first = far, near_second = near;
  far_first.number = 0;
  far_first.time = 0;
  near_second.number = 1;
  near_second.time = 0.1;
  rec.frames = {far_first, near_second};
  EXPECT_THROW(loop.load_recording(rec), Error);
  EXPECT_EQ(loop.change().generation, loaded.generation);
  loop.step();
  EXPECT_EQ(loop.change().kind, Kind::stepped);
  EXPECT_EQ(loop.change().generation, loaded.generation + 1);
  EXPECT_EQ(loop.change().loaded_at, loop.change().generation) << "a new source, to the views";
}

TEST(FrameLoop, EveryFrameIsConsistent) {
  ASSERT_TRUE(kRegistered);
  FrameLoop loop;
  load_scene_file(loop, scene("default"));
  EXPECT_EQ(loop.source().frame(), 0);
  EXPECT_TRUE(loop.result().report().ok());
  EXPECT_FALSE(loop.result().report().box2d_stepped);  // no Box2D contacts before the first step
  for (int k = 1; k <= 30; ++k) {
    loop.step();
    ASSERT_EQ(loop.source().frame(), k);
    EXPECT_NEAR(loop.source().time(), k * loop.source().scene().time_step, 1e-9);
    const Elements& e = loop.source().elements();
    EXPECT_EQ(loop.result().selected().pairs, brute_pairs(e));
    EXPECT_EQ(static_cast<std::int64_t>(loop.result().selected().cells.size()), e.size());
    EXPECT_EQ(static_cast<std::int64_t>(loop.source().element_sources().size()), e.size());
    for (std::int64_t i = 0; i < e.size(); ++i) {
      EXPECT_EQ(loop.result().selected().cells[static_cast<std::size_t>(i)].ix, loop.result().selected().grid.cell(e.x[i], 0));
      EXPECT_EQ(loop.result().selected().cells[static_cast<std::size_t>(i)].iy, loop.result().selected().grid.cell(e.y[i], 1));
    }
    EXPECT_TRUE(loop.result().report().ok()) << "frame " << k;
    EXPECT_EQ(loop.result().report().frame, k);
    EXPECT_EQ(loop.result().reference, loop.result().selected().pairs);
    EXPECT_GE(loop.result().report().timings.physics_ms, 0);
  }
  EXPECT_FALSE(loop.result().box2d.empty());
  EXPECT_FALSE(loop.result().touching.empty());
  EXPECT_GE(loop.result().tight_aabb.size(), loop.result().touching.size());
  std::vector<BodyShape> shapes;
  loop.source().body_shapes(shapes);
  EXPECT_EQ(static_cast<std::int64_t>(shapes.size()), loop.source().elements().size());
  EXPECT_GT(loop.source().body_count(), 400);
}

TEST(FrameLoop, SwitchesAlgorithmFaultAndChecksLive) {
  FrameLoop loop;
  load_scene_file(loop, scene("default"));
  for (int k = 0; k < 10; ++k) loop.step();
  const PairList before = loop.result().selected().pairs;
  loop.redetect_with_algorithm("box2d");
  EXPECT_EQ(loop.pipeline().algorithm(), "box2d");
  EXPECT_EQ(loop.pipeline().algorithm(), "box2d");
  EXPECT_EQ(loop.source().frame(), 10);  // the same frame, detected again
  EXPECT_EQ(loop.result().selected().pairs, before);
  EXPECT_TRUE(loop.result().report().ok());

  loop.redetect_with_fault(Fault::DropPair);
  EXPECT_EQ(loop.result().selected().pairs.size() + 1, before.size());
  EXPECT_FALSE(loop.result().report().ok());
  EXPECT_GT(loop.result().report().broken[static_cast<int>(Invariant::AEqualsR)], 0);
  loop.redetect_with_checks(false);
  EXPECT_FALSE(loop.result().report().checked);
  EXPECT_TRUE(loop.result().reference.empty());
  loop.redetect_with_checks(true);
  loop.redetect_with_fault(Fault::None);
  EXPECT_TRUE(loop.result().report().ok());

  EXPECT_THROW(loop.redetect_with_algorithm("quadtree"), Error);
  EXPECT_EQ(loop.pipeline().algorithm(), "box2d");  // kept
}

TEST(FrameLoop, ComparisonLanesAreCheckedOnTheSameFrame) {
  FrameLoop loop;
  load_scene_file(loop, scene("pile"));
  loop.redetect_with_comparisons({"box2d", "brute"});
  ASSERT_EQ(loop.result().lanes.size(), 3u);  // the selected lane, then the comparisons in the order given
  for (int k = 0; k < 5; ++k) {
    loop.step();
    for (std::size_t lane = 1; lane < loop.result().lanes.size(); ++lane) {
      const FrameReport& r = loop.result().lanes[lane].report;
      EXPECT_TRUE(r.ok());
      EXPECT_EQ(r.frame, loop.source().frame());
      EXPECT_EQ(r.counts.a, static_cast<std::int64_t>(loop.result().selected().pairs.size()));
    }
  }
  EXPECT_EQ(loop.result().lanes[2].report.reference, "sort");  // brute never checks itself
  EXPECT_THROW(loop.redetect_with_comparisons({"nbs", "nope"}), Error);
  EXPECT_EQ(loop.pipeline().comparison_algorithms().size(), 2u);  // kept
}

TEST(FrameLoop, StalePositionsAreLastFramesPositions) {
  FrameLoop loop;
  load_scene_file(loop, scene("gas"));
  loop.step();
  const Elements previous = loop.source().elements();
  loop.redetect_with_fault(Fault::StalePositions);
  loop.step();
  EXPECT_EQ(loop.result().selected().pairs, brute_pairs(previous));
  EXPECT_NE(loop.result().selected().pairs, brute_pairs(loop.source().elements()));
  EXPECT_FALSE(loop.result().report().ok());
}

TEST(FrameLoop, ABadSceneKeepsTheOldOneAndRestartGoesBackToFrameZero) {
  FrameLoop loop;
  load_scene_file(loop, scene("book-fig-3-15"));
  loop.step();
  EXPECT_THROW(load_scene_file(loop, "/nonexistent.json"), Error);
  EXPECT_EQ(loop.source().scene().name, "book-fig-3-15");
  EXPECT_EQ(loop.source().frame(), 1);
  EXPECT_EQ(loop.source().elements().size(), 9);
  loop.restart();
  EXPECT_EQ(loop.source().frame(), 0);
  EXPECT_EQ(loop.result().selected().grid.n[0], 10);  // the scene pins the book's 10x10 grid of unit cells
  EXPECT_EQ(loop.result().selected().grid.n[1], 10);
  EXPECT_EQ(loop.result().selected().grid.cell_size, 1);
  // Book element 1 (element 0) is in C[5][7] (1-based): cell (4, 6) here.
  EXPECT_EQ(loop.result().selected().cells[0], (CellIndex{4, 6}));
  const auto trace = loop.pipeline().frame_trace();
  ASSERT_NE(trace, nullptr);
  EXPECT_FALSE(trace->log.events().empty());
  EXPECT_TRUE(trace->refusal.empty());
  EXPECT_EQ(trace->frame, loop.source().frame());
  PairList traced = trace->pairs;
  sort_pairs(traced);
  EXPECT_EQ(traced, loop.result().selected().pairs);
  // One trace per frame: asked again, the same record; after a step, a new one.
  EXPECT_EQ(loop.pipeline().frame_trace(), trace);
  loop.step();
  EXPECT_NE(loop.pipeline().frame_trace()->serial, trace->serial);
  EXPECT_EQ(loop.pipeline().frame_trace()->frame, loop.source().frame());
  loop.redetect_with_algorithm("box2d");
  EXPECT_TRUE(loop.pipeline().frame_trace()->log.events().empty());
  EXPECT_NE(loop.pipeline().frame_trace()->refusal.find("records no operations"), std::string::npos);
}

TEST(FrameLoop, DraggingMovesABody) {
  FrameLoop loop;
  loop.load_scene(parse_scene_json(R"({"bodies": [
      {"type": "static", "shape": "box", "half_extents": [0.5, 0.5], "position": [0, -0.5]},
      {"shape": "circle", "radius": 0.5, "position": [0, 0.5]}]})",
                                   "drag.json"));
  std::vector<BodyShape> shapes;
  loop.source().body_shapes(shapes);
  ASSERT_EQ(shapes.size(), 2u);
  EXPECT_EQ(shapes[1].body_type, BodyType::Dynamic);
  EXPECT_FALSE(loop.drag().begin(0, -0.5));  // the static tile
  ASSERT_TRUE(loop.drag().begin(shapes[1].centre.x, shapes[1].centre.y));
  EXPECT_TRUE(loop.drag().active());
  loop.drag().move_to(6, 3);
  for (int k = 0; k < 90; ++k) loop.step();
  EXPECT_GT(loop.source().elements().x[1], 3);
  EXPECT_GT(loop.source().elements().y[1], 1.5);
  loop.drag().end();
  EXPECT_FALSE(loop.drag().active());
  EXPECT_TRUE(loop.result().report().ok());
}

}  // namespace
}  // namespace nbscope

namespace nbscope {
namespace {

// A detection that fails (screen's C would need more cells than it may allocate) is the trace's
// reason, not an exception out of the window's frame: the stepper panels and the lists legend say it.
TEST(FrameLoop, ATraceTheDetectorRefusesCarriesTheReason) {
  FrameLoop loop;
  loop.load_scene(parse_scene_json(R"({"gravity": [0, 0], "bodies": [
      {"shape": "circle", "radius": 0.01, "position": [0, 0]},
      {"shape": "circle", "radius": 0.01, "position": [90000, 90000]}]})",
                                   "sparse.json"));
  try {
    loop.redetect_with_algorithm("screen");
  } catch (const Error&) {
    // the detector is switched; the frame's detection is what failed
  }
  ASSERT_EQ(loop.pipeline().algorithm(), "screen");
  std::shared_ptr<const FrameTrace> trace;
  ASSERT_NO_THROW(trace = loop.pipeline().frame_trace());
  ASSERT_NE(trace, nullptr);
  EXPECT_TRUE(trace->log.events().empty());
  EXPECT_FALSE(trace->refusal.empty());
  EXPECT_EQ(loop.pipeline().frame_trace(), trace) << "a refusal is kept, not retried every UI frame";
}

}  // namespace
}  // namespace nbscope

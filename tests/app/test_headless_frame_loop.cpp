// FrameLoop, the pipeline the window and the headless command share: one consistent frame after
// load and after every step, live switches (algorithm, fault, checks), comparison lanes, shapes,
// dragging, tracing, and errors that leave the loop usable.
#include <gtest/gtest.h>

#include "support/paths.hpp"
#include "support/generators.hpp"

#include "app/frame_loop.hpp"
#include "core/brute.hpp"
#include "core/error.hpp"
#include "io/scene_json.hpp"
#include "physics/box2d_detector.hpp"

namespace nbscope {
namespace {

const bool kRegistered = (register_physics_detectors(), true);

using testpaths::scene;

using testdata::brute_pairs;

TEST(FrameLoop, EmptyUntilASceneIsLoaded) {
  FrameLoop loop;
  EXPECT_FALSE(loop.has_scene());
  loop.step();  // no effect
  EXPECT_EQ(loop.frame(), 0);
  EXPECT_EQ(loop.elements().size(), 0);
  std::vector<BodyShape> shapes;
  loop.body_shapes(shapes);
  EXPECT_TRUE(shapes.empty());
  EXPECT_FALSE(loop.begin_drag(0, 0));
}

TEST(FrameLoop, EveryFrameIsConsistent) {
  ASSERT_TRUE(kRegistered);
  FrameLoop loop;
  loop.load_scene_file(scene("default"));
  EXPECT_EQ(loop.frame(), 0);
  EXPECT_TRUE(loop.report().ok());
  EXPECT_FALSE(loop.report().box2d_stepped);  // no Box2D contacts before the first step
  for (int k = 1; k <= 30; ++k) {
    loop.step();
    ASSERT_EQ(loop.frame(), k);
    EXPECT_NEAR(loop.time(), k * loop.scene().time_step, 1e-9);
    const Elements& e = loop.elements();
    EXPECT_EQ(loop.pairs(), brute_pairs(e));
    EXPECT_EQ(static_cast<std::int64_t>(loop.cells().size()), e.size());
    EXPECT_EQ(static_cast<std::int64_t>(loop.element_sources().size()), e.size());
    for (std::int64_t i = 0; i < e.size(); ++i) {
      EXPECT_EQ(loop.cells()[static_cast<std::size_t>(i)].ix, loop.grid().cell(e.x[i], 0));
      EXPECT_EQ(loop.cells()[static_cast<std::size_t>(i)].iy, loop.grid().cell(e.y[i], 1));
    }
    EXPECT_TRUE(loop.report().ok()) << "frame " << k;
    EXPECT_EQ(loop.report().frame, k);
    EXPECT_EQ(loop.reference_pairs(), loop.pairs());
    EXPECT_GE(loop.timings().physics_ms, 0);
  }
  EXPECT_FALSE(loop.box2d_pairs().empty());
  EXPECT_FALSE(loop.touching_pairs().empty());
  EXPECT_GE(loop.tight_aabb_pairs().size(), loop.touching_pairs().size());
  std::vector<BodyShape> shapes;
  loop.body_shapes(shapes);
  EXPECT_EQ(static_cast<std::int64_t>(shapes.size()), loop.elements().size());
  EXPECT_GT(loop.body_count(), 400);
}

TEST(FrameLoop, SwitchesAlgorithmFaultAndChecksLive) {
  FrameLoop loop;
  loop.load_scene_file(scene("default"));
  for (int k = 0; k < 10; ++k) loop.step();
  const PairList before = loop.pairs();
  loop.set_algorithm("box2d");
  EXPECT_EQ(loop.algorithm(), "box2d");
  EXPECT_EQ(loop.detector().name(), "box2d");
  EXPECT_EQ(loop.frame(), 10);  // the same frame, detected again
  EXPECT_EQ(loop.pairs(), before);
  EXPECT_TRUE(loop.report().ok());

  loop.set_fault(Fault::DropPair);
  EXPECT_EQ(loop.pairs().size() + 1, before.size());
  EXPECT_FALSE(loop.report().ok());
  EXPECT_GT(loop.report().broken[static_cast<int>(Invariant::AEqualsR)], 0);
  loop.set_checks_enabled(false);
  EXPECT_FALSE(loop.report().checked);
  EXPECT_TRUE(loop.reference_pairs().empty());
  loop.set_checks_enabled(true);
  loop.set_fault(Fault::None);
  EXPECT_TRUE(loop.report().ok());

  EXPECT_THROW(loop.set_algorithm("quadtree"), Error);
  EXPECT_EQ(loop.algorithm(), "box2d");  // kept
}

TEST(FrameLoop, ComparisonLanesAreCheckedOnTheSameFrame) {
  FrameLoop loop;
  loop.load_scene_file(scene("pile"));
  loop.set_comparison_algorithms({"box2d", "brute"});
  ASSERT_EQ(loop.comparison_reports().size(), 2u);
  for (int k = 0; k < 5; ++k) {
    loop.step();
    for (const FrameReport& r : loop.comparison_reports()) {
      EXPECT_TRUE(r.ok());
      EXPECT_EQ(r.frame, loop.frame());
      EXPECT_EQ(r.counts.a, static_cast<std::int64_t>(loop.pairs().size()));
    }
  }
  EXPECT_EQ(loop.comparison_reports()[1].reference, "sort");  // brute never checks itself
  EXPECT_THROW(loop.set_comparison_algorithms({"nbs", "nope"}), Error);
  EXPECT_EQ(loop.comparison_algorithms().size(), 2u);  // kept
}

TEST(FrameLoop, StalePositionsAreLastFramesPositions) {
  FrameLoop loop;
  loop.load_scene_file(scene("gas"));
  loop.step();
  const Elements previous = loop.elements();
  loop.set_fault(Fault::StalePositions);
  loop.step();
  EXPECT_EQ(loop.pairs(), brute_pairs(previous));
  EXPECT_NE(loop.pairs(), brute_pairs(loop.elements()));
  EXPECT_FALSE(loop.report().ok());
}

TEST(FrameLoop, ABadSceneKeepsTheOldOneAndRestartGoesBackToFrameZero) {
  FrameLoop loop;
  loop.load_scene_file(scene("book-fig-3-15"));
  loop.step();
  EXPECT_THROW(loop.load_scene_file("/nonexistent.json"), Error);
  EXPECT_EQ(loop.scene().name, "book-fig-3-15");
  EXPECT_EQ(loop.frame(), 1);
  EXPECT_EQ(loop.elements().size(), 9);
  loop.restart();
  EXPECT_EQ(loop.frame(), 0);
  EXPECT_EQ(loop.grid().n[0], 10);  // the scene pins the book's 10x10 grid of unit cells
  EXPECT_EQ(loop.grid().n[1], 10);
  EXPECT_EQ(loop.grid().cell_size, 1);
  // Book element 1 (element 0) is in C[5][7] (1-based): cell (4, 6) here.
  EXPECT_EQ(loop.cells()[0], (CellIndex{4, 6}));
  const auto trace = loop.frame_trace();
  ASSERT_NE(trace, nullptr);
  EXPECT_FALSE(trace->log.events().empty());
  EXPECT_TRUE(trace->refusal.empty());
  EXPECT_EQ(trace->frame, loop.frame());
  PairList traced = trace->pairs;
  sort_pairs(traced);
  EXPECT_EQ(traced, loop.pairs());
  // One trace per frame: asked again, the same record; after a step, a new one.
  EXPECT_EQ(loop.frame_trace(), trace);
  loop.step();
  EXPECT_NE(loop.frame_trace()->serial, trace->serial);
  EXPECT_EQ(loop.frame_trace()->frame, loop.frame());
  loop.set_algorithm("box2d");
  EXPECT_TRUE(loop.frame_trace()->log.events().empty());
  EXPECT_NE(loop.frame_trace()->refusal.find("records no operations"), std::string::npos);
}

TEST(FrameLoop, DraggingMovesABody) {
  FrameLoop loop;
  loop.load_scene(parse_scene_json(R"({"bodies": [
      {"type": "static", "shape": "box", "half_extents": [0.5, 0.5], "position": [0, -0.5]},
      {"shape": "circle", "radius": 0.5, "position": [0, 0.5]}]})",
                                   "drag.json"));
  std::vector<BodyShape> shapes;
  loop.body_shapes(shapes);
  ASSERT_EQ(shapes.size(), 2u);
  EXPECT_EQ(shapes[1].body_type, BodyType::Dynamic);
  EXPECT_FALSE(loop.begin_drag(0, -0.5));  // the static tile
  ASSERT_TRUE(loop.begin_drag(shapes[1].centre.x, shapes[1].centre.y));
  EXPECT_TRUE(loop.dragging());
  loop.drag_to(6, 3);
  for (int k = 0; k < 90; ++k) loop.step();
  EXPECT_GT(loop.elements().x[1], 3);
  EXPECT_GT(loop.elements().y[1], 1.5);
  loop.end_drag();
  EXPECT_FALSE(loop.dragging());
  EXPECT_TRUE(loop.report().ok());
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
    loop.set_algorithm("screen");
  } catch (const Error&) {
    // the detector is switched; the frame's detection is what failed
  }
  ASSERT_EQ(loop.algorithm(), "screen");
  std::shared_ptr<const FrameTrace> trace;
  ASSERT_NO_THROW(trace = loop.frame_trace());
  ASSERT_NE(trace, nullptr);
  EXPECT_TRUE(trace->log.events().empty());
  EXPECT_FALSE(trace->refusal.empty());
  EXPECT_EQ(loop.frame_trace(), trace) << "a refusal is kept, not retried every UI frame";
}

}  // namespace
}  // namespace nbscope

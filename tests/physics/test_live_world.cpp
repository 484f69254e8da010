// The live world as a frame source (physics/live_world.hpp): the overlapped step (Box2D on a worker
// thread) against the plain step on a second world of the same scene, bit for bit; the frame shown
// while the worker steps; the drag log (each call with its frame, release_drag as the user's own
// end) and replay_drag, which re-makes a dragged run on a fresh world; replace_world's forgetting.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "core/error.hpp"
#include "physics/live_world.hpp"
#include "support/physics_context.hpp"

namespace nbscope {
namespace {

using testphysics::expect_same_sets;
using testphysics::PhysicsTestContext;
using testphysics::same_elements;
using testphysics::sets_of;

// Circles, boxes, triangles and static tiles poured on by an emitter: bodies appear mid-run.
const char* kMixed = R"({"gravity": [0, -10], "bodies": [
    {"type": "static", "shape": "box", "half_extents": [8, 0.5], "position": [0, -0.5]}],
  "generators": [
    {"kind": "random_box", "count": 60, "seed": 11, "min": [-5, 0.5], "max": [5, 6], "radius": [0.2, 0.5], "body": {"shape": "circle"}},
    {"kind": "random_box", "count": 25, "seed": 12, "min": [-5, 0.5], "max": [5, 6], "random_angle": true,
     "body": {"shape": "box", "half_extents": [0.4, 0.2]}},
    {"kind": "random_box", "count": 25, "seed": 13, "min": [-5, 0.5], "max": [5, 6], "random_angle": true,
     "body": {"shape": "polygon", "vertices": [[-0.3, -0.3], [0.4, -0.2], [0, 0.5]]}},
    {"kind": "emitter", "count": 20, "position": [0, 8], "rate": 30, "width": 4, "seed": 14}]})";

// One dynamic circle at the origin, nothing else, no gravity: a drag is all that moves it.
const char* kOneCircle = R"({"gravity": [0, 0], "bodies": [{"shape": "circle", "radius": 0.5, "position": [0, 0]}]})";

// An emitter pouring ten circles on one point, one on the first step and the other nine on the
// second: 45 contacts there, past a limit of 5 (the world refuses that step).
const char* kPouredOnOnePoint = R"({"gravity": [0, 0], "max_contacts": 5, "generators": [{"kind": "emitter", "count": 10,
    "rate": 600, "position": [0, 0], "body": {"shape": "circle", "radius": 0.5}}]})";

std::unique_ptr<LiveWorld> live(const char* json) {
  return std::make_unique<LiveWorld>(PhysicsTestContext(json).take_world());
}

// Every frame of a run stepped on the worker equals the same frame of a run stepped in place.
TEST(LiveWorld, OverlappedStepsGiveThePlainStepsFramesBitForBit) {
  const auto plain = live(kMixed), overlapped = live(kMixed);
  for (int k = 1; k <= 45; ++k) {
    plain->step();
    ASSERT_TRUE(overlapped->begin_step());
    overlapped->finish_step();
    expect_same_sets(sets_of(plain->world()), sets_of(overlapped->world()));
    if (testing::Test::HasFailure()) FAIL() << "frame " << k;
  }
  EXPECT_EQ(plain->world().body_count(), 1 + 60 + 25 + 25 + 20);  // the emitter poured all its bodies
}

// While the worker steps, the accessors show the frame the step started from, bit for bit.
TEST(LiveWorld, WhileAStepIsPendingTheFrameItStartedFromIsShown) {
  const auto w = live(kMixed);
  w->step();
  w->step();
  const Elements before = w->elements();
  const std::vector<ElementSource> sources = w->element_sources();
  std::vector<BodyShape> shapes_before, shapes_shown;
  w->body_shapes(shapes_before);
  const std::int64_t bodies = w->body_count();
  const double time = w->time();
  ASSERT_TRUE(w->begin_step());
  EXPECT_TRUE(w->pending());
  w->wait();  // the worker is done, but the step is not adopted yet
  EXPECT_TRUE(w->step_ready());
  EXPECT_EQ(w->frame(), 2);
  EXPECT_EQ(w->newest_frame(), 2);
  EXPECT_EQ(w->time(), time);
  EXPECT_EQ(w->body_count(), bodies);
  EXPECT_TRUE(same_elements(w->elements(), before));
  EXPECT_EQ(w->element_sources().size(), sources.size());
  w->body_shapes(shapes_shown);
  ASSERT_EQ(shapes_shown.size(), shapes_before.size());
  for (std::size_t k = 0; k < shapes_shown.size(); ++k)
    EXPECT_TRUE(shapes_shown[k].centre.x == shapes_before[k].centre.x && shapes_shown[k].centre.y == shapes_before[k].centre.y);
  w->finish_step();
  EXPECT_FALSE(w->pending());
  EXPECT_EQ(w->frame(), 3);
  EXPECT_FALSE(same_elements(w->elements(), before));  // bodies fall under gravity
}

// Each drag call is logged with the frame it was made on; calls that change nothing are not.
TEST(LiveWorld, DragsAreLoggedWithTheirFrames) {
  const auto w = live(kOneCircle);
  w->drag_to(1, 1);  // nothing held: not logged
  w->end_drag();
  EXPECT_TRUE(w->drags().empty());
  w->step();
  w->step();
  ASSERT_TRUE(w->begin_drag(0.1, 0.1));
  w->drag_to(1, 2);
  w->step();
  w->drag_to(3, 4);
  w->end_drag();
  w->end_drag();     // already let go: not logged
  w->drag_to(5, 6);  // nothing held: not logged
  using K = DragInput::Kind;
  const std::vector<DragInput>& log = w->drags();
  ASSERT_EQ(log.size(), 4u);
  EXPECT_TRUE(log[0].kind == K::Begin && log[0].frame == 2 && log[0].x == 0.1 && log[0].y == 0.1);
  EXPECT_TRUE(log[1].kind == K::To && log[1].frame == 2 && log[1].x == 1 && log[1].y == 2);
  EXPECT_TRUE(log[2].kind == K::To && log[2].frame == 3 && log[2].x == 3 && log[2].y == 4);
  EXPECT_TRUE(log[3].kind == K::End && log[3].frame == 3);
  EXPECT_FALSE(w->dragging());
}

// release_drag lets the body go and is logged as an end on its frame; with nothing held it does nothing.
TEST(LiveWorld, ReleaseDragEndsTheDragAsTheUsersOwnEndWould) {
  const auto w = live(kOneCircle);
  ASSERT_TRUE(w->begin_drag(0, 0));
  w->drag_to(4, 0);
  for (int k = 0; k < 5; ++k) w->step();
  EXPECT_TRUE(w->dragging());
  w->release_drag();
  EXPECT_FALSE(w->dragging());
  ASSERT_EQ(w->drags().size(), 3u);
  EXPECT_EQ(w->drags().back().kind, DragInput::Kind::End);
  EXPECT_EQ(w->drags().back().frame, 5);
  w->release_drag();
  EXPECT_EQ(w->drags().size(), 3u);
}

// The logged drags replayed with replay_drag on a fresh world, each before its frame's step, make
// the dragged run again bit for bit (and the drag mattered: an undragged run differs).
TEST(LiveWorld, ReplayingTheDragLogRemakesTheRun) {
  PhysicsTestContext scene(kMixed);
  const auto w = live(kMixed);
  for (int k = 0; k < 40; ++k) {
    const Elements& e = w->elements();
    if (k == 5) {  // element 1: a dynamic circle
      ASSERT_TRUE(w->begin_drag(e.x[1], e.y[1]));
    }
    if (k > 5 && k < 25) w->drag_to(-4 + 0.3 * k, 7);
    if (k == 25) w->release_drag();
    w->step();
  }
  std::unique_ptr<PhysicsWorld> again = scene.fresh_world();
  std::size_t next = 0;
  for (int k = 0; k < 40; ++k) {
    while (next < w->drags().size() && w->drags()[next].frame == again->frame()) replay_drag(*again, w->drags()[next++]);
    again->step();
  }
  EXPECT_EQ(next, w->drags().size());
  expect_same_sets(sets_of(w->world()), sets_of(*again));
  scene.step(40);
  EXPECT_FALSE(same_elements(scene.elements(), w->elements()));
}

// A world re-simulated to frame K replaces the live one; the drags logged from K on are forgotten.
TEST(LiveWorld, ReplaceWorldForgetsTheDragsFromItsFrameOn) {
  PhysicsTestContext scene(kOneCircle);
  const auto w = live(kOneCircle);
  ASSERT_TRUE(w->begin_drag(0, 0));  // frame 0
  for (int k = 0; k < 4; ++k) w->step();
  w->drag_to(1, 0);  // frame 4
  for (int k = 0; k < 4; ++k) w->step();
  w->drag_to(2, 0);  // frame 8
  w->end_drag();     // frame 8
  ASSERT_EQ(w->drags().size(), 4u);
  std::unique_ptr<PhysicsWorld> at_four = scene.fresh_world();
  for (int k = 0; k < 4; ++k) at_four->step();
  w->replace_world(std::move(at_four));
  EXPECT_EQ(w->frame(), 4);
  ASSERT_EQ(w->drags().size(), 1u);
  EXPECT_EQ(w->drags()[0].kind, DragInput::Kind::Begin);
}

// A step the world refuses on the worker is rethrown by finish_step; discard_step swallows it.
TEST(LiveWorld, AStepRefusedOnTheWorkerIsRethrownWhenFinished) {
  const auto w = live(kPouredOnOnePoint);
  w->step();  // one body
  ASSERT_TRUE(w->begin_step());
  EXPECT_THROW(w->finish_step(), Error);
  EXPECT_FALSE(w->pending());
  ASSERT_TRUE(w->begin_step());  // the world refuses every later step too
  w->discard_step();
  EXPECT_FALSE(w->pending());
  EXPECT_EQ(w->frame(), 1);
}

}  // namespace
}  // namespace nbscope

// A kept frame (physics/kept_frame.hpp): a past frame rebuilt from the WorldState the history
// captured and the world's fixed geometry, held to the live world at that frame: the same elements,
// shapes, contacts, ground truth and A-in-F scope, bit for bit, for every frame of runs with
// polygons, emitted bodies and a mouse joint, rebuilt after the world has moved on.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <vector>

#include "physics/kept_frame.hpp"
#include "support/physics_context.hpp"

namespace nbscope {
namespace {

using testphysics::expect_same_sets;
using testphysics::FrameSets;
using testphysics::PhysicsTestContext;
using testphysics::same_elements;
using testphysics::sets_of;

// Circles, boxes, triangles, a compound body, static tiles, and an emitter adding bodies mid-run.
const char* kMixed = R"({"gravity": [0, -10], "bodies": [
    {"position": [0, 7], "fixtures": [{"shape": "circle", "radius": 0.4, "offset": [-0.3, 0]},
                                      {"shape": "box", "half_extents": [0.3, 0.2], "offset": [0.3, 0]}]}],
  "generators": [
    {"kind": "grid", "columns": 12, "rows": 1, "origin": [-6, -0.5], "spacing": [1, 0],
     "body": {"type": "static", "shape": "box", "half_extents": [0.5, 0.5]}},
    {"kind": "random_box", "count": 60, "seed": 21, "min": [-5, 0.5], "max": [5, 6], "radius": [0.2, 0.5], "body": {"shape": "circle"}},
    {"kind": "random_box", "count": 20, "seed": 22, "min": [-5, 0.5], "max": [5, 6], "random_angle": true,
     "body": {"shape": "box", "half_extents": [0.4, 0.2]}},
    {"kind": "random_box", "count": 20, "seed": 23, "min": [-5, 0.5], "max": [5, 6], "random_angle": true,
     "body": {"shape": "polygon", "vertices": [[-0.3, -0.3], [0.4, -0.2], [0, 0.5]]}},
    {"kind": "emitter", "count": 15, "position": [0, 9], "rate": 20, "width": 3, "seed": 24}]})";

// Every frame of a 50-frame run, rebuilt from its captured state once the run is at frame 50, gives
// what the live world gave at that frame: elements, shapes, F, G, T, A-in-F's scope and its reasons.
TEST(KeptWorldFrame, EveryKeptFrameIsTheLiveFrameAgainBitForBit) {
  PhysicsTestContext c(kMixed);
  std::map<std::int64_t, FrameSets> live;
  std::map<std::int64_t, std::shared_ptr<WorldState>> kept;
  for (int k = 0; k <= 50; ++k) {
    if (k == 20) {  // a joint: its scope path
      ASSERT_TRUE(c.world().begin_drag(c.elements().x[20], c.elements().y[20]));
    }
    if (k == 35) c.world().end_drag();
    if (k > 0) c.step();
    live[k] = sets_of(c.frame());
    kept[k] = c.capture();
  }
  ASSERT_GT(live[50].elements.size(), live[0].elements.size());  // the emitter added bodies
  for (const auto& [k, state] : kept) {
    const KeptWorldFrame frame(c.world(), state);
    expect_same_sets(sets_of(frame), live[k]);
    if (testing::Test::HasFailure()) FAIL() << "frame " << k;
  }
}

// As a Frame, a kept frame answers with its own frame, the world's element sources and its shapes.
TEST(KeptWorldFrame, AsAFrameItIsThePastFrame) {
  PhysicsTestContext c(kMixed, 10);
  const std::vector<ElementSource> sources_then = c.world().sources();
  const Elements elements_then = c.elements();
  const std::shared_ptr<WorldState> state = c.capture();
  c.step(30);
  const KeptWorldFrame kept(c.world(), state);
  const Frame& frame = kept;
  EXPECT_EQ(frame.frame(), 10);
  EXPECT_EQ(frame.time(), state->time);
  EXPECT_EQ(&kept.state(), state.get());
  EXPECT_EQ(frame.box2d(), &kept);
  EXPECT_TRUE(same_elements(frame.elements(), elements_then));
  ASSERT_GE(frame.element_sources().size(), sources_then.size());
  for (std::size_t k = 0; k < sources_then.size(); ++k)
    EXPECT_TRUE(frame.element_sources()[k].body == sources_then[k].body && frame.element_sources()[k].fixture == sources_then[k].fixture);
  std::vector<BodyShape> drawn, shapes;
  frame.body_shapes(drawn);
  kept.shapes(shapes);
  ASSERT_EQ(drawn.size(), static_cast<std::size_t>(elements_then.size()));
  ASSERT_EQ(drawn.size(), shapes.size());
  for (std::size_t k = 0; k < drawn.size(); ++k) EXPECT_TRUE(drawn[k].centre.x == shapes[k].centre.x && drawn[k].element == shapes[k].element);
}

// PhysicsWorld::element_centre of a kept state is the centre elements() had at that frame.
TEST(KeptWorldFrame, TheWorldGivesAKeptElementsCentreAsItWasThen) {
  PhysicsTestContext c(kMixed, 12);
  const Elements then = c.elements();
  const std::shared_ptr<WorldState> state = c.capture();
  c.step(25);
  for (ElementId k = 0; k < then.size(); ++k) {
    double x = 0, y = 0;
    c.world().element_centre(*state, k, x, y);
    ASSERT_TRUE(x == then.x[k] && y == then.y[k]) << "element " << k;
  }
}

// The kept frame finds G and T from its own poses (tight AABBs, shapes) as the live world does from its bodies.
TEST(KeptWorldFrame, KeptGroundTruthEqualsTheWorldsQuery) {
  PhysicsTestContext c = PhysicsTestContext::bundled("mixed-sizes", 40);
  const PhysicsWorld& world = c.world();
  KeptWorldFrame kept(world, c.capture());
  PairList g1, t1, g2, t2, f1, f2;
  world.ground_truth(g1, t1);
  kept.ground_truth(g2, t2);
  EXPECT_FALSE(g1.empty());
  EXPECT_EQ(g1, g2);
  EXPECT_EQ(t1, t2);
  world.contact_pairs(f1);
  kept.contact_pairs(f2);
  EXPECT_EQ(f1, f2);
  EXPECT_EQ(kept.body_count(), world.body_count());
}

}  // namespace
}  // namespace nbscope

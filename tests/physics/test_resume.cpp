// Resume (physics/resume.hpp) and the divergence check (physics/divergence.hpp): a fresh world
// re-simulated to frame K with the drags the run logged arrives with the run's own element hash and
// previous frame, a few frames per call; a planted change (a drag left out, a hash the run did not
// have) is reported at the first frame it shows; a step that refuses cancels the resume with its
// frame named. The run's hashes come from a LiveWorld stepped straight, an independent path.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <vector>

#include "core/error.hpp"
#include "physics/divergence.hpp"
#include "physics/resume.hpp"
#include "support/physics_context.hpp"

namespace nbscope {
namespace {

using testphysics::PhysicsTestContext;
using testphysics::same_elements;

// Circles and triangles falling on a floor.
const char* kFalling = R"({"gravity": [0, -10], "bodies": [
    {"type": "static", "shape": "box", "half_extents": [8, 0.5], "position": [0, -0.5]}],
  "generators": [
    {"kind": "random_box", "count": 50, "seed": 31, "min": [-5, 0.5], "max": [5, 6], "radius": [0.2, 0.5], "body": {"shape": "circle"}},
    {"kind": "random_box", "count": 20, "seed": 32, "min": [-5, 0.5], "max": [5, 6], "random_angle": true,
     "body": {"shape": "polygon", "vertices": [[-0.3, -0.3], [0.4, -0.2], [0, 0.5]]}}]})";

// A run of kFalling stepped straight for `frames` frames, dragging element 1 from frame 10 to 30:
// every frame's element hash and elements, and its drag log.
struct StraightRun {
  Scene scene;
  std::map<std::int64_t, std::uint64_t> hashes;
  std::map<std::int64_t, Elements> elements;
  std::vector<DragInput> drags;

  explicit StraightRun(int frames) {
    PhysicsTestContext c(kFalling);
    scene = c.scene();
    LiveWorld w(c.take_world());
    for (int k = 0; k <= frames; ++k) {
      hashes[k] = hash_elements(w.elements());
      elements[k] = w.elements();
      if (k == frames) break;
      if (k == 10) {
        EXPECT_TRUE(w.begin_drag(w.elements().x[1], w.elements().y[1]));
      }
      if (k > 10 && k < 30) w.drag_to(-4 + 0.25 * k, 6);
      if (k == 30) w.end_drag();
      w.step();
    }
    drags = w.drags();
  }
  [[nodiscard]] Resume::HashOf hash_of() const {
    return [this](std::int64_t frame) { return hashes.count(frame) != 0 ? hashes.at(frame) : 0; };
  }
};

// Advances `r` in 1 ms slices until it arrives; the calls it took.
int advance_to_target(Resume& r, const std::vector<DragInput>& drags, const Resume::HashOf& hash_of) {
  int calls = 1;
  while (!r.advance(1.0, drags, hash_of)) ++calls;
  return calls;
}

// Resumed to frame 40 with the logged drags, the world arrives with the run's hash at 40 and the run's
// frame 39 as its previous elements, and nothing diverged on the way.
TEST(Resume, ArrivesAtTheTargetWithTheRunsHash) {
  const StraightRun run(60);
  Resume r;
  r.begin(run.scene, 40);
  EXPECT_TRUE(r.active());
  EXPECT_EQ(r.target(), 40);
  advance_to_target(r, run.drags, run.hash_of());
  EXPECT_EQ(r.progress(), (std::pair<std::int64_t, std::int64_t>{40, 40}));
  EXPECT_FALSE(r.divergence().has_value());
  std::unique_ptr<PhysicsWorld> world = r.take_world();
  EXPECT_FALSE(r.active());
  ASSERT_NE(world, nullptr);
  EXPECT_EQ(world->frame(), 40);
  EXPECT_EQ(hash_elements(world->elements()), run.hashes.at(40));
  EXPECT_TRUE(same_elements(world->elements(), run.elements.at(40)));
  EXPECT_TRUE(same_elements(r.previous_elements(), run.elements.at(39)));
}

// The drag mattered: resumed without it, the run diverges on frame 11, the first stepped with the body held.
TEST(Resume, LeavingOutTheDragsDivergesWhereTheDragBegan) {
  const StraightRun run(40);
  Resume r;
  r.begin(run.scene, 40);
  advance_to_target(r, {}, run.hash_of());
  EXPECT_EQ(r.divergence(), 11);
  EXPECT_NE(hash_elements(r.take_world()->elements()), run.hashes.at(40));
  EXPECT_EQ(r.divergence(), 11);  // kept after arriving
  r.reset();
  EXPECT_FALSE(r.divergence().has_value());
}

// A hash the run did not have (one bit flipped at frame 25) is reported at 25; unknown hashes (0) are not compared.
TEST(Resume, APlantedHashIsReportedAtItsFrameAndUnknownOnesAreNot) {
  StraightRun run(30);
  run.hashes[25] ^= 1;
  Resume r;
  r.begin(run.scene, 30);
  advance_to_target(r, run.drags, run.hash_of());
  EXPECT_EQ(r.divergence(), 25);
  r.begin(run.scene, 30);  // a new comparison forgets the old one
  advance_to_target(r, {}, [](std::int64_t) { return std::uint64_t{0}; });
  EXPECT_FALSE(r.divergence().has_value());
}

// Each call steps at least once however small its budget, and progress counts the frames made.
TEST(Resume, EachCallStepsAtLeastOnceAndProgressCountsFrames) {
  const StraightRun run(0);
  Resume r;
  EXPECT_EQ(r.progress(), (std::pair<std::int64_t, std::int64_t>{0, 0}));
  r.begin(run.scene, 3);
  EXPECT_FALSE(r.advance(0.0, {}, run.hash_of()));
  EXPECT_EQ(r.progress(), (std::pair<std::int64_t, std::int64_t>{1, 3}));
  EXPECT_FALSE(r.advance(0.0, {}, run.hash_of()));
  EXPECT_TRUE(r.advance(0.0, {}, run.hash_of()));
  EXPECT_EQ(r.progress(), (std::pair<std::int64_t, std::int64_t>{3, 3}));
  r.cancel();
  EXPECT_FALSE(r.active());
  EXPECT_EQ(r.target(), -1);
  EXPECT_EQ(r.progress(), (std::pair<std::int64_t, std::int64_t>{0, 0}));
}

// Resumed to frame 0, the world is the scene's first frame and its own previous elements.
TEST(Resume, FrameZeroIsItsOwnPreviousFrame) {
  const StraightRun run(0);
  Resume r;
  r.begin(run.scene, 0);
  EXPECT_TRUE(r.advance(1.0, {}, run.hash_of()));
  const std::unique_ptr<PhysicsWorld> world = r.take_world();
  EXPECT_EQ(world->frame(), 0);
  EXPECT_TRUE(same_elements(world->elements(), run.elements.at(0)));
  EXPECT_TRUE(same_elements(r.previous_elements(), run.elements.at(0)));
}

// A step the world refuses ends the resume with one Error naming the scene and the frame.
TEST(Resume, ARefusedStepCancelsTheResumeNamingTheFrame) {
  // An emitter pouring ten circles on one point, one on the first step and nine on the second: 45
  // contacts there, past a limit of 5.
  const Scene crowded = testphysics::scene_of(R"({"gravity": [0, 0], "max_contacts": 5, "generators": [{"kind": "emitter",
      "count": 10, "rate": 600, "position": [0, 0], "body": {"shape": "circle", "radius": 0.5}}]})");
  Resume r;
  r.begin(crowded, 5);
  try {
    r.advance(1.0, {}, [](std::int64_t) { return std::uint64_t{0}; });
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("test.json: resuming at frame 1: ", 0), 0u) << e.what();
  }
  EXPECT_FALSE(r.active());
  EXPECT_EQ(r.target(), -1);
}

// Divergence keeps the first frame whose hash differs from a known one, worked case by case.
TEST(Divergence, KeepsTheFirstFrameThatDiffersFromAKnownHash) {
  Divergence d;
  EXPECT_FALSE(d.first().has_value());
  d.compare(3, 0, 5);  // not known: not compared
  d.compare(4, 7, 7);  // came back exactly
  EXPECT_FALSE(d.first().has_value());
  d.compare(5, 7, 8);
  EXPECT_EQ(d.first(), 5);
  d.compare(6, 1, 2);  // a later difference does not move it
  EXPECT_EQ(d.first(), 5);
  d.clear();
  EXPECT_FALSE(d.first().has_value());
  d.compare(9, 1, 2);
  EXPECT_EQ(d.first(), 9);
}

}  // namespace
}  // namespace nbscope

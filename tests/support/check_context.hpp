// nbscope tests: the check floor's fixture, as Jolt's PhysicsTestContext is its physics tests': one
// frame source and one Pipeline run on its frames the way the frame loop runs them, so a test says
// only what it sets and what it expects. The sources are the product's own (the live Box2D world of
// a scene, or recorded frames held in memory: io/recording_source.hpp over io/recorded_frames.hpp),
// made and driven here alone: the one place to adapt when the Frame interfaces change.
//
// Beside it, the tests' oracle: every touching pair by a double loop over all pairs, independent of
// every detector and of the checker.
#pragma once
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "check/pipeline.hpp"
#include "core/layouts.hpp"
#include "io/recorded_frames.hpp"
#include "io/recording_source.hpp"
#include "io/scene_json.hpp"
#include "physics/live_world.hpp"
#include "physics/world.hpp"

namespace nbscope::testcheck {

// Every pair (i < j) of `e` whose circles (spheres) touch or overlap, |c_i - c_j| <= r_i + r_j,
// sorted by (i, j): all N(N-1)/2 pairs looked at, nothing shared with a detector.
inline PairList touching_pairs(const Elements& e) {
  PairList out;
  for (Eigen::Index i = 0; i < e.size(); ++i)
    for (Eigen::Index j = i + 1; j < e.size(); ++j) {
      const double dx = e.x[i] - e.x[j], dy = e.y[i] - e.y[j], dz = e.dim == 3 ? e.z[i] - e.z[j] : 0.0;
      const double reach = e.r[i] + e.r[j];
      if (dx * dx + dy * dy + dz * dz <= reach * reach) out.push_back({static_cast<ElementId>(i), static_cast<ElementId>(j)});
    }
  return out;
}

// `n` loose random circles (core's `loose` layout, reproducible from `seed`).
inline Elements random_circles(std::int64_t n, std::uint64_t seed) { return make_layout(Layout::Loose, n, 2, seed); }

// Recorded frame `number` (time number / 60 s) of `elements`, carrying `pairs` as its pairs block.
inline RecordedFrame recorded_frame(std::int64_t number, Elements elements, PairList pairs = {}) {
  RecordedFrame f;
  f.number = number;
  f.time = static_cast<double>(number) / 60.0;
  f.elements = std::move(elements);
  f.pairs = std::move(pairs);
  return f;
}

// PipelineOptions naming the selected lane's algorithm and the injected fault.
inline PipelineOptions lane_options(const std::string& algorithm, Fault fault = Fault::None) {
  PipelineOptions o;
  o.algorithm = algorithm;
  o.fault = fault;
  return o;
}

class CheckTestContext {
 public:
  // The frames of a scene (its JSON text), stepped by Box2D: F, G and T exist, every invariant runs.
  static std::unique_ptr<CheckTestContext> scene(const std::string& json, const PipelineOptions& options = {}) {
    const Scene parsed = parse_scene_json(json, "test.json");
    auto c = std::unique_ptr<CheckTestContext>(new CheckTestContext(options));
    auto world = std::make_unique<LiveWorld>(std::make_unique<PhysicsWorld>(parsed));
    c->live_ = world.get();
    c->source_ = std::move(world);
    DetectOptions detect;
    detect.grid = parsed.grid;
    c->pipeline_.set_detect_options(detect);
    return c;
  }
  // Recorded frames held in memory (at least one; numbers increasing): no Box2D side, so only A==R,
  // cells and contract run. `with_pairs`: every frame's `pairs` is its pairs block (the `recorded` lane's).
  static std::unique_ptr<CheckTestContext> recorded(std::vector<RecordedFrame> frames, const PipelineOptions& options = {},
                                                    bool with_pairs = false) {
    Recording recording;
    recording.path = "test.nbsrec";
    recording.dim = frames.empty() ? 2 : frames.front().elements.dim;
    recording.has_pairs = with_pairs;
    recording.frames = std::move(frames);
    auto c = std::unique_ptr<CheckTestContext>(new CheckTestContext(options));
    auto source = std::make_unique<RecordingSource>(held_frames(std::move(recording)), std::size_t{1} << 20);
    c->recording_ = source.get();
    c->source_ = std::move(source);
    return c;
  }

  [[nodiscard]] Pipeline& pipeline() { return pipeline_; }
  [[nodiscard]] const Frame& source() const { return *source_; }
  [[nodiscard]] const Elements& elements() const { return source_->elements(); }

  // Detects and checks the current frame, as the frame loop does (the frame carries its pairs and
  // precision; its predecessor is given as the loop gives it).
  const FrameResult& run() {
    FrameInput in;
    in.source = source_.get();
    in.first = live_ != nullptr ? live_->frame() == 0 : recording_->first();
    if (recording_ != nullptr) in.previous = [this] { return recording_->previous_elements(nullptr); };
    in.where = "test: frame " + std::to_string(source_->frame()) + ": ";
    return pipeline_.run(in);
  }
  // Makes the next frame (a Box2D step, or the next recorded frame), then run(). A live frame is
  // made from its predecessor, whose positions the pipeline remembers (the stale-positions fault's).
  const FrameResult& next() {
    if (live_ != nullptr) {
      Elements before = live_->elements();
      pipeline_.set_physics_ms(live_->step());
      pipeline_.remember_previous(live_->frame(), std::move(before));
    } else {
      EXPECT_TRUE(recording_->can_step()) << "no recorded frame after " << recording_->frame();
      pipeline_.set_physics_ms(recording_->step());
    }
    return run();
  }
  // Lane 0's traced run of the current frame (Pipeline::trace).
  std::shared_ptr<const FrameTrace> trace() { return pipeline_.trace(*source_); }

 private:
  explicit CheckTestContext(const PipelineOptions& options) : pipeline_(options) {}

  Pipeline pipeline_;
  std::unique_ptr<Frame> source_;
  LiveWorld* live_ = nullptr;            // source_, when a scene's
  RecordingSource* recording_ = nullptr;  // source_, when recorded frames
};

}  // namespace nbscope::testcheck

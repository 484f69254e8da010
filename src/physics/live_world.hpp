// nbscope physics: the live Box2D world as a frame source: its plain step, its overlapped step
// (Box2D steps frame k+1 on a worker thread while the window draws frame k) and the user's drags,
// logged with their frames so that a resume (app) replays them.
//
// Why the overlapped step is safe: the worker touches only the PhysicsWorld, and between
// begin_step() and finish_step() the owner calls nothing of it, nor any Box2D code that keeps global
// state: the Frame accessors read a snapshot taken before the worker starts (ShownFrame).
// Every call that needs the world finishes the step first or waits for the worker. The future's
// get()/wait() is the synchronisation point: the worker's writes happen-before its return.
// Why it is the same frame: the worker runs the very PhysicsWorld::step() that step() runs, on the
// same world in the same order (Box2D is deterministic) (tests/app/test_frame_loop_overlap.cpp).
#pragma once
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <vector>

#include "physics/frame.hpp"
#include "physics/world.hpp"

namespace nbscope {

// A drag call, with the frame it was made on (before that frame's successor was stepped).
struct DragInput {
  enum class Kind : std::uint8_t { Begin, To, End } kind = Kind::Begin;
  std::int64_t frame = 0;
  double x = 0, y = 0;
};

// Replays `in` on `world` as the user's own call was made.
void replay_drag(PhysicsWorld& world, const DragInput& in);

class LiveWorld final : public Frame {
 public:
  // Takes a built world (frame 0 or any later frame).
  explicit LiveWorld(std::unique_ptr<PhysicsWorld> world);
  ~LiveWorld() override;
  LiveWorld(const LiveWorld&) = delete;
  LiveWorld& operator=(const LiveWorld&) = delete;

  // ---- Frame: while a step is pending, the frame shown (the snapshot) ----
  [[nodiscard]] std::int64_t frame() const override;
  [[nodiscard]] double time() const override;
  [[nodiscard]] const Elements& elements() const override;
  [[nodiscard]] const std::vector<ElementSource>& element_sources() const override;
  [[nodiscard]] std::int64_t body_count() const override;
  void body_shapes(std::vector<BodyShape>& out) const override;
  // Element k's centre at a kept frame (k must exist then and now), also while a step is pending:
  // from the snapshot's element sources and local centres then, the world's otherwise.
  void element_centre(const WorldState& state, ElementId k, double& x, double& y) const;
  // The world itself (only when no step is pending).
  [[nodiscard]] const Box2dFrame* box2d() const override { return world_.get(); }
  // Box2D's step on this thread; its milliseconds. Throws Error as PhysicsWorld::step().
  double step();

  // ---- the overlapped step ----
  // Starts the next step on a worker thread, then `then` on the same thread with the new frame (the
  // frame's detection and check); false (nothing pending) when no thread can be had. Until
  // finish_step() the owner touches nothing `then` uses.
  bool begin_step(std::function<void(const Frame& next)> then = {});
  // True between begin_step() and finish_step()/discard_step().
  [[nodiscard]] bool pending() const { return stepping_.valid(); }
  // True when a pending step has finished (finish_step() will not wait): the window adopts it then.
  [[nodiscard]] bool step_ready() const;
  // Waits for the worker; returns the step's own milliseconds, Box2D's alone (rethrows its Error, or
  // `then`'s; spent either way).
  double finish_step();
  // Forgets a pending step (its world is about to be replaced); its error goes with it.
  void discard_step();
  // Returns once the worker is done with the world.
  void wait() const;

  // ---- the world ----
  // The world (wait() first while a step may be pending).
  [[nodiscard]] PhysicsWorld& world() { return *world_; }
  [[nodiscard]] const PhysicsWorld& world() const { return *world_; }
  // The world's frame, the newest of the run (the one shown while a step is pending).
  [[nodiscard]] std::int64_t newest_frame() const { return pending() ? shown_.frame : world_->frame(); }
  // Replaces the world by one re-simulated to its frame (a resume's arrival); drags from that frame on are forgotten.
  void replace_world(std::unique_ptr<PhysicsWorld> world);

  // ---- drags (each logged with its frame) ----
  bool begin_drag(double x, double y);
  void drag_to(double x, double y);
  void end_drag();
  // Ends a drag, logged as the user's own end would be (a drag cannot continue where the frame is left).
  void release_drag();
  // True while a body is held (the snapshot's while a step is pending).
  [[nodiscard]] bool dragging() const;
  // Every drag call of the run, in order.
  [[nodiscard]] const std::vector<DragInput>& drags() const { return drags_; }

 private:
  // What the accessors read of the current frame while the worker steps the world to the next one.
  struct ShownFrame {
    std::int64_t frame = 0;
    double time = 0;
    std::int64_t bodies = 0;
    bool dragging = false;
    Elements elements;
    std::vector<ElementSource> sources;
    std::vector<b2Vec2> local_centres;  // element_centre() of kept frames (a trail) while the worker steps
    std::vector<BodyShape> shapes;
  };

  std::unique_ptr<PhysicsWorld> world_;
  std::vector<DragInput> drags_;
  ShownFrame shown_;
  // The worker's world_->step(); its result: the step's own milliseconds. Declared after world_, so
  // it is destroyed (waited for) first.
  std::future<double> stepping_;
};

}  // namespace nbscope

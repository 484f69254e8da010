// nbscope app: a scene simulated by Box2D as a frame source (io/frame_source.hpp): the live world
// (physics/live_world.hpp: its plain and overlapped step, the drags), the past frame shown
// (physics/kept_frame.hpp, rebuilt from what the history kept) and resume (physics/resume.hpp).
// Only app/frame_sources.cpp makes one; everyone else sees a FrameSource.
#pragma once
#include <memory>

#include "io/frame_source.hpp"
#include "physics/kept_frame.hpp"
#include "physics/live_world.hpp"
#include "physics/resume.hpp"

namespace nbscope {

class SimulatedSource final : public FrameSource, public Simulation {
 public:
  // Takes `world`, built from `scene` (frame 0).
  SimulatedSource(Scene scene, std::unique_ptr<PhysicsWorld> world);
  ~SimulatedSource() override;
  SimulatedSource(const SimulatedSource&) = delete;
  SimulatedSource& operator=(const SimulatedSource&) = delete;

  // ---- Frame: the past frame shown, else the live world's (its snapshot while a step is pending) ----
  [[nodiscard]] std::int64_t frame() const override { return shown().frame(); }
  [[nodiscard]] double time() const override { return shown().time(); }
  [[nodiscard]] const Elements& elements() const override { return shown().elements(); }
  [[nodiscard]] const std::vector<ElementSource>& element_sources() const override { return shown().element_sources(); }
  [[nodiscard]] std::int64_t body_count() const override { return shown().body_count(); }
  void body_shapes(std::vector<BodyShape>& out) const override { shown().body_shapes(out); }
  [[nodiscard]] const Box2dFrame* box2d() const override { return shown().box2d(); }

  // ---- FrameSource ----
  [[nodiscard]] const Scene& scene() const override { return scene_; }
  [[nodiscard]] bool first() const override { return frame() == 0; }
  [[nodiscard]] std::int64_t newest_frame() const override { return live_->newest_frame(); }
  // The live world always has a next frame (a past frame's next is the run's own, kept).
  [[nodiscard]] bool can_step() const override { return kept_ == nullptr; }
  double step() override { return live_->step(); }
  void show(std::int64_t frame, const std::shared_ptr<const WorldState>& kept) override;
  // A fresh world from the scene at frame 0; the drags and the resume go.
  void rewind() override;
  [[nodiscard]] bool showing_past() const override { return kept_ != nullptr; }
  [[nodiscard]] KeptState keep(const PairList* box2d_contacts) const override;
  [[nodiscard]] Elements previous_elements(const std::shared_ptr<const WorldState>& kept_before) const override;
  void element_path(const FrameHistory& history, ElementId k, std::int64_t from, std::int64_t to,
                    std::vector<std::array<double, 2>>& out) const override;
  // Box2D's step: bodies and contacts.
  [[nodiscard]] std::function<std::string()> step_note() const override;
  [[nodiscard]] Simulation* simulation() override { return this; }

  // ---- Simulation ----
  bool begin_step(std::function<void(const Frame& next)> then) override { return live_->begin_step(std::move(then)); }
  [[nodiscard]] bool pending() const override { return live_->pending(); }
  [[nodiscard]] bool step_ready() const override { return live_->step_ready(); }
  double finish_step() override { return live_->finish_step(); }
  void discard_step() override { live_->discard_step(); }
  void wait() const override { live_->wait(); }
  bool begin_drag(double x, double y) override { return live_->begin_drag(x, y); }
  void drag_to(double x, double y) override { live_->drag_to(x, y); }
  void end_drag() override { live_->end_drag(); }
  [[nodiscard]] bool dragging() const override { return live_->dragging(); }
  void begin_resume() override;
  bool advance_resume(double budget_ms, const std::function<std::uint64_t(std::int64_t)>& hash_of) override;
  void cancel_resume() override { resume_.cancel(); }
  [[nodiscard]] bool resuming() const override { return resume_.active(); }
  [[nodiscard]] std::pair<std::int64_t, std::int64_t> resume_progress() const override { return resume_.progress(); }
  [[nodiscard]] std::optional<std::int64_t> divergence() const override { return resume_.divergence(); }
  [[nodiscard]] Elements resumed_previous() const override { return resume_.previous_elements(); }

 private:
  [[nodiscard]] const Frame& shown() const {
    if (kept_) return *kept_;
    return *live_;
  }

  Scene scene_;
  std::unique_ptr<LiveWorld> live_;
  std::unique_ptr<KeptWorldFrame> kept_;  // the past frame shown (it reads live_'s world), or null
  Resume resume_;                         // a fresh world re-simulated to the past frame shown
};

}  // namespace nbscope

// nbscope app: the Scaling panel's run on a thread of its own, so that the window keeps drawing
// while detectors are timed; cancelled and joined when the panel closes or the view goes.
#pragma once
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include "ui/scaling_panel.hpp"

namespace nbscope {

class ScalingJob final : public ui::ScalingRunner {
 public:
  ScalingJob() = default;
  // Cancels a run going on and waits for it (at most one detection).
  ~ScalingJob() override;
  ScalingJob(const ScalingJob&) = delete;
  ScalingJob& operator=(const ScalingJob&) = delete;

  // Starts `plan` on the job's thread unless one is running; a plan that cannot run becomes a note.
  void start(const ScalingPlan& plan) override;
  // Asks the running plan to stop after the current detection.
  void cancel() override;
  // A copy of the state; joins a thread that has finished.
  [[nodiscard]] ui::ScalingStatus status() const override;
  // Shows finished rows (headless --scaling), read from `source` ("" for a run made elsewhere).
  void show(const ScalingResult& result, const ScalingPlan& plan, const std::string& source, double seconds);
  // True while a plan runs (cheap: the window asks every frame whether it may sleep).
  [[nodiscard]] bool running() const { return !finished_.load(); }
  // Waits for the run going on, if any, to finish (tests; the window never waits).
  void wait();

 private:
  mutable std::mutex mutex_;
  ui::ScalingStatus status_;
  std::atomic<bool> cancel_{false};
  std::atomic<bool> finished_{true};
  mutable std::thread thread_;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace nbscope

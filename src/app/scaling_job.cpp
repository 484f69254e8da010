#include "app/scaling_job.hpp"

#include "core/error.hpp"

namespace nbscope {

ScalingJob::~ScalingJob() {
  cancel_ = true;
  if (thread_.joinable()) thread_.join();
}

void ScalingJob::start(const ScalingPlan& plan) {
  if (!finished_) return;
  if (thread_.joinable()) thread_.join();
  cancel_ = false;
  {
    std::lock_guard lock(mutex_);
    status_.running = true;
    status_.done = 0;
    status_.total = scaling_point_count(plan);
    status_.point.clear();
    status_.plan = plan;
    status_.result = ScalingResult{};
    status_.seconds = 0;
    status_.source.clear();
    ++status_.generation;
  }
  started_ = std::chrono::steady_clock::now();
  finished_ = false;
  thread_ = std::thread([this, plan] {
    ScalingResult result;
    try {
      result = run_scaling(
          plan,
          [this](const ScalingProgress& p) {
            std::lock_guard lock(mutex_);
            status_.done = p.done;
            status_.point = p.point;
            if (p.row != nullptr) status_.result.rows.push_back(*p.row);
            if (!p.note.empty()) status_.result.notes.push_back(p.point + ": " + p.note);
            status_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
          },
          &cancel_);
    } catch (const std::exception& e) {  // a plan that cannot run, out of memory at 1e7, ...
      result.rows = status().result.rows;
      result.notes.push_back(std::string("stopped: ") + e.what());
      result.cancelled = true;
    }
    {
      std::lock_guard lock(mutex_);
      status_.result = std::move(result);
      status_.running = false;
      status_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    }
    finished_ = true;
  });
}

void ScalingJob::cancel() { cancel_ = true; }

ui::ScalingStatus ScalingJob::status() const {
  if (finished_ && thread_.joinable()) thread_.join();  // done: joining does not wait
  std::lock_guard lock(mutex_);
  return status_;
}

void ScalingJob::show(const ScalingResult& result, const ScalingPlan& plan, const std::string& source, double seconds) {
  cancel_ = true;
  if (thread_.joinable()) thread_.join();
  std::lock_guard lock(mutex_);
  status_.running = false;
  // A run made elsewhere fills the bar; rows read from a file ran nowhere.
  status_.done = status_.total = source.empty() ? result.rows.size() + result.notes.size() : 0;
  status_.point.clear();
  status_.plan = plan;
  status_.result = result;
  status_.seconds = seconds;
  status_.source = source;
  ++status_.generation;
}

void ScalingJob::wait() {
  if (thread_.joinable()) thread_.join();
}

}  // namespace nbscope

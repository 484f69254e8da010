// The slow-frame note's watcher thread.
#include "app/frame_watch.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace nbscope {

namespace {

double threshold_from_environment() {
  if (const char* text = std::getenv("NBSCOPE_SLOW_FRAME_SECONDS")) {
    char* end = nullptr;
    const double v = std::strtod(text, &end);
    if (end != text && *end == '\0' && v > 0 && v < 1e6) return v;
  }
  return 5.0;
}

}  // namespace

FrameWatch::FrameWatch() : threshold_(threshold_from_environment()) {}

FrameWatch::~FrameWatch() {
  {
    const std::lock_guard lock(mutex_);
    quit_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void FrameWatch::arm(std::int64_t frame, Describe describe) {
  {
    const std::lock_guard lock(mutex_);
    if (noted_) return;  // once per run
    describe_ = std::move(describe);
    if (armed_ && frame_ == frame) return;  // another phase of the same frame: its clock runs on
    armed_ = true;
    frame_ = frame;
    started_ = std::chrono::steady_clock::now();
    first_phase_ended_.reset();
    ++generation_;
    if (!thread_.joinable()) thread_ = std::thread([this] { watch(); });
  }
  wake_.notify_all();
}

void FrameWatch::next_phase(std::int64_t frame, Describe describe) {
  const std::lock_guard lock(mutex_);
  if (!armed_ || frame_ != frame) return;
  if (!first_phase_ended_) {
    first_phase_ended_ = std::chrono::steady_clock::now();
    first_describe_ = std::move(describe_);
  }
  describe_ = std::move(describe);
}

void FrameWatch::disarm() {
  const std::lock_guard lock(mutex_);
  if (armed_ && !noted_) add_recent(std::chrono::steady_clock::now());
  armed_ = false;
  first_describe_ = nullptr;
}

void FrameWatch::reset() {
  const std::lock_guard lock(mutex_);
  armed_ = false;
  noted_ = false;
  recent_.clear();
}

void FrameWatch::add_recent(std::chrono::steady_clock::time_point now) {
  const auto seconds = [](auto from, auto to) { return std::chrono::duration<double>(to - from).count(); };
  const auto first_end = first_phase_ended_.value_or(now);
  if (!recent_.empty() && recent_.back().frame + 1 != frame_) recent_.clear();  // consecutive frames only
  recent_.push_back({frame_, seconds(started_, first_end), seconds(first_end, now)});
  if (recent_.size() > static_cast<std::size_t>(kSlowWindow)) recent_.pop_front();
  double first = 0, later = 0;
  for (const Spent& s : recent_) {
    first += s.first_phase;
    later += s.later;
  }
  if (recent_.size() < 2 || first + later <= threshold_) return;
  // The frames are done: what they read is not changing.
  const Describe& what = first >= later && first_describe_ ? first_describe_ : describe_;
  const std::string text = what ? what() : std::string();
  std::fprintf(stderr, "nbscope: note: frames %lld to %lld took %.*f s together%s%s%s\n", static_cast<long long>(recent_.front().frame),
               static_cast<long long>(recent_.back().frame), first + later < 1 ? 2 : 1, first + later, text.empty() ? "" : " (", text.c_str(),
               text.empty() ? "" : ")");
  std::fflush(stderr);
  noted_ = true;
}

bool FrameWatch::noted() const {
  const std::lock_guard lock(mutex_);
  return noted_;
}

void FrameWatch::watch() {
  std::unique_lock lock(mutex_);
  while (!quit_) {
    if (!armed_ || noted_) {
      wake_.wait(lock);
      continue;
    }
    const std::uint64_t generation = generation_;
    const auto deadline = started_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(threshold_));
    if (wake_.wait_until(lock, deadline, [&] { return quit_ || !armed_ || generation_ != generation; })) continue;
    // Still the same frame, past the threshold: say what it is doing (the description is asked for
    // under the lock, so that the frame cannot end and be replaced meanwhile).
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    const std::string what = describe_ ? describe_() : std::string();
    std::fprintf(stderr, "nbscope: note: frame %lld has run for %.1f s so far%s%s%s\n", static_cast<long long>(frame_), seconds,
                 what.empty() ? "" : " (", what.c_str(), what.empty() ? "" : ")");
    std::fflush(stderr);
    noted_ = true;
  }
}

}  // namespace nbscope

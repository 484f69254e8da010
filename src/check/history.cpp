#include "check/history.hpp"

#include <algorithm>
#include <cassert>

namespace nbscope {

// ---- FrameHistory --------------------------------------------------------------------------

void FrameHistory::clear() {
  summaries_.clear();
  states_.clear();
  state_sizes_.clear();
  first_state_ = 0;
  state_bytes_ = 0;
  dropped_ = 0;
}

void FrameHistory::set_budget(std::size_t bytes) {
  budget_ = bytes;
  enforce_budget();
}

void FrameHistory::set_max_summaries(std::size_t count) { max_summaries_ = std::max<std::size_t>(count, 1); }

void FrameHistory::push(const FrameSummary& summary, std::shared_ptr<const WorldState> state, std::size_t state_bytes) {
  assert((summaries_.empty() || summary.frame > summaries_.back().frame) && "FrameHistory::push: frames must increase");
  summaries_.push_back(summary);
  state_bytes_ += state ? state_bytes : 0;
  state_sizes_.push_back(state ? state_bytes : 0);
  states_.push_back(std::move(state));
  while (summaries_.size() > max_summaries_) {
    state_bytes_ -= state_sizes_.front();
    summaries_.pop_front();
    states_.pop_front();
    state_sizes_.pop_front();
    first_state_ = first_state_ > 0 ? first_state_ - 1 : 0;
  }
  enforce_budget();
}

void FrameHistory::enforce_budget() {
  // Never the newest: the frame on screen must stay showable.
  while (state_bytes_ > budget_ && first_state_ + 1 < states_.size()) {
    if (states_[first_state_]) {
      state_bytes_ -= state_sizes_[first_state_];
      state_sizes_[first_state_] = 0;
      states_[first_state_].reset();
      summaries_[first_state_].kept = false;
      ++dropped_;
    }
    ++first_state_;
  }
}

std::optional<std::size_t> FrameHistory::find(std::int64_t frame) const {
  const std::size_t index = first_from(frame);
  if (index == summaries_.size() || summaries_[index].frame != frame) return std::nullopt;
  return index;
}

std::size_t FrameHistory::first_from(std::int64_t frame) const {
  const auto it = std::lower_bound(summaries_.begin(), summaries_.end(), frame,
                                   [](const FrameSummary& s, std::int64_t f) { return s.frame < f; });
  return static_cast<std::size_t>(it - summaries_.begin());
}

void FrameHistory::update(std::size_t index, const FrameSummary& summary) {
  const bool kept = summaries_[index].kept;
  summaries_[index] = summary;
  summaries_[index].kept = kept;
}

void FrameHistory::truncate_after(std::int64_t frame) {
  while (!summaries_.empty() && summaries_.back().frame > frame) {
    state_bytes_ -= state_sizes_.back();
    summaries_.pop_back();
    states_.pop_back();
    state_sizes_.pop_back();
  }
  first_state_ = std::min(first_state_, summaries_.empty() ? 0 : summaries_.size() - 1);
}

std::optional<std::int64_t> FrameHistory::first_kept() const {
  for (std::size_t k = first_state_; k < summaries_.size(); ++k)
    if (summaries_[k].kept) return summaries_[k].frame;
  return std::nullopt;
}

// ---- ViolationLog --------------------------------------------------------------------------

void ViolationLog::clear() {
  listed_.clear();
  per_frame_.clear();
  by_invariant_ = {};
  ++generation_;
}

void ViolationLog::forget_frame(std::int64_t frame) {
  const auto counts = per_frame_.find(frame);
  if (counts == per_frame_.end()) return;
  for (std::size_t k = 0; k < by_invariant_.size(); ++k) by_invariant_[k] -= counts->second[k];
  per_frame_.erase(counts);
  const auto by_frame = [](const Violation& v, std::int64_t f) { return v.frame < f; };
  const auto first = std::lower_bound(listed_.begin(), listed_.end(), frame, by_frame);
  auto last = first;
  while (last != listed_.end() && last->frame == frame) ++last;
  listed_.erase(first, last);
}

void ViolationLog::set_frame(const FrameReport& report) {
  forget_frame(report.frame);
  ++generation_;  // also when a frame checked again lists the same number of others
  if (report.violation_count() == 0) return;
  per_frame_[report.frame] = report.broken;
  for (std::size_t k = 0; k < by_invariant_.size(); ++k) by_invariant_[k] += report.broken[k];
  const auto by_frame = [](std::int64_t f, const Violation& v) { return f < v.frame; };
  auto at = std::upper_bound(listed_.begin(), listed_.end(), report.frame, by_frame);
  const std::size_t room = kMaxListed > listed_.size() ? kMaxListed - listed_.size() : 0;
  const std::size_t n = std::min(room, report.violations.size());
  listed_.insert(at, report.violations.begin(), report.violations.begin() + static_cast<std::ptrdiff_t>(n));
}

void ViolationLog::truncate_after(std::int64_t frame) {
  while (!per_frame_.empty() && per_frame_.rbegin()->first > frame) forget_frame(per_frame_.rbegin()->first);
  ++generation_;
}

std::int64_t ViolationLog::total() const {
  std::int64_t t = 0;
  for (const std::int64_t v : by_invariant_) t += v;
  return t;
}

std::optional<std::int64_t> ViolationLog::first_frame() const {
  if (per_frame_.empty()) return std::nullopt;
  return per_frame_.begin()->first;
}

}  // namespace nbscope

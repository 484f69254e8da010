// nbscope io: recorded frames as a frame source (recording_source.hpp).
#include "io/recording_source.hpp"

#include <algorithm>

namespace nbscope {

RecordingSource::RecordingSource(std::unique_ptr<RecordedFrames> frames, std::size_t budget)
    : frames_(std::move(frames)), budget_(budget) {
  current_ = frame_at(0);
}

const std::vector<ElementSource>& RecordingSource::element_sources() const {
  static const std::vector<ElementSource> kNone;
  return kNone;
}

double RecordingSource::step() {
  if (can_step()) show_index(index_ + 1);
  return 0;
}

void RecordingSource::show_index(std::size_t index) {
  if (index == index_ && current_) return;
  current_ = frame_at(index);  // first: a frame that cannot be read leaves the current one shown
  index_ = index;
}

std::size_t RecordingSource::index_of(std::int64_t frame) const {
  const auto& e = entries();
  const auto it = std::lower_bound(e.begin(), e.end(), frame, [](const RecordedEntry& f, std::int64_t n) { return f.number < n; });
  return static_cast<std::size_t>(it - e.begin());
}

Elements RecordingSource::previous_elements() const { return frame_at(index_ > 0 ? index_ - 1 : 0)->elements; }

std::shared_ptr<const RecordedFrame> RecordingSource::held(std::size_t index) const {
  if (current_ && index == index_) return current_;
  if (!frames_->reads_files()) return frames_->read(index);
  const auto it = kept_.find(index);
  return it != kept_.end() ? it->second.first : nullptr;
}

std::shared_ptr<const RecordedFrame> RecordingSource::frame_at(std::size_t index) const {
  if (auto f = held(index)) return f;
  auto f = frames_->read(index);
  keep(index, f);
  return f;
}

void RecordingSource::keep(std::size_t index, const std::shared_ptr<const RecordedFrame>& frame) const {
  const std::size_t bytes = recorded_frame_bytes(*frame);
  if (bytes > budget_) return;
  kept_.emplace(index, std::make_pair(frame, bytes));
  order_.push_back(index);
  kept_bytes_ += bytes;
  trim();
}

void RecordingSource::trim() const {
  while (kept_bytes_ > budget_ && !order_.empty()) {
    const auto it = kept_.find(order_.front());
    order_.pop_front();
    if (it == kept_.end()) continue;
    kept_bytes_ -= it->second.second;
    kept_.erase(it);
  }
}

void RecordingSource::set_budget(std::size_t bytes) {
  budget_ = bytes;
  trim();
}

}  // namespace nbscope

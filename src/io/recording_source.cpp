// nbscope io: recorded frames as a frame source (recording_source.hpp).
#include "io/recording_source.hpp"

#include <algorithm>
#include <filesystem>

namespace nbscope {

RecordingSource::RecordingSource(std::unique_ptr<RecordedFrames> frames, std::size_t budget)
    : frames_(std::move(frames)), budget_(budget) {
  current_ = frame_at(0);
  const Recording& rec = header();
  scene_.path = rec.path;
  scene_.name = std::filesystem::path(rec.path).stem().string();
  scene_.grid = rec.grid;
  // The recorded time per frame, for the panels (the recording's own times are shown per frame).
  const RecordedEntry& first = entries().front();
  const RecordedEntry& last = entries().back();
  if (last.number > first.number && last.time > first.time)
    scene_.time_step = (last.time - first.time) / static_cast<double>(last.number - first.number);
}

const std::vector<ElementSource>& RecordingSource::element_sources() const {
  static const std::vector<ElementSource> kNone;
  return kNone;
}

double RecordingSource::step() {
  if (index_ + 1 < entries().size() || frames_->more()) show_index(index_ + 1);
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

void RecordingSource::show(std::int64_t frame, const std::shared_ptr<const WorldState>& kept) {
  (void)kept;
  show_index(index_of(frame));
}

Elements RecordingSource::previous_elements(const std::shared_ptr<const WorldState>& kept_before) const {
  (void)kept_before;
  return frame_at(index_ > 0 ? index_ - 1 : 0)->elements;
}

std::shared_ptr<const std::vector<std::int64_t>> RecordingSource::ids() const {
  if (current_->ids.empty()) return nullptr;
  return {current_, &current_->ids};  // holds the frame while its ids are used
}

void RecordingSource::element_path(const FrameHistory& history, ElementId k, std::int64_t from, std::int64_t to,
                                   std::vector<std::array<double, 2>>& out) const {
  out.clear();
  if (k < 0) return;
  // A dump's rows shift as atoms come and go: the atom at row k of frame `to` is followed by its id.
  const std::size_t to_index = index_of(to);
  const std::shared_ptr<const RecordedFrame> frame_to = to_index < entries().size() ? frame_at(to_index) : nullptr;
  const bool by_atom = frame_to != nullptr && static_cast<std::size_t>(k) < frame_to->ids.size();
  const std::int64_t atom = by_atom ? frame_to->ids[static_cast<std::size_t>(k)] : -1;
  // From the first summary at or after `from` (a trail is a few hundred frames of a long history).
  for (std::size_t i = history.first_from(from); i < history.size(); ++i) {
    const FrameSummary& f = history.at(i);
    if (f.frame > to) break;
    const std::shared_ptr<const RecordedFrame> rf = held(index_of(f.frame));
    if (!rf) continue;
    std::int64_t row = k;
    if (by_atom) {
      const auto it = std::lower_bound(rf->ids.begin(), rf->ids.end(), atom);  // ascending (io/recording.hpp)
      row = it != rf->ids.end() && *it == atom ? it - rf->ids.begin() : -1;     // -1: not in that frame
    }
    if (row >= 0 && row < rf->elements.size()) out.push_back({rf->elements.x[row], rf->elements.y[row]});
  }
}

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

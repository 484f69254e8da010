// nbscope io: a recording's frames as a frame source (recording_source.hpp).
#include "io/recording_source.hpp"

#include <algorithm>

namespace nbscope {

RecordingSource::RecordingSource(std::shared_ptr<const Recording> recording) : recording_(std::move(recording)) {}

const std::vector<ElementSource>& RecordingSource::element_sources() const {
  static const std::vector<ElementSource> kNone;
  return kNone;
}

double RecordingSource::step() {
  if (can_step()) ++index_;
  return 0;
}

std::size_t RecordingSource::index_of(std::int64_t frame) const {
  const auto& frames = recording_->frames;
  const auto it = std::lower_bound(frames.begin(), frames.end(), frame,
                                   [](const RecordedFrame& f, std::int64_t n) { return f.number < n; });
  return static_cast<std::size_t>(it - frames.begin());
}

}  // namespace nbscope

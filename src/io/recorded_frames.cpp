// nbscope io: a recording held whole as RecordedFrames (recorded_frames.hpp).
#include "io/recorded_frames.hpp"

#include "core/error.hpp"

namespace nbscope {

namespace {

class HeldFrames final : public RecordedFrames {
 public:
  explicit HeldFrames(Recording r) {
    if (r.frames.empty()) throw Error(r.path + ": no frames");
    frames_.reserve(r.frames.size());
    entries_.reserve(r.frames.size());
    for (RecordedFrame& f : r.frames) {
      entries_.push_back(RecordedEntry{f.number, f.time, f.elements.size()});
      frames_.push_back(std::make_shared<const RecordedFrame>(std::move(f)));
    }
    r.frames.clear();
    r.frames.shrink_to_fit();
    header_ = std::move(r);
  }
  [[nodiscard]] const Recording& header() const override { return header_; }
  [[nodiscard]] const std::vector<RecordedEntry>& entries() const override { return entries_; }
  [[nodiscard]] std::shared_ptr<const RecordedFrame> read(std::size_t index) override { return frames_.at(index); }
  [[nodiscard]] bool reads_files() const override { return false; }

 private:
  Recording header_;
  std::vector<RecordedEntry> entries_;
  std::vector<std::shared_ptr<const RecordedFrame>> frames_;
};

}  // namespace

std::unique_ptr<RecordedFrames> held_frames(Recording recording) { return std::make_unique<HeldFrames>(std::move(recording)); }

std::size_t recorded_frame_bytes(const RecordedFrame& f) {
  const auto n = static_cast<std::size_t>(f.elements.size());
  return sizeof f + n * static_cast<std::size_t>(f.elements.dim + 1) * sizeof(double) + f.ids.capacity() * sizeof(std::int64_t) +
         f.ranks.capacity() * sizeof(std::int32_t) + f.pairs.capacity() * sizeof(f.pairs[0]) +
         (f.columns ? f.columns->values.size() * n * sizeof(double) : 0);
}

}  // namespace nbscope

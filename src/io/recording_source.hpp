// nbscope io: recorded frames (io/recorded_frames.hpp) as a frame source (io/frame_source.hpp): one after the other, no
// bodies (each element is drawn as a dynamic circle) and no Box2D side (the check runs only A==R).
// Frames read from files are kept within a byte budget (the history's): the current one always, the
// others until the budget is spent, oldest dropped first; a dropped frame is read again when shown.
#pragma once
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <vector>

#include "io/frame_source.hpp"
#include "io/recorded_frames.hpp"

namespace nbscope {

class RecordingSource final : public FrameSource {
 public:
  // Starts at the first frame (read now: its errors come from here), keeping at most `budget` bytes
  // of other frames read from files.
  RecordingSource(std::unique_ptr<RecordedFrames> frames, std::size_t budget);

  // ---- Frame ----
  [[nodiscard]] std::int64_t frame() const override { return current_->number; }
  [[nodiscard]] double time() const override { return current_->time; }
  [[nodiscard]] const Elements& elements() const override { return current_->elements; }
  // No bodies.
  [[nodiscard]] const std::vector<ElementSource>& element_sources() const override;
  [[nodiscard]] std::int64_t body_count() const override { return 0; }
  // One dynamic circle per element.
  void body_shapes(std::vector<BodyShape>& out) const override { circles_of(elements(), out); }
  [[nodiscard]] const Box2dFrame* box2d() const override { return nullptr; }
  [[nodiscard]] std::shared_ptr<const std::vector<std::int64_t>> ids() const override;
  // The frame's `pairs` block when the recording carries pairs, else null.
  [[nodiscard]] const PairList* recorded_pairs() const override { return header().has_pairs ? &current_->pairs : nullptr; }
  [[nodiscard]] double precision() const override { return current_->precision; }
  [[nodiscard]] const std::vector<std::int32_t>* ranks() const override { return current_->ranks.empty() ? nullptr : &current_->ranks; }
  [[nodiscard]] const Subdomains* subdomains() const override { return current_->subdomains.get(); }
  [[nodiscard]] std::shared_ptr<const AtomColumns> columns() const override { return current_->columns; }

  // ---- FrameSource ----
  [[nodiscard]] const Scene& scene() const override { return scene_; }
  [[nodiscard]] const Recording* recording() const override { return &header(); }
  // Every frame's number, time and element count.
  [[nodiscard]] const std::vector<RecordedEntry>& entries() const override { return frames_->entries(); }
  [[nodiscard]] bool first() const override { return index_ == 0; }
  [[nodiscard]] std::int64_t newest_frame() const override { return entries().back().number; }
  // False on the last frame, unless more frames may still come (a run being written).
  [[nodiscard]] bool can_step() const override { return index_ + 1 < entries().size() || frames_->growing(); }
  // The next recorded frame (nothing simulated: 0 ms); on the last, the frames looked at for a new
  // one (RecordedFrames::more), else no effect. Error, unmoved, for a frame whose text is wrong.
  double step() override;
  // Recorded frame number `frame` (it must exist); `kept` is not needed. Error, unmoved, as step().
  void show(std::int64_t frame, const std::shared_ptr<const WorldState>& kept) override;
  void rewind() override { show_index(0); }
  // The frame before the current one (the first frame's own for the first), read when not kept.
  [[nodiscard]] Elements previous_elements(const std::shared_ptr<const WorldState>& kept_before) const override;
  // Through the frames held (none is read again for a trail), each atom followed by its id.
  void element_path(const FrameHistory& history, ElementId k, std::int64_t from, std::int64_t to,
                    std::vector<std::array<double, 2>>& out) const override;
  // The bytes of frames kept beside the current one, and their budget.
  [[nodiscard]] std::size_t held_bytes() const override { return kept_bytes_; }
  [[nodiscard]] std::optional<double> written_at() const override { return frames_->written_at(index_); }
  void set_budget(std::size_t bytes) override;

  // ---- the recording ----
  // The recording's facts (its `frames` empty).
  [[nodiscard]] const Recording& header() const { return frames_->header(); }
  // The index of the current frame, and the frame.
  [[nodiscard]] std::size_t index() const { return index_; }
  [[nodiscard]] const RecordedFrame& current() const { return *current_; }
  // Index of recorded frame number `frame` (entries().size() when there is none).
  [[nodiscard]] std::size_t index_of(std::int64_t frame) const;
  // Frame `index` when it is in memory (the current one, or kept), else null: nothing is read.
  [[nodiscard]] std::shared_ptr<const RecordedFrame> held(std::size_t index) const;
  // Frame `index`, read when it is not in memory (and then kept as the budget allows).
  [[nodiscard]] std::shared_ptr<const RecordedFrame> frame_at(std::size_t index) const;

 private:
  void show_index(std::size_t index);
  void keep(std::size_t index, const std::shared_ptr<const RecordedFrame>& frame) const;
  void trim() const;

  std::unique_ptr<RecordedFrames> frames_;
  Scene scene_;
  std::size_t index_ = 0;
  std::shared_ptr<const RecordedFrame> current_;
  std::size_t budget_ = 0;
  // Frames read from files and kept, with their bytes, and the order they came in (dropped first).
  mutable std::map<std::size_t, std::pair<std::shared_ptr<const RecordedFrame>, std::size_t>> kept_;
  mutable std::deque<std::size_t> order_;
  mutable std::size_t kept_bytes_ = 0;
};

}  // namespace nbscope

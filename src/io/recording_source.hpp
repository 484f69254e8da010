// nbscope io: a recording (io/recording.hpp) as a frame source: its frames one after the other, no
// bodies (each element is drawn as a dynamic circle) and no Box2D side (the check runs only A==R).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "io/recording.hpp"
#include "physics/frame_source.hpp"

namespace nbscope {

class RecordingSource final : public FrameSource {
 public:
  // Starts at the recording's first frame (it has at least one).
  explicit RecordingSource(std::shared_ptr<const Recording> recording);

  [[nodiscard]] std::int64_t frame() const override { return current().number; }
  [[nodiscard]] double time() const override { return current().time; }
  [[nodiscard]] const Elements& elements() const override { return current().elements; }
  // No bodies.
  [[nodiscard]] const std::vector<ElementSource>& element_sources() const override;
  [[nodiscard]] std::int64_t body_count() const override { return 0; }
  // One dynamic circle per element.
  void body_shapes(std::vector<BodyShape>& out) const override { circles_of(elements(), out); }
  [[nodiscard]] const Box2dFrame* box2d() const override { return nullptr; }
  // False on the last frame.
  [[nodiscard]] bool can_step() const override { return index_ + 1 < recording_->frames.size(); }
  // The next recorded frame (nothing simulated: 0 ms); no effect on the last.
  double step() override;

  // The recording and the index of the current frame in it.
  [[nodiscard]] const Recording& recording() const { return *recording_; }
  [[nodiscard]] std::size_t index() const { return index_; }
  [[nodiscard]] const RecordedFrame& current() const { return recording_->frames[index_]; }
  // Makes the first frame current again.
  void rewind() { index_ = 0; }
  // Makes recorded frame number `frame` current (it must exist).
  void show(std::int64_t frame) { index_ = index_of(frame); }
  // Index of recorded frame number `frame` (it must exist).
  [[nodiscard]] std::size_t index_of(std::int64_t frame) const;
  // The frame before the current one (the first frame's own for the first).
  [[nodiscard]] const Elements& previous_elements() const { return recording_->frames[index_ > 0 ? index_ - 1 : 0].elements; }

 private:
  std::shared_ptr<const Recording> recording_;
  std::size_t index_ = 0;
};

}  // namespace nbscope

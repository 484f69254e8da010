// nbscope app: where frame sources are made (io/frame_source.hpp is their contract). A new kind of
// source is one class and one function here; the loop takes it with FrameLoop::load().
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>

#include "io/frame_source.hpp"
#include "io/recorded_frames.hpp"
#include "physics/scene.hpp"

namespace nbscope {

// A Box2D world built from `scene` at frame 0 (`max_contacts` over the scene's key: --max-contacts).
// Error "<where>: <what>" when the scene cannot be simulated (a pinned cell smaller than an element).
std::unique_ptr<FrameSource> simulated_source(const Scene& scene, std::optional<std::int64_t> max_contacts);
// Recorded frames replayed at their first frame (read now: its errors come from here), keeping at
// most `budget` bytes of other frames read from files.
std::unique_ptr<FrameSource> recorded_source(std::unique_ptr<RecordedFrames> frames, std::size_t budget);

}  // namespace nbscope

// nbscope physics: where a frame comes from. The pipeline (check/pipeline.hpp) and the views read a
// frame only through this interface, so the live Box2D world (physics/live_world.hpp), a kept past
// frame (physics/kept_frame.hpp) and a recording (io/recording_source.hpp) are one kind of thing;
// frames from other codes and 3D frames come in as more implementations.
#pragma once
#include <cstdint>
#include <vector>

#include "core/elements.hpp"
#include "physics/box2d_frame.hpp"
#include "physics/shapes.hpp"

namespace nbscope {

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  // The frame's number and simulated time in seconds (a recording's own).
  [[nodiscard]] virtual std::int64_t frame() const = 0;
  [[nodiscard]] virtual double time() const = 0;
  // The frame's elements (bounding circles).
  [[nodiscard]] virtual const Elements& elements() const = 0;
  // Element -> (body, fixture); empty when the frame has no bodies.
  [[nodiscard]] virtual const std::vector<ElementSource>& element_sources() const = 0;
  // Bodies that exist at this frame (0 without bodies).
  [[nodiscard]] virtual std::int64_t body_count() const = 0;
  // Every shape at this frame in world coordinates, for drawing (clears `out` first).
  virtual void body_shapes(std::vector<BodyShape>& out) const = 0;
  // Box2D's side of the frame for the check, or null when there is none (recorded frames).
  [[nodiscard]] virtual const Box2dFrame* box2d() const = 0;
  // True when step() can make a next frame.
  [[nodiscard]] virtual bool can_step() const = 0;
  // Makes the next frame; returns the milliseconds spent simulating it (0 when nothing is simulated).
  virtual double step() = 0;
};

// One dynamic circle per element: how frames without bodies are drawn.
inline void circles_of(const Elements& e, std::vector<BodyShape>& out) {
  out.clear();
  out.resize(static_cast<std::size_t>(e.size()));
  for (Eigen::Index k = 0; k < e.size(); ++k) {
    BodyShape& b = out[static_cast<std::size_t>(k)];
    b.element = static_cast<ElementId>(k);
    b.centre = Vec2{e.x[k], e.y[k]};
    b.radius = e.r[k];
  }
}

}  // namespace nbscope

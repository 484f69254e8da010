// nbscope render: the GPU side of batched drawing. Each primitive kind has one instance layout and
// one GL buffer that grows as needed and is refilled every frame; one draw call per kind and layer.
#pragma once
#include <cstddef>
#include <vector>

#include "render/gl.hpp"
#include "render/palette.hpp"

namespace nbscope::render {

// One circle (circle.vert): centre, radius, colours, minimum radius and outline width in pixels.
struct CircleInstance {
  float x, y, radius;
  Rgba fill, outline;
  float min_radius_px, outline_px;
};
// One segment (line.vert).
struct LineInstance {
  float x0, y0, x1, y1;
  Rgba colour;
  float width_px;
};
// One axis-aligned rectangle (rect.vert).
struct RectInstance {
  float x0, y0, x1, y1;
  Rgba colour;
};
// One vertex of a plain triangle list (triangle.vert).
struct TriangleVertex {
  float x, y;
  Rgba colour;
};

// Which primitive a GpuBatch draws.
enum class BatchKind { Rects, Triangles, Circles, Lines };
inline constexpr int kBatchKindCount = 4;
// Name of a batch kind for the Metrics window.
const char* batch_kind_name(BatchKind kind);

// A vertex array with one streamed buffer (instances, or vertices for triangles).
class GpuBatch {
 public:
  // Sets up the vertex layout of `kind`; `unit_quad` is the shared corner buffer (instanced kinds).
  GpuBatch(BatchKind kind, GLuint unit_quad_for_circles, GLuint unit_quad_for_lines, GLuint unit_quad_for_rects);
  GpuBatch(const GpuBatch&) = delete;
  GpuBatch& operator=(const GpuBatch&) = delete;
  ~GpuBatch();

  // Uploads `count` items of `item_bytes` each (growing the buffer by doubling), then draws them;
  // returns the number of draw calls issued (0 or 1).
  int upload_and_draw(const void* items, std::size_t count, std::size_t item_bytes);
  // Bytes the GL buffer holds.
  [[nodiscard]] std::size_t capacity_bytes() const { return capacity_; }

 private:
  BatchKind kind_;
  GLuint vao_ = 0;
  GLuint buffer_ = 0;
  std::size_t capacity_ = 0;
};

}  // namespace nbscope::render

#include "render/batches.hpp"

#include <cstddef>
#include <cstdint>

namespace nbscope::render {

namespace {

void float_attr(GLuint loc, int components, std::size_t stride, std::size_t offset, bool per_instance) {
  glEnableVertexAttribArray(loc);
  glVertexAttribPointer(loc, components, GL_FLOAT, GL_FALSE, static_cast<GLsizei>(stride),
                        reinterpret_cast<const void*>(static_cast<std::uintptr_t>(offset)));
  glVertexAttribDivisor(loc, per_instance ? 1 : 0);
}

void colour_attr(GLuint loc, std::size_t stride, std::size_t offset, bool per_instance) {
  glEnableVertexAttribArray(loc);
  glVertexAttribPointer(loc, 4, GL_UNSIGNED_BYTE, GL_TRUE, static_cast<GLsizei>(stride),
                        reinterpret_cast<const void*>(static_cast<std::uintptr_t>(offset)));
  glVertexAttribDivisor(loc, per_instance ? 1 : 0);
}

}  // namespace

const char* batch_kind_name(BatchKind kind) {
  switch (kind) {
    case BatchKind::Rects: return "rects";
    case BatchKind::Triangles: return "triangles";
    case BatchKind::Circles: return "circles";
    case BatchKind::Lines: return "lines";
  }
  return "?";
}

GpuBatch::GpuBatch(BatchKind kind, GLuint quad_circles, GLuint quad_lines, GLuint quad_rects) : kind_(kind) {
  glGenVertexArrays(1, &vao_);
  glGenBuffers(1, &buffer_);
  glBindVertexArray(vao_);
  const GLuint quad = kind == BatchKind::Circles ? quad_circles : (kind == BatchKind::Lines ? quad_lines : quad_rects);
  if (kind != BatchKind::Triangles) {
    glBindBuffer(GL_ARRAY_BUFFER, quad);
    float_attr(0, 2, 2 * sizeof(float), 0, false);
  }
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  switch (kind) {
    case BatchKind::Circles: {
      const std::size_t s = sizeof(CircleInstance);
      float_attr(1, 3, s, offsetof(CircleInstance, x), true);
      colour_attr(2, s, offsetof(CircleInstance, fill), true);
      colour_attr(3, s, offsetof(CircleInstance, outline), true);
      float_attr(4, 2, s, offsetof(CircleInstance, min_radius_px), true);
      break;
    }
    case BatchKind::Lines: {
      const std::size_t s = sizeof(LineInstance);
      float_attr(1, 4, s, offsetof(LineInstance, x0), true);
      colour_attr(2, s, offsetof(LineInstance, colour), true);
      float_attr(3, 1, s, offsetof(LineInstance, width_px), true);
      break;
    }
    case BatchKind::Rects: {
      const std::size_t s = sizeof(RectInstance);
      float_attr(1, 4, s, offsetof(RectInstance, x0), true);
      colour_attr(2, s, offsetof(RectInstance, colour), true);
      break;
    }
    case BatchKind::Triangles: {
      const std::size_t s = sizeof(TriangleVertex);
      float_attr(0, 2, s, offsetof(TriangleVertex, x), false);
      colour_attr(1, s, offsetof(TriangleVertex, colour), false);
      break;
    }
  }
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

GpuBatch::~GpuBatch() {
  glDeleteBuffers(1, &buffer_);
  glDeleteVertexArrays(1, &vao_);
}

int GpuBatch::upload_and_draw(const void* items, std::size_t count, std::size_t item_bytes) {
  if (count == 0) return 0;
  const std::size_t bytes = count * item_bytes;
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  if (bytes > capacity_) {
    std::size_t grown = capacity_ == 0 ? 4096 : capacity_;
    while (grown < bytes) grown *= 2;
    capacity_ = grown;
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity_), nullptr, GL_STREAM_DRAW);
  } else {
    // Orphan the old storage so the driver need not wait for last frame's draw.
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity_), nullptr, GL_STREAM_DRAW);
  }
  glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), items);
  glBindVertexArray(vao_);
  const auto n = static_cast<GLsizei>(count);
  switch (kind_) {
    case BatchKind::Triangles: glDrawArrays(GL_TRIANGLES, 0, n); break;
    default: glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, n); break;
  }
  glBindVertexArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  return 1;
}

}  // namespace nbscope::render

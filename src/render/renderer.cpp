#include "render/renderer.hpp"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace nbscope::render {

namespace {
constexpr float kCircleQuad[] = {-1, -1, 1, -1, -1, 1, 1, 1};
constexpr float kLineQuad[] = {0, -1, 1, -1, 0, 1, 1, 1};
constexpr float kRectQuad[] = {0, 0, 1, 0, 0, 1, 1, 1};

GLuint make_static_buffer(const float* data, std::size_t bytes) {
  GLuint b = 0;
  glGenBuffers(1, &b);
  glBindBuffer(GL_ARRAY_BUFFER, b);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  return b;
}

ImU32 to_imgui(Rgba c) { return IM_COL32(c.r, c.g, c.b, c.a); }
}  // namespace

Renderer::Renderer(const std::string& shader_dir)
    : circle_program_(shader_dir, "circle"),
      line_program_(shader_dir, "line"),
      rect_program_(shader_dir, "rect"),
      triangle_program_(shader_dir, "triangle") {
  quad_buffers_[0] = make_static_buffer(kCircleQuad, sizeof kCircleQuad);
  quad_buffers_[1] = make_static_buffer(kLineQuad, sizeof kLineQuad);
  quad_buffers_[2] = make_static_buffer(kRectQuad, sizeof kRectQuad);
  for (int layer = 0; layer < kLayerCount; ++layer)
    for (int kind = 0; kind < kBatchKindCount; ++kind)
      gpu_.push_back(std::make_unique<GpuBatch>(static_cast<BatchKind>(kind), quad_buffers_[0], quad_buffers_[1],
                                                quad_buffers_[2]));
  check_gl("renderer set-up");
}

Renderer::~Renderer() {
  gpu_.clear();
  glDeleteBuffers(3, quad_buffers_);
}

void Renderer::begin_frame(const Camera& camera) {
  camera_ = camera;
  for (LayerItems& l : layers_) {
    l.rects.clear();
    l.triangles.clear();
    l.circles.clear();
    l.lines.clear();
  }
  labels_.clear();
  labels_dropped_ = 0;
}

void Renderer::circle(Layer layer, Vec2 c, float radius, Rgba fill, Rgba outline, float outline_px,
                      float min_radius_px) {
  items(layer).circles.push_back({c.x(), c.y(), radius, fill, outline, min_radius_px, outline_px});
}

void Renderer::polygon(Layer layer, std::span<const Vec2> p, Rgba fill, Rgba outline) {
  if (p.size() < 3) return;
  auto& tri = items(layer).triangles;
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    tri.push_back({p[0].x(), p[0].y(), fill});
    tri.push_back({p[i].x(), p[i].y(), fill});
    tri.push_back({p[i + 1].x(), p[i + 1].y(), fill});
  }
  if (outline.a == 0) return;
  for (std::size_t i = 0; i < p.size(); ++i) line(layer, p[i], p[(i + 1) % p.size()], outline, 1.0f);
}

void Renderer::line(Layer layer, Vec2 a, Vec2 b, Rgba colour, float width_px) {
  items(layer).lines.push_back({a.x(), a.y(), b.x(), b.y(), colour, width_px});
}

void Renderer::arrow(Layer layer, Vec2 a, Vec2 b, Rgba colour, float width_px) {
  const float ppm = static_cast<float>(camera_.pixels_per_metre());
  const Vec2 d = b - a;
  const float length_px = d.norm() * ppm;
  if (length_px < 1e-3f) return;
  // Head: 9 px long (thicker lines get bigger heads) but at most 45% of the arrow.
  const float head_px = std::min(6.0f + 2.0f * width_px, 0.45f * length_px);
  const Vec2 dir = d / d.norm();
  const Vec2 normal(-dir.y(), dir.x());
  const float head = head_px / ppm;
  const Vec2 base = b - dir * head;
  line(layer, a, base, colour, width_px);
  auto& tri = items(layer).triangles;
  const Vec2 l = base + normal * (0.5f * head), r = base - normal * (0.5f * head);
  tri.push_back({b.x(), b.y(), colour});
  tri.push_back({l.x(), l.y(), colour});
  tri.push_back({r.x(), r.y(), colour});
}

void Renderer::rect(Layer layer, Vec2 min, Vec2 max, Rgba fill) {
  items(layer).rects.push_back({min.x(), min.y(), max.x(), max.y(), fill});
}

void Renderer::text(Vec2 at, std::string_view text, Rgba colour) {
  if (labels_.size() >= kMaxLabels) {
    ++labels_dropped_;
    return;
  }
  labels_.push_back({at, std::string(text), colour});
}

void Renderer::set_uniforms(const Program& p) const {
  float scale[2], offset[2];
  camera_.ndc_transform(scale, offset);
  glUseProgram(p.id());
  glUniform2f(p.uniform("u_scale"), scale[0], scale[1]);
  glUniform2f(p.uniform("u_offset"), offset[0], offset[1]);
  const GLint vp = p.uniform("u_viewport");
  if (vp >= 0) glUniform2f(vp, static_cast<float>(camera_.width()), static_cast<float>(camera_.height()));
}

void Renderer::draw(Rgba bg) {
  const auto start = std::chrono::steady_clock::now();
  glViewport(0, 0, camera_.width(), camera_.height());
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glClearColor(bg.r / 255.0f, bg.g / 255.0f, bg.b / 255.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

  stats_ = RenderStats{};
  auto run = [&](int layer, BatchKind kind, const Program& program, const void* data, std::size_t count,
                 std::size_t bytes, std::size_t vertices_each) {
    if (count == 0) return;
    set_uniforms(program);
    GpuBatch& g = *gpu_[static_cast<std::size_t>(layer * kBatchKindCount + static_cast<int>(kind))];
    stats_.draw_calls += g.upload_and_draw(data, count, bytes);
    stats_.batches.push_back({static_cast<Layer>(layer), kind, count, count * vertices_each, g.capacity_bytes()});
  };
  for (int layer = 0; layer < kLayerCount; ++layer) {
    const LayerItems& l = layers_[static_cast<std::size_t>(layer)];
    run(layer, BatchKind::Rects, rect_program_, l.rects.data(), l.rects.size(), sizeof(RectInstance), 4);
    run(layer, BatchKind::Triangles, triangle_program_, l.triangles.data(), l.triangles.size(), sizeof(TriangleVertex), 1);
    run(layer, BatchKind::Circles, circle_program_, l.circles.data(), l.circles.size(), sizeof(CircleInstance), 4);
    run(layer, BatchKind::Lines, line_program_, l.lines.data(), l.lines.size(), sizeof(LineInstance), 4);
  }
  glUseProgram(0);
  stats_.labels = labels_.size();
  stats_.labels_dropped = labels_dropped_;
  stats_.gpu_submit_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void Renderer::emit_labels(ImDrawList* list) const {
  const double w = camera_.width(), h = camera_.height();
  for (const Label& l : labels_) {
    const Eigen::Vector2d s = camera_.to_screen(l.at.cast<double>());
    if (s.x() < -50 || s.y() < -20 || s.x() > w + 50 || s.y() > h + 20) continue;
    const ImVec2 size = ImGui::CalcTextSize(l.text.c_str(), l.text.c_str() + l.text.size());
    const ImVec2 pos(std::floor(static_cast<float>(s.x()) - 0.5f * size.x),
                     std::floor(static_cast<float>(s.y()) - 0.5f * size.y));
    // A dark shadow keeps ids readable over light bodies.
    list->AddText(ImVec2(pos.x + 1, pos.y + 1), IM_COL32(0, 0, 0, l.colour.a), l.text.c_str(),
                  l.text.c_str() + l.text.size());
    list->AddText(pos, to_imgui(l.colour), l.text.c_str(), l.text.c_str() + l.text.size());
  }
}

}  // namespace nbscope::render

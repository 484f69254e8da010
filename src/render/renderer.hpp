// nbscope render: the GL renderer. Collects everything drawn in a frame (DrawSink), then draws it
// layer by layer with one instanced draw call per primitive kind, and reports what it did.
#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "render/batches.hpp"
#include "render/camera.hpp"
#include "render/draw_sink.hpp"
#include "render/shader.hpp"

struct ImDrawList;

namespace nbscope::render {

// What one primitive kind of one layer drew in the last frame (for the Metrics window).
struct BatchStats {
  Layer layer = Layer::Cells;
  BatchKind kind = BatchKind::Rects;
  std::size_t items = 0;         // instances (vertices for triangles)
  std::size_t vertices = 0;      // vertices the GPU processed
  std::size_t buffer_bytes = 0;  // size of the GL buffer
};

// What the renderer did in the last frame.
struct RenderStats {
  int draw_calls = 0;
  std::vector<BatchStats> batches;  // only the non-empty ones
  std::size_t labels = 0;
  std::size_t labels_dropped = 0;  // past kMaxLabels
  double gpu_submit_ms = 0;        // upload + draw calls, CPU side
};

class Renderer final : public DrawSink {
 public:
  // Most text labels one frame draws; more would be unreadable and slow.
  static constexpr std::size_t kMaxLabels = 4000;

  // Loads the shaders from `shader_dir` (a GL 3.3 context must be current); Error when they are
  // missing or do not compile.
  explicit Renderer(const std::string& shader_dir);
  ~Renderer() override;
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Starts collecting a frame seen through `camera`.
  void begin_frame(const Camera& camera);
  // Clears the framebuffer to `background` and draws everything collected, back to front.
  void draw(Rgba background);
  // Adds the collected text labels to an ImGui draw list (call between NewFrame and Render).
  void emit_labels(ImDrawList* list) const;
  [[nodiscard]] const RenderStats& stats() const { return stats_; }
  [[nodiscard]] const Camera& camera() const { return camera_; }

  void circle(Layer layer, Vec2 centre, float radius, Rgba fill, Rgba outline, float outline_px = 1.0f,
              float min_radius_px = 0.0f) override;
  void polygon(Layer layer, std::span<const Vec2> points, Rgba fill, Rgba outline) override;
  void line(Layer layer, Vec2 from, Vec2 to, Rgba colour, float width_px = 1.0f) override;
  void arrow(Layer layer, Vec2 from, Vec2 to, Rgba colour, float width_px = 1.5f) override;
  void rect(Layer layer, Vec2 min, Vec2 max, Rgba fill) override;
  void text(Vec2 at, std::string_view text, Rgba colour) override;

 private:
  struct LayerItems {
    std::vector<RectInstance> rects;
    std::vector<TriangleVertex> triangles;
    std::vector<CircleInstance> circles;
    std::vector<LineInstance> lines;
  };
  struct Label {
    Vec2 at;
    std::string text;
    Rgba colour;
  };
  LayerItems& items(Layer layer) { return layers_[static_cast<int>(layer)]; }
  void set_uniforms(const Program& p) const;

  Camera camera_;
  std::array<LayerItems, kLayerCount> layers_;
  std::vector<Label> labels_;
  std::size_t labels_dropped_ = 0;
  Program circle_program_, line_program_, rect_program_, triangle_program_;
  GLuint quad_buffers_[3] = {0, 0, 0};
  std::vector<std::unique_ptr<GpuBatch>> gpu_;  // [layer * kBatchKindCount + kind]
  RenderStats stats_;
};

}  // namespace nbscope::render

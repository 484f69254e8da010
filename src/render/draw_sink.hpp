// nbscope render: the small drawing interface the overlays talk to. The GL renderer implements it
// with batches; a recorder (tests, a future trace exporter) can implement it to see what is drawn.
#pragma once
#include <Eigen/Core>
#include <span>
#include <string_view>

#include "render/palette.hpp"

namespace nbscope::render {

// World coordinates in metres, y up.
using Vec2 = Eigen::Vector2f;

// Draw order, back to front. Within a layer: rectangles, polygons, circles, lines.
enum class Layer : int { Cells = 0, Bodies = 1, Overlay = 2, Top = 3 };
inline constexpr int kLayerCount = 4;

class DrawSink {
 public:
  virtual ~DrawSink() = default;
  // A filled circle with an outline band `outline_px` wide; never drawn smaller than
  // `min_radius_px` on screen (markers that must stay visible when zoomed out).
  virtual void circle(Layer layer, Vec2 centre, float radius, Rgba fill, Rgba outline, float outline_px = 1.0f,
                      float min_radius_px = 0.0f) = 0;
  // A filled convex polygon (counter-clockwise) with a 1-pixel outline.
  virtual void polygon(Layer layer, std::span<const Vec2> points, Rgba fill, Rgba outline) = 0;
  // A segment `width_px` pixels wide.
  virtual void line(Layer layer, Vec2 from, Vec2 to, Rgba colour, float width_px = 1.0f) = 0;
  // A segment with a filled head at `to`, sized in pixels but never longer than half the segment.
  virtual void arrow(Layer layer, Vec2 from, Vec2 to, Rgba colour, float width_px = 1.5f) = 0;
  // An axis-aligned filled rectangle (cells).
  virtual void rect(Layer layer, Vec2 min, Vec2 max, Rgba fill) = 0;
  // A short text centred on a world point, drawn over the scene and under the panels.
  virtual void text(Vec2 at, std::string_view text, Rgba colour) = 0;
};

}  // namespace nbscope::render

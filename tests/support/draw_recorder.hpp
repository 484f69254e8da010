// nbscope tests: a DrawSink that records every call with its layer, geometry, colours and widths, and
// the queries the overlay, layer-view, verify and panel tests ask of what was drawn. One recorder for
// every test that draws without GL (render/draw_sink.hpp), so they all see the same calls.
#pragma once
#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "render/draw_sink.hpp"

namespace nbscope::render::testdraw {

struct Recorder final : DrawSink {
  struct Circle {
    Layer layer;
    Vec2 centre;
    float radius;
    Rgba fill, outline;
    float outline_px, min_px;
  };
  struct Polygon {
    Layer layer;
    std::vector<Vec2> points;
    Rgba fill, outline;
  };
  struct Line {  // a line or an arrow (its head at `to`)
    Layer layer;
    Vec2 from, to;
    Rgba colour;
    float width;
  };
  struct Rect {
    Layer layer;
    Vec2 min, max;
    Rgba colour;
  };
  struct Text {
    Vec2 at;
    std::string text;
    Rgba colour;
  };
  std::vector<Circle> circles;
  std::vector<Polygon> polygons;
  std::vector<Line> lines, arrows;
  std::vector<Rect> rects;
  std::vector<Text> texts;

  void circle(Layer layer, Vec2 c, float r, Rgba fill, Rgba outline, float outline_px, float min_px) override {
    circles.push_back({layer, c, r, fill, outline, outline_px, min_px});
  }
  void polygon(Layer layer, std::span<const Vec2> points, Rgba fill, Rgba outline) override {
    polygons.push_back({layer, std::vector<Vec2>(points.begin(), points.end()), fill, outline});
  }
  void line(Layer layer, Vec2 a, Vec2 b, Rgba c, float width) override { lines.push_back({layer, a, b, c, width}); }
  void arrow(Layer layer, Vec2 a, Vec2 b, Rgba c, float width) override { arrows.push_back({layer, a, b, c, width}); }
  void rect(Layer layer, Vec2 lo, Vec2 hi, Rgba c) override { rects.push_back({layer, lo, hi, c}); }
  void text(Vec2 at, std::string_view t, Rgba c) override { texts.push_back({at, std::string(t), c}); }

  // Items of `items` (lines, arrows, rects, texts) drawn in colour `c`.
  template <class Item>
  [[nodiscard]] static long count(const std::vector<Item>& items, Rgba c) {
    return std::count_if(items.begin(), items.end(), [&](const Item& i) { return i.colour == c; });
  }
  // Lines drawn in colour `c`.
  [[nodiscard]] std::vector<Line> lines_of(Rgba c) const {
    std::vector<Line> out;
    for (const Line& l : lines)
      if (l.colour == c) out.push_back(l);
    return out;
  }
  // The smallest on-screen radius asked of each circle of `layer`, in drawing order.
  [[nodiscard]] std::vector<float> min_px_of(Layer layer) const {
    std::vector<float> out;
    for (const Circle& c : circles)
      if (c.layer == layer) out.push_back(c.min_px);
    return out;
  }
  // Circles centred on `at` (within a hair).
  [[nodiscard]] std::vector<Circle> circles_at(Vec2 at) const {
    std::vector<Circle> out;
    for (const Circle& c : circles)
      if ((c.centre - at).norm() < 1e-4f) out.push_back(c);
    return out;
  }
  // Segments with both ends on the circle of radius r around `at` (a dashed outline's dashes).
  [[nodiscard]] int dashes_around(Vec2 at, float r) const {
    int n = 0;
    for (const Line& l : lines)
      if (std::abs((l.from - at).norm() - r) < 1e-4f && std::abs((l.to - at).norm() - r) < 1e-4f) ++n;
    return n;
  }
  // Every text drawn, in drawing order.
  [[nodiscard]] std::vector<std::string> text_strings() const {
    std::vector<std::string> out;
    for (const Text& t : texts) out.push_back(t.text);
    return out;
  }
  // Texts drawn that are exactly `t`.
  [[nodiscard]] long text_count(const std::string& t) const {
    return std::count_if(texts.begin(), texts.end(), [&](const Text& x) { return x.text == t; });
  }
  [[nodiscard]] bool has_text(const std::string& t) const { return text_count(t) > 0; }
  // True when a text drawn contains `part`.
  [[nodiscard]] bool has_text_containing(const std::string& part) const {
    return std::any_of(texts.begin(), texts.end(), [&](const Text& x) { return x.text.find(part) != std::string::npos; });
  }
};

}  // namespace nbscope::render::testdraw

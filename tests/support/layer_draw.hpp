// nbscope tests: what the layer view of a 3D frame draws, recorded without pixels (a DrawSink that
// keeps every circle, line, rect and text), and the small frames both layer-view test files draw:
// unit cells from the origin, four spheres one to a layer, a camera over a square.
#pragma once
#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/elements.hpp"
#include "core/grid.hpp"
#include "render/camera.hpp"
#include "render/draw_sink.hpp"
#include "render/overlays.hpp"  // ShapeDraw

namespace nbscope::render::testlayers {

struct Recorder final : DrawSink {
  struct Circle {
    Layer layer;
    Vec2 centre;
    float radius;
    Rgba fill, outline;
  };
  struct Line {
    Layer layer;
    Vec2 from, to;
    Rgba colour;
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
  std::vector<Line> lines, arrows;
  std::vector<Rect> rects;
  std::vector<Text> texts;
  void circle(Layer layer, Vec2 c, float r, Rgba fill, Rgba outline, float, float) override {
    circles.push_back({layer, c, r, fill, outline});
  }
  void polygon(Layer, std::span<const Vec2>, Rgba, Rgba) override {}
  void line(Layer layer, Vec2 a, Vec2 b, Rgba c, float) override { lines.push_back({layer, a, b, c}); }
  void arrow(Layer layer, Vec2 a, Vec2 b, Rgba c, float) override { arrows.push_back({layer, a, b, c}); }
  void rect(Layer layer, Vec2 lo, Vec2 hi, Rgba c) override { rects.push_back({layer, lo, hi, c}); }
  void text(Vec2 at, std::string_view t, Rgba c) override { texts.push_back({at, std::string(t), c}); }

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
  [[nodiscard]] bool has_text(const std::string& t) const {
    return std::any_of(texts.begin(), texts.end(), [&](const Text& x) { return x.text == t; });
  }
};

inline Vec2 at(const Elements& e, ElementId k) { return {static_cast<float>(e.x[k]), static_cast<float>(e.y[k])}; }

// Unit cells from the origin, nx x ny x nz of them.
inline GridOptions unit_cells(std::int64_t nx, std::int64_t ny, std::int64_t nz) {
  GridOptions o;
  o.cell_size = 1.0;
  o.origin = {0.0, 0.0, 0.0};
  o.cells = {{nx, ny, nz}};
  return o;
}

// Four spheres one above the other's layer, each at its own (x, y) in a 4 x 4 x 4 grid: element k
// in layer k (0: two below the layer shown, 1: below, 2: the layer shown, 3: above).
struct Column {
  Elements e;
  Grid grid;
  std::vector<ShapeDraw> shapes;
  Column() {
    e.dim = 3;
    e.push_back(0.5, 0.5, 0.5, 0.3);
    e.push_back(1.5, 1.5, 1.5, 0.3);
    e.push_back(2.5, 2.5, 2.5, 0.3);
    e.push_back(3.5, 3.5, 3.5, 0.3);
    grid = make_grid(e, unit_cells(4, 4, 4));
    for (ElementId k = 0; k < 4; ++k) {
      ShapeDraw s;
      s.centre = at(e, k);
      s.radius = 0.3f;
      s.element = k;
      s.spoke = false;
      shapes.push_back(s);
    }
  }
};

inline Camera camera_over(double lo, double hi) {
  Camera c;
  c.set_viewport(1280, 720);
  c.fit({{lo, lo}, {hi, hi}});
  return c;
}

}  // namespace nbscope::render::testlayers

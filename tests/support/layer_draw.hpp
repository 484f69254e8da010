// nbscope tests: what the layer view of a 3D frame draws, recorded without pixels (the shared
// recorder, support/draw_recorder.hpp), and the small frames both layer-view test files draw:
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
#include "support/draw_recorder.hpp"
#include "render/overlays.hpp"  // ShapeDraw

namespace nbscope::render::testlayers {

// The one recorder of the tests that draw without GL (support/draw_recorder.hpp).
using testdraw::Recorder;

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

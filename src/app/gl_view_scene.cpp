// The scene's part of GlView: the Box2D bodies as the renderer draws them, and the pairs the
// checks overlay colours (Box2D confirms, violations, broadphase only).
#include <algorithm>
#include <iterator>

#include "app/colour_by.hpp"
#include "app/gl_view.hpp"

namespace nbscope {

void GlView::build_shapes(const FrameLoop& loop) {
  loop.source().body_shapes(scratch_.body_shapes);
  scratch_.shapes.clear();
  scratch_.shape_points.clear();
  const bool flat = loop.source().elements().dim == 3;  // a 3D frame's spheres seen from above: plain circles
  const LayerSlice* slice = layer();
  for (const BodyShape& b : scratch_.body_shapes) {
    // A 3D frame's layers above and further below are hidden: not even handed to the renderer.
    if (slice != nullptr && b.element >= 0 && static_cast<std::size_t>(b.element) < slice->element_layer.size() && !slice->visible(b.element))
      continue;
    render::ShapeDraw d;
    d.motion = b.body_type == BodyType::Static      ? render::Motion::Static
               : b.body_type == BodyType::Kinematic ? render::Motion::Kinematic
                                                    : render::Motion::Dynamic;
    d.is_circle = b.form == ShapeForm::Circle;
    d.centre = render::Vec2(static_cast<float>(b.centre.x), static_cast<float>(b.centre.y));
    d.radius = static_cast<float>(b.radius);
    d.angle = static_cast<float>(b.angle);
    d.element = b.element;
    d.spoke = d.spoke && !flat;
    if (!d.is_circle) {
      d.first = static_cast<std::uint32_t>(scratch_.shape_points.size());
      d.count = static_cast<std::uint32_t>(b.vertex_count);
      for (int v = 0; v < b.vertex_count; ++v)
        scratch_.shape_points.emplace_back(static_cast<float>(b.vertices[static_cast<std::size_t>(v)].x),
                                   static_cast<float>(b.vertices[static_cast<std::size_t>(v)].y));
    }
    scratch_.shapes.push_back(d);
  }
}

void GlView::build_checks(const FrameLoop& loop) {
  scratch_.checks.confirmed.clear();
  scratch_.checks.broadphase_only.clear();
  scratch_.checks.violations.clear();
  const FrameReport& r = loop.result().report();
  if (!r.checked) return;
  const PairList& a = loop.result().selected().pairs;
  if (state_.overlays.checks) {
    const PairList& t = loop.result().touching;
    std::set_intersection(a.begin(), a.end(), t.begin(), t.end(), std::back_inserter(scratch_.checks.confirmed));
    for (const Violation& v : r.violations) scratch_.checks.violations.push_back(v.pair);
  }
  if (state_.overlays.broadphase) {
    const PairList& f = loop.result().box2d;
    std::set_difference(f.begin(), f.end(), a.begin(), a.end(), std::back_inserter(scratch_.checks.broadphase_only));
  }
}

void GlView::update_colours(const FrameLoop& loop) {
  if (!choices_.colour_by || colours_.generation == loop.change().generation) return;
  const ColourValues v = colour_values_of(*choices_.colour_by, loop.result(), loop.source().elements(), loop.source().ranks());
  colours_.key = render::colour_values(v.values, v.categorical, v.title, colours_.fills);
  colours_.generation = loop.change().generation;
}

}  // namespace nbscope

// nbscope physics (internal): a fixture's Box2D shape built from its spec, and its bounding circle.
// Included by the world's .cpp files only (it includes Box2D).
#pragma once
#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "physics/scene.hpp"
#include "physics/world.hpp"  // kPolygonCircleMargin

namespace nbscope {

inline b2Vec2 to_b2(Vec2 v) { return {static_cast<float>(v.x), static_cast<float>(v.y)}; }

// A fixture's Box2D shape built from its spec, with the centre (body frame) and radius of its
// bounding circle, the element the detectors see: a polygon's includes Box2D's skin.
struct FixtureShape {
  b2CircleShape circle;
  b2PolygonShape polygon;
  const b2Shape* shape = nullptr;
  b2Vec2 centre{0, 0};
  double radius = 0;

  explicit FixtureShape(const ShapeSpec& s) {
    if (s.kind == ShapeKind::Circle) {
      circle.m_p = to_b2(s.offset);
      circle.m_radius = static_cast<float>(s.radius);
      shape = &circle;
      centre = circle.m_p;
      radius = circle.m_radius;
      return;
    }
    if (s.kind == ShapeKind::Box) {
      polygon.SetAsBox(static_cast<float>(s.half_extents.x), static_cast<float>(s.half_extents.y), to_b2(s.offset),
                       static_cast<float>(s.angle));
    } else {
      b2Vec2 points[b2_maxPolygonVertices];
      for (std::size_t i = 0; i < s.vertices.size(); ++i) points[i] = to_b2(s.vertices[i]);
      polygon.Set(points, static_cast<int32>(s.vertices.size()));
      if (polygon.m_count != static_cast<int32>(s.vertices.size()))
        throw Error(s.where + "Box2D keeps only " + std::to_string(polygon.m_count) + " of the " +
                    std::to_string(s.vertices.size()) + " polygon vertices (points too close or nearly collinear)");
    }
    shape = &polygon;
    centre = polygon.m_centroid;
    double far = 0;
    for (int32 i = 0; i < polygon.m_count; ++i) {
      const double dx = static_cast<double>(polygon.m_vertices[i].x) - centre.x;
      const double dy = static_cast<double>(polygon.m_vertices[i].y) - centre.y;
      far = std::max(far, std::sqrt(dx * dx + dy * dy));
    }
    radius = far + static_cast<double>(polygon.m_radius) + kPolygonCircleMargin;
  }
  FixtureShape(const FixtureShape&) = delete;
  FixtureShape& operator=(const FixtureShape&) = delete;
};

// What Box2D's float would make of `body` that breaks it, in words ("" when nothing): a circle
// radius that is 0 or a denormal in float; for a dynamic body, a fixture of positive density whose
// float mass is 0 or a denormal (its inverse infinite: the first step turns the body NaN), or a
// rotational inertia about the centre of mass that rounds to 0 or below (b2Body::ResetMassData
// asserts, an abort). Mass data are Box2D's own (b2Shape::ComputeMass), summed in the order and
// float arithmetic of ResetMassData after each fixture is created.
std::string box2d_float_trouble(const BodySpec& body);

}  // namespace nbscope

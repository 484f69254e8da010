// nbscope physics: what the rest of nbscope may know about Box2D's bodies, in plain structs (no
// Box2D types), so that render, ui and the frame loop's header never include Box2D.
#pragma once
#include <array>
#include <cstdint>

#include "core/elements.hpp"
#include "physics/scene.hpp"

namespace nbscope {

// Where an element (a fixture's bounding circle) comes from.
struct ElementSource {
  std::int32_t body = -1;     // body index: the scene's bodies in file order, then generated ones, then emitted ones
  std::int32_t fixture = -1;  // fixture index within that body (as listed in its "fixtures")
};

// How a fixture is drawn: boxes are polygons here.
enum class ShapeForm : std::uint8_t { Circle, Polygon };

// One fixture at the current transforms, in world coordinates.
struct BodyShape {
  ShapeForm form = ShapeForm::Circle;
  BodyType body_type = BodyType::Dynamic;
  ElementId element = -1;           // the element (bounding circle) of this fixture
  std::int32_t body = -1;           // body index as in ElementSource
  Vec2 centre;                      // circle centre; polygon centroid
  double radius = 0;                // circle radius; polygon skin radius (b2_polygonRadius)
  double angle = 0;                 // the body's angle, radians
  int vertex_count = 0;             // polygon only
  std::array<Vec2, 8> vertices{};   // polygon only, world coordinates, counter-clockwise
};

}  // namespace nbscope

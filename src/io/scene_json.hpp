// nbscope io: scene files (docs/formats.md "Scene JSON") read into a Scene (physics/scene.hpp), every field
// validated.
//
// The format, with every default (lengths in metres, angles in radians, times in seconds):
//   name "" (the file's stem), gravity [0,-10], time_step 1/60 (one frame), sub_steps 1 (Box2D steps
//   per frame, each time_step/sub_steps), velocity_iterations 8, position_iterations 3,
//   continuous true (Box2D's time of impact against static bodies; its TOI solver costs
//   contacts x events per step, so large piles turn it off),
//   cell_size null, origin null (null: derived from the elements each frame), cells null ([nx, ny]
//   pins the grid's extent, e.g. the book's 10x10), bodies [], generators [].
// A body: type "dynamic" | "static" | "kinematic"; position [0,0]; angle 0; velocity [0,0];
//   angular_velocity 0; and either one shape inline or "fixtures": [shape, ...] (a compound body).
// A shape: shape "circle" (radius; offset [0,0] in the body), "box" (half_extents; offset [0,0];
//   angle 0 in the body) or "polygon" (vertices: 3 to 8 body-local points, convex,
//   counter-clockwise); density 1, friction 0.6, restitution 0.
// A generator: kind "grid" | "random_box" | "pile" | "emitter" and "body", a body without a position
//   (default: a dynamic circle of radius 0.5; a template circle's radius defaults to 0.5); see
//   GeneratorSpec for each kind's fields.
// Unknown fields are errors (a typo must not silently become a default). `//` comments are allowed.
#pragma once
#include <string>

#include "core/error.hpp"
#include "physics/scene.hpp"

namespace nbscope {

// A scene that reads, but whose world Box2D cannot be given (a circle radius its float cannot
// hold): the window opens paused on it, as on a world that stops at load; elsewhere an Error like any other.
class WorldRefused : public Error {
 public:
  using Error::Error;
};

// Reads and validates a scene file. Throws Error("<path>:<line>: <field>: <what>") on anything
// wrong: unreadable file, JSON syntax, a missing or unknown field, a wrong type, a value out of range
// (NaN/inf, negative sizes, a concave, clockwise or degenerate polygon, too many bodies);
// WorldRefused for a circle radius Box2D's float cannot hold.
Scene read_scene_json(const std::string& path);
// Same from memory; `where` stands for the file name in messages and in Scene::path.
Scene parse_scene_json(const std::string& text, const std::string& where);

}  // namespace nbscope

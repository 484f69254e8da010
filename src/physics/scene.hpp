// nbscope physics: the scene description physics builds a world from: bodies, their shapes,
// generators of many bodies, the simulation's settings and the pinned grid. Plain data with no
// Box2D, so io (io/scene_json.hpp reads it from files, every field validated there), the frame loop
// and the panels include it freely.
//
// Index: limits | Vec2, BodyType, ShapeKind | ShapeSpec, BodySpec | GeneratorSpec | Scene.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/grid.hpp"

namespace nbscope {

// Most bodies one scene may create (explicit bodies plus everything its generators make).
inline constexpr std::int64_t kMaxSceneBodies = 1'000'000;
// Box2D works in float: positions beyond this many metres lose centimetres.
inline constexpr double kMaxSceneCoordinate = 100'000;
// Largest shape size (radius, half extent, vertex distance) a scene may ask for, in metres.
inline constexpr double kMaxShapeSize = 10'000;
// Most Box2D contacts a frame may create (the scene's "max_contacts", the --max-contacts flag):
// physics/world_limits.hpp estimates them before Box2D steps. Measured at ~1.7 kB each (peak
// memory over contacts, circles in a box), 1M contacts take ~1.7 GB.
inline constexpr std::int64_t kDefaultMaxContacts = 1'000'000;
// Largest max_contacts a scene or the flag may set (hundreds of GB of contacts: beyond any machine).
inline constexpr std::int64_t kMaxMaxContacts = 1'000'000'000;
// A body farther than this from the origin (either coordinate, metres) has left any sensible
// world: Box2D's float positions there are 0.0625 m apart, a tenth of a typical body.
inline constexpr double kMaxWorldCoordinate = 1'000'000;
// Smallest box half extent / polygon edge: Box2D welds polygon points closer than its linear slop.
inline constexpr double kMinPolygonFeature = 0.005;

// A point or a vector in the scene's plane (metres, or metres per second).
struct Vec2 {
  double x = 0;
  double y = 0;
};

enum class BodyType : std::uint8_t { Static, Kinematic, Dynamic };
enum class ShapeKind : std::uint8_t { Circle, Box, Polygon };

// "static", "kinematic", "dynamic".
inline const char* body_type_name(BodyType type) {
  switch (type) {
    case BodyType::Static: return "static";
    case BodyType::Kinematic: return "kinematic";
    case BodyType::Dynamic: return "dynamic";
  }
  return "?";
}

// "circle", "box", "polygon".
inline const char* shape_kind_name(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::Circle: return "circle";
    case ShapeKind::Box: return "box";
    case ShapeKind::Polygon: return "polygon";
  }
  return "?";
}

// One fixture of a body, in the body's coordinates.
struct ShapeSpec {
  ShapeKind kind = ShapeKind::Circle;
  double radius = 0.5;               // circle
  Vec2 half_extents{0.5, 0.5};       // box
  std::vector<Vec2> vertices;        // polygon: convex, counter-clockwise, 3..8 points
  Vec2 offset;                       // circle / box centre in the body
  double angle = 0;                  // box rotation in the body
  double density = 1;
  double friction = 0.6;
  double restitution = 0;
  std::string where;                 // "file:line: bodies[3]: " (or ...fixtures[1]), for later messages
};

// One rigid body with one or more fixtures.
struct BodySpec {
  BodyType type = BodyType::Dynamic;
  Vec2 position;
  double angle = 0;
  Vec2 velocity;
  double angular_velocity = 0;
  std::vector<ShapeSpec> fixtures;   // at least one
  std::string where;                 // "file:line: bodies[3]: " or "...: generators[0].body: "
};

enum class GeneratorKind : std::uint8_t { Grid, RandomBox, Pile, Emitter };
// "grid", "random_box", "pile", "emitter".
inline const char* generator_kind_name(GeneratorKind kind) {
  switch (kind) {
    case GeneratorKind::Grid: return "grid";
    case GeneratorKind::RandomBox: return "random_box";
    case GeneratorKind::Pile: return "pile";
    case GeneratorKind::Emitter: return "emitter";
  }
  return "?";
}

// Makes many bodies from one template `body` (whose position the generator sets).
//   grid:       columns x rows bodies, the first centred at origin, spaced by spacing [sx, sy].
//   random_box: count bodies, centres uniform in [min, max]; radius [a, b] draws circle radii,
//               scale [a, b] multiplies any shape's size, speed [a, b] gives a velocity of random
//               direction, random_angle rotates each body; reproducible from seed.
//   pile:       count bodies stacked in rows of `columns`, alternate rows shifted half a spacing,
//               bottom row centred at position; spacing defaults to the template's width + 5%;
//               jitter (fraction of spacing, default 0.05) from seed.
//   emitter:    pours count bodies over time: `rate` per second from `start`, spread along a
//               segment of `width` centred at position, velocity of the template turned by a
//               random angle within +-spread/2; reproducible from seed.
struct GeneratorSpec {
  GeneratorKind kind = GeneratorKind::Grid;
  BodySpec body;                     // template
  std::int64_t count = 0;            // bodies made (grid: columns * rows)
  std::uint64_t seed = 1;
  std::int64_t columns = 1, rows = 1;                 // grid; pile uses columns
  Vec2 origin;                                        // grid
  Vec2 spacing{1, 1};                                 // grid; pile uses spacing.x (0: default)
  Vec2 min, max;                                      // random_box
  std::optional<std::array<double, 2>> radius_range;  // random_box, circle templates
  std::array<double, 2> scale_range{1, 1};            // random_box
  std::array<double, 2> speed_range{0, 0};            // random_box
  bool random_angle = false;                          // random_box
  Vec2 position;                                      // pile, emitter
  double jitter = 0.05;                               // pile
  double rate = 10;                                   // emitter, bodies per second
  double start = 0;                                   // emitter, seconds
  double width = 0;                                   // emitter
  double spread = 0;                                  // emitter, radians
  std::string where;                                  // "file:line: generators[2]: "
};

// A whole scene: what physics builds a world from (read from a file, or built in memory).
struct Scene {
  std::string path;                  // as given; "" for scenes built in memory
  std::string name;
  Vec2 gravity{0, -10};
  double time_step = 1.0 / 60.0;     // seconds per frame
  int sub_steps = 1;
  int velocity_iterations = 8;
  int position_iterations = 3;
  bool continuous = true;
  std::int64_t max_contacts = kDefaultMaxContacts;  // Box2D contacts a frame may create
  GridOptions grid;                  // cell_size, origin, cells keys (2D: origin z 0, cells nz 1)
  std::vector<BodySpec> bodies;
  std::vector<GeneratorSpec> generators;
  std::string cell_size_where;       // "file:line: cell_size: " when grid.cell_size is set, for later checks

  // Bodies the scene creates in all: explicit ones plus every generator's count.
  [[nodiscard]] std::int64_t total_bodies() const {
    std::int64_t n = static_cast<std::int64_t>(bodies.size());
    for (const GeneratorSpec& g : generators) n += g.count;
    return n;
  }
};

}  // namespace nbscope

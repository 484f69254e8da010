// Scene files: every field read through ObjectReader (io/scene_json_fields.hpp), which knows the
// object's path and line and refuses fields nobody asked for; bodies in io/scene_json_bodies.cpp.
//
// Index: generators | the scene.
#include "io/scene_json.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "core/error.hpp"
#include "io/excerpt.hpp"
#include "io/input_file.hpp"
#include "io/scene_json_bodies.hpp"
#include "io/scene_json_fields.hpp"
#include "io/scene_json_source.hpp"

namespace nbscope {

namespace {

using namespace scene_fields;

// Longest scene name (the "name" key).
constexpr std::size_t kMaxSceneNameBytes = 200;

// ---- generators ----------------------------------------------------------------------------

GeneratorSpec read_generator(const LocatedJson& doc, const json& v, const Path& path) {
  ObjectReader r(doc, v, path, "a generator");
  GeneratorSpec g;
  g.where = doc.locate(path);
  const std::string kind = read_string(doc, r.need("kind", "grid, random_box, pile or emitter"), r.at("kind"));
  if (r.has("body")) {
    g.body = read_body(doc, r.get("body"), r.at("body"), true);
  } else {
    g.body.fixtures.push_back(ShapeSpec{});
    g.body.where = doc.locate(r.at("body"));
    g.body.fixtures.back().where = g.body.where;
  }
  g.seed = static_cast<std::uint64_t>(r.integer("seed", 1, 0, std::int64_t{1} << 53));
  const std::int64_t max_count = kMaxSceneBodies * 100;  // past the scene limit, to report it clearly below
  if (kind == "grid") {
    g.kind = GeneratorKind::Grid;
    g.columns = read_integer(doc, r.need("columns"), r.at("columns"), 1, max_count);
    g.rows = read_integer(doc, r.need("rows"), r.at("rows"), 1, max_count);
    g.origin = read_vec2(doc, r.need("origin", "centre of the first body"), r.at("origin"), kMaxSceneCoordinate);
    g.spacing = r.vec2("spacing", {1, 1}, kMaxSceneCoordinate);
    if (g.columns > max_count / g.rows) doc.fail(r.at("rows"), "columns x rows is far too many bodies");
    g.count = g.columns * g.rows;
    // Bodies stacked on one point: Box2D pairs each with all the others, O(N^2) time and memory.
    if ((g.columns > 1 && g.spacing.x == 0) || (g.rows > 1 && g.spacing.y == 0))
      doc.fail(r.at("spacing"), "0 along an axis with more than one body puts bodies on top of each other");
    const Vec2 end{g.origin.x + g.spacing.x * static_cast<double>(g.columns - 1), g.origin.y + g.spacing.y * static_cast<double>(g.rows - 1)};
    if (std::abs(end.x) > kMaxSceneCoordinate || std::abs(end.y) > kMaxSceneCoordinate)
      doc.fail(r.at("spacing"), "the grid would reach beyond +-" + fmt(kMaxSceneCoordinate) + " m");
  } else if (kind == "random_box") {
    g.kind = GeneratorKind::RandomBox;
    g.count = read_integer(doc, r.need("count"), r.at("count"), 0, max_count);
    g.min = read_vec2(doc, r.need("min", "lower corner of the box"), r.at("min"), kMaxSceneCoordinate);
    g.max = read_vec2(doc, r.need("max", "upper corner of the box"), r.at("max"), kMaxSceneCoordinate);
    if (g.min.x > g.max.x || g.min.y > g.max.y) doc.fail(r.at("max"), "must not be below min on either axis");
    if (g.count > 1 && g.min.x == g.max.x && g.min.y == g.max.y)
      doc.fail(r.at("max"), "equals min: all " + std::to_string(g.count) + " bodies would be at one point");
    if (r.has("radius")) {
      if (g.body.fixtures.size() != 1 || g.body.fixtures[0].kind != ShapeKind::Circle)
        doc.fail(r.at("radius"), "radius applies to circle templates; use scale for other shapes");
      g.radius_range = read_range(doc, r.get("radius"), r.at("radius"), 0, kMaxShapeSize, true);
      check_radius_in_float(doc, LocatedJson::element(r.at("radius"), 0), (*g.radius_range)[0],
                            g.body.type == BodyType::Dynamic ? g.body.fixtures[0].density : 0);
    }
    if (r.has("scale")) g.scale_range = read_range(doc, r.get("scale"), r.at("scale"), 0, 1e4, true);
    if (r.has("speed")) g.speed_range = read_range(doc, r.get("speed"), r.at("speed"), 0, 1e5, false);
    if (r.has("random_angle")) g.random_angle = read_bool(doc, r.get("random_angle"), r.at("random_angle"));
    if (smallest_feature(g.body) * g.scale_range[0] < kMinPolygonFeature)
      doc.fail(r.at("scale"), "scales a box or polygon below " + fmt(kMinPolygonFeature) + " m");
    const double largest_radius = g.radius_range ? (*g.radius_range)[1] : 0.0;
    if (std::max(largest_feature(g.body), largest_radius) * g.scale_range[1] > kMaxShapeSize)
      doc.fail(r.at("scale"), "scales a shape beyond " + fmt(kMaxShapeSize) + " m");
  } else if (kind == "pile") {
    g.kind = GeneratorKind::Pile;
    g.count = read_integer(doc, r.need("count"), r.at("count"), 0, max_count);
    g.columns = read_integer(doc, r.need("columns", "bodies per row"), r.at("columns"), 1, max_count);
    g.position = read_vec2(doc, r.need("position", "centre of the bottom row"), r.at("position"), kMaxSceneCoordinate);
    if (r.has("spacing")) g.spacing.x = read_positive(doc, r.get("spacing"), r.at("spacing"), kMaxShapeSize);
    else g.spacing.x = 0;
    g.jitter = r.number_in("jitter", 0.05, 0, 0.5, "from 0 to 0.5");
  } else if (kind == "emitter") {
    g.kind = GeneratorKind::Emitter;
    g.count = read_integer(doc, r.need("count"), r.at("count"), 0, max_count);
    g.position = read_vec2(doc, r.need("position", "where bodies appear"), r.at("position"), kMaxSceneCoordinate);
    g.rate = read_positive(doc, r.need("rate", "bodies per second"), r.at("rate"), 1e6);
    g.start = r.number_in("start", 0, 0, 1e6, "from 0 to 1e6 seconds");
    g.width = r.number_in("width", 0, 0, kMaxSceneCoordinate, "from 0 to 1e5");
    g.spread = r.number_in("spread", 0, 0, 2 * std::numbers::pi, "from 0 to 2 pi");
  } else {
    doc.fail(r.at("kind"), "must be \"grid\", \"random_box\", \"pile\" or \"emitter\", got " + show(r.get("kind")));
  }
  r.finish();
  return g;
}

// ---- the scene -----------------------------------------------------------------------------

Scene read_scene(const LocatedJson& doc) {
  ObjectReader r(doc, doc.root(), "", "a scene");
  Scene s;
  s.path = doc.where();
  s.name = std::filesystem::path(doc.where()).stem().string();
  if (r.has("name")) {
    s.name = read_string(doc, r.get("name"), r.at("name"));
    // The name goes into window titles, reports and file names: a line of text, not a document.
    if (s.name.size() > kMaxSceneNameBytes)
      doc.fail(r.at("name"), "a name of " + std::to_string(s.name.size()) + " bytes \"" + excerpt(s.name) + "\"; at most " +
                                 std::to_string(kMaxSceneNameBytes));
  }
  r.allow({"description"});
  s.gravity = r.vec2("gravity", s.gravity, 1e4);
  s.time_step = r.number_in("time_step", s.time_step, 1e-6, 1, "from 1e-6 to 1 second");
  if (s.time_step <= 0) doc.fail(r.at("time_step"), "must be positive");
  s.sub_steps = static_cast<int>(r.integer("sub_steps", 1, 1, 100));
  s.velocity_iterations = static_cast<int>(r.integer("velocity_iterations", 8, 1, 1000));
  s.position_iterations = static_cast<int>(r.integer("position_iterations", 3, 1, 1000));
  if (r.has("continuous")) s.continuous = read_bool(doc, r.get("continuous"), r.at("continuous"));
  s.max_contacts = r.integer("max_contacts", kDefaultMaxContacts, 0, kMaxMaxContacts);
  if (r.has_value("cell_size")) {
    s.grid.cell_size = read_positive(doc, r.get("cell_size"), r.at("cell_size"), 1e6);
    s.cell_size_where = doc.locate(r.at("cell_size"));
  }
  if (r.has_value("origin")) {
    const Vec2 origin = read_vec2(doc, r.get("origin"), r.at("origin"), kMaxSceneCoordinate);
    s.grid.origin = std::array<double, 3>{origin.x, origin.y, 0};
  }
  if (r.has_value("cells")) {
    const json& c = r.get("cells");
    if (!c.is_array() || c.size() != 2) doc.fail(r.at("cells"), "must be [nx, ny], got " + show(c));
    s.grid.cells = std::array<std::int64_t, 3>{read_integer(doc, c[0], LocatedJson::element(r.at("cells"), 0), 1, 1 << 24),
                                               read_integer(doc, c[1], LocatedJson::element(r.at("cells"), 1), 1, 1 << 24), 1};
  }

  std::int64_t total = 0;
  auto count = [&](std::int64_t n, const Path& where) {
    total += n;
    if (total > kMaxSceneBodies)
      doc.fail(where, std::to_string(total) + " bodies requested in all; a scene holds at most " + std::to_string(kMaxSceneBodies));
  };
  if (r.has("bodies")) {
    const json& b = r.get("bodies");
    if (!b.is_array()) doc.fail(r.at("bodies"), "must be an array of bodies, got " + type_of(b));
    if (static_cast<std::int64_t>(b.size()) > kMaxSceneBodies) count(static_cast<std::int64_t>(b.size()), r.at("bodies"));
    for (std::size_t i = 0; i < b.size(); ++i) {
      s.bodies.push_back(read_body(doc, b[i], LocatedJson::element(r.at("bodies"), i), false));
      count(1, LocatedJson::element(r.at("bodies"), i));
    }
  }
  if (r.has("generators")) {
    const json& g = r.get("generators");
    if (!g.is_array()) doc.fail(r.at("generators"), "must be an array of generators, got " + type_of(g));
    for (std::size_t i = 0; i < g.size(); ++i) {
      s.generators.push_back(read_generator(doc, g[i], LocatedJson::element(r.at("generators"), i)));
      const GeneratorSpec& gen = s.generators.back();
      const Path gp = LocatedJson::element(r.at("generators"), i);
      count(gen.count, LocatedJson::member(gp, gen.kind == GeneratorKind::Grid ? "rows" : "count"));
    }
  }
  r.finish();
  return s;
}

}  // namespace

Scene parse_scene_json(const std::string& text, const std::string& where) {
  const LocatedJson doc(text, where);
  return read_scene(doc);
}

Scene read_scene_json(const std::string& path) {
  return parse_scene_json(read_input_file(path, "scene file", kMaxSceneBytes), path);
}

}  // namespace nbscope

// Scene files: every field read through ObjectReader, which knows the object's path and line and
// refuses fields nobody asked for.
//
// Index: value readers (numbers, vectors, integers) | ObjectReader | shapes and polygons | bodies |
// generators | the scene.
#include "io/scene_json.hpp"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "io/excerpt.hpp"
#include "io/input_file.hpp"
#include "io/scene_json_source.hpp"

namespace nbscope {

namespace {

using nlohmann::json;
using Path = std::string;

// Longest scene name (the "name" key).
constexpr std::size_t kMaxSceneNameBytes = 200;

// Appends `v` as JSON to `out`, stopping once `out` is longer than `limit`: a 1e6-element array or
// a 50 MB string costs what is shown, not its whole dump.
void dump_short(const json& v, std::string& out, std::size_t limit) {
  if (out.size() > limit) return;
  if (v.is_array() || v.is_object()) {
    out += v.is_array() ? '[' : '{';
    bool first = true;
    for (auto it = v.begin(); it != v.end() && out.size() <= limit; ++it, first = false) {
      if (!first) out += ',';
      if (v.is_object()) {
        dump_short(json(it.key()), out, limit);
        out += ':';
      }
      dump_short(*it, out, limit);
    }
    out += v.is_array() ? ']' : '}';
  } else if (v.is_string()) {
    // A cut may split a UTF-8 character: replace it rather than throw.
    out += json(v.get_ref<const std::string&>().substr(0, limit)).dump(-1, ' ', false, json::error_handler_t::replace);
  } else {
    out += v.dump();
  }
}

// `v` as a short excerpt for a message.
std::string show(const json& v) {
  std::string s;
  dump_short(v, s, kExcerptBytes);
  return s.size() > kExcerptBytes ? excerpt(s) : s;
}

std::string type_of(const json& v) {
  if (v.is_boolean()) return "a boolean";
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_array()) return "an array";
  if (v.is_object()) return "an object";
  if (v.is_null()) return "null";
  return "something else";
}

// What a value of the wrong type is, for "must be ..., got X": its type and an excerpt, or "null"
// alone (it was "got null null").
std::string described(const json& v) { return v.is_null() ? "null" : type_of(v) + " " + show(v); }

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

// ---- value readers -------------------------------------------------------------------------

double read_number(const LocatedJson& doc, const json& v, const Path& path) {
  if (!v.is_number()) doc.fail(path, "must be a number, got " + described(v));
  const double d = v.get<double>();
  if (!std::isfinite(d)) doc.fail(path, "must be a finite number");
  return d;
}

// A number in [lo, hi]; `range` words the allowed values for the message.
double read_number_in(const LocatedJson& doc, const json& v, const Path& path, double lo, double hi, const char* range) {
  const double d = read_number(doc, v, path);
  if (!(d >= lo && d <= hi)) doc.fail(path, std::string("must be ") + range + ", got " + fmt(d));
  return d;
}

double read_positive(const LocatedJson& doc, const json& v, const Path& path, double hi) {
  const double d = read_number(doc, v, path);
  if (!(d > 0)) doc.fail(path, "must be positive, got " + fmt(d));
  if (d > hi) doc.fail(path, "must be at most " + fmt(hi) + ", got " + fmt(d));
  return d;
}

std::int64_t read_integer(const LocatedJson& doc, const json& v, const Path& path, std::int64_t lo, std::int64_t hi) {
  if (!v.is_number()) doc.fail(path, "must be a whole number, got " + described(v));
  const double d = v.get<double>();
  if (!std::isfinite(d) || d != std::floor(d)) doc.fail(path, "must be a whole number, got " + show(v));
  if (d < static_cast<double>(lo) || d > static_cast<double>(hi))
    doc.fail(path, "must be from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got " + show(v));
  return v.is_number_integer() ? v.get<std::int64_t>() : static_cast<std::int64_t>(d);
}

bool read_bool(const LocatedJson& doc, const json& v, const Path& path) {
  if (!v.is_boolean()) doc.fail(path, "must be true or false, got " + described(v));
  return v.get<bool>();
}

std::string read_string(const LocatedJson& doc, const json& v, const Path& path) {
  if (!v.is_string()) doc.fail(path, "must be a string, got " + described(v));
  return v.get<std::string>();
}

std::array<double, 2> read_pair(const LocatedJson& doc, const json& v, const Path& path) {
  if (!v.is_array() || v.size() != 2)
    doc.fail(path, "must be an array of two numbers [a, b], got " + described(v));
  return {read_number(doc, v[0], LocatedJson::element(path, 0)), read_number(doc, v[1], LocatedJson::element(path, 1))};
}

Vec2 read_vec2(const LocatedJson& doc, const json& v, const Path& path, double limit) {
  const auto p = read_pair(doc, v, path);
  for (int a = 0; a < 2; ++a)
    if (std::abs(p[a]) > limit)
      doc.fail(LocatedJson::element(path, a), "must be within +-" + fmt(limit) + ", got " + fmt(p[a]));
  return {p[0], p[1]};
}

// [a, b] with lo <= a <= b <= hi.
std::array<double, 2> read_range(const LocatedJson& doc, const json& v, const Path& path, double lo, double hi, bool positive) {
  const auto r = read_pair(doc, v, path);
  for (int a = 0; a < 2; ++a) {
    const Path p = LocatedJson::element(path, a);
    if (positive && !(r[a] > 0)) doc.fail(p, "must be positive, got " + fmt(r[a]));
    if (r[a] < lo || r[a] > hi) doc.fail(p, "must be from " + fmt(lo) + " to " + fmt(hi) + ", got " + fmt(r[a]));
  }
  if (r[0] > r[1]) doc.fail(path, "must be [low, high] with low <= high, got " + show(v));
  return r;
}

// ---- ObjectReader --------------------------------------------------------------------------

// One JSON object of the scene: hands out its fields by name and, in finish(), refuses the rest.
class ObjectReader {
 public:
  ObjectReader(const LocatedJson& doc, const json& object, Path path, std::string what)
      : doc_(doc), object_(object), path_(std::move(path)) {
    if (!object_.is_object()) doc_.fail(path_, "must be " + what + " (a JSON object), got " + described(object));
  }
  [[nodiscard]] const LocatedJson& doc() const { return doc_; }
  [[nodiscard]] const Path& path() const { return path_; }
  // Path of the field `key` of this object.
  [[nodiscard]] Path at(const std::string& key) const { return LocatedJson::member(path_, key); }
  // True when the field is present (and marks it read).
  bool has(const std::string& key) {
    known_.insert(key);
    return object_.contains(key);
  }
  // True when the field is present and not null.
  bool has_value(const std::string& key) { return has(key) && !object_.at(key).is_null(); }
  // The field; fails with "missing" (at this object's line) when absent. `why` completes the message.
  const json& need(const std::string& key, const std::string& why = "") {
    if (!has(key)) doc_.fail(at(key), "missing" + (why.empty() ? "" : " (" + why + ")"));
    return object_.at(key);
  }
  const json& get(const std::string& key) { return need(key); }
  // Marks keys as belonging here without reading them (read elsewhere or ignored).
  void allow(std::initializer_list<const char*> keys) {
    for (const char* k : keys) known_.insert(k);
  }
  // Fails on the first field nobody asked for.
  void finish() const {
    for (auto it = object_.begin(); it != object_.end(); ++it) {
      if (known_.count(it.key())) continue;
      std::string list;
      for (const std::string& k : known_) list += (list.empty() ? "" : ", ") + k;
      doc_.fail(at(it.key()), "unknown field (known here: " + list + ")");
    }
  }

  double number(const std::string& key, double fallback) { return has(key) ? read_number(doc_, object_.at(key), at(key)) : fallback; }
  double number_in(const std::string& key, double fallback, double lo, double hi, const char* range) {
    return has(key) ? read_number_in(doc_, object_.at(key), at(key), lo, hi, range) : fallback;
  }
  Vec2 vec2(const std::string& key, Vec2 fallback, double limit) {
    return has(key) ? read_vec2(doc_, object_.at(key), at(key), limit) : fallback;
  }
  std::int64_t integer(const std::string& key, std::int64_t fallback, std::int64_t lo, std::int64_t hi) {
    return has(key) ? read_integer(doc_, object_.at(key), at(key), lo, hi) : fallback;
  }

 private:
  const LocatedJson& doc_;
  const json& object_;
  Path path_;
  std::set<std::string> known_;
};

// ---- shapes and polygons -------------------------------------------------------------------

double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
Vec2 sub(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
double length(Vec2 a) { return std::hypot(a.x, a.y); }

// Convex, counter-clockwise, no two points closer than Box2D's weld distance, no three collinear,
// winding once: what b2PolygonShape::Set keeps as given (it would silently take the convex hull).
void check_polygon(const LocatedJson& doc, const std::vector<Vec2>& v, const Path& path) {
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double edge = length(sub(v[(i + 1) % n], v[i]));
    if (edge < kMinPolygonFeature)
      doc.fail(LocatedJson::element(path, (i + 1) % n),
               "degenerate polygon: vertices " + std::to_string(i) + " and " + std::to_string((i + 1) % n) + " are " + fmt(edge) +
                   " apart (at least " + fmt(kMinPolygonFeature) + ")");
  }
  double turning = 0, area2 = 0;
  int left = 0, right = 0;
  std::size_t first_right = 0, first_left = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 e1 = sub(v[(i + 1) % n], v[i]);
    const Vec2 e2 = sub(v[(i + 2) % n], v[(i + 1) % n]);
    const std::size_t corner = (i + 1) % n;
    const double c = cross(e1, e2);
    if (std::abs(c) <= 1e-6 * length(e1) * length(e2))
      doc.fail(LocatedJson::element(path, corner),
               "degenerate polygon: vertices " + std::to_string(i) + ", " + std::to_string(corner) + ", " +
                   std::to_string((i + 2) % n) + " are collinear");
    if (c > 0) {
      if (left++ == 0) first_left = corner;
    } else {
      if (right++ == 0) first_right = corner;
    }
    turning += std::atan2(c, e1.x * e2.x + e1.y * e2.y);
    area2 += cross(v[i], v[(i + 1) % n]);
  }
  if (left > 0 && right > 0) {
    const std::size_t at = left >= right ? first_right : first_left;
    doc.fail(LocatedJson::element(path, at), "polygon is not convex (concave at vertex " + std::to_string(at) + ")");
  }
  if (right > 0) doc.fail(path, "polygon vertices are clockwise; list them counter-clockwise");
  if (std::abs(turning - 2 * std::numbers::pi) > 1e-6)
    doc.fail(path, "polygon winds around " + fmt(turning / (2 * std::numbers::pi)) + " times (it crosses itself)");
  if (area2 / 2 < kMinPolygonFeature * kMinPolygonFeature) doc.fail(path, "degenerate polygon: area " + fmt(area2 / 2));
}

// A circle radius (at `path`) Box2D's float holds: not 0 or a denormal there, and with a positive
// `density` (a dynamic body's; Box2D gives others no mass) a mass (Box2D's density * pi * r * r, in float) that is not either: a denormal mass
// has an infinite inverse, and Box2D's first step turns the body NaN. The rest of what float
// makes of a body (several fixtures, inertia) is physics' check when the world is built.
void check_radius_in_float(const LocatedJson& doc, const Path& path, double radius, double density) {
  const auto short_number = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return std::string(buf);
  };
  const float r = static_cast<float>(radius);
  if (!(r >= FLT_MIN))
    doc.fail(path, fmt(radius) + " m is " + (r == 0 ? std::string("0") : "a denormal") + " in Box2D's float: at least " + short_number(FLT_MIN) + " m");
  const float mass = static_cast<float>(density) * 3.14159265359f * r * r;  // b2CircleShape::ComputeMass
  if (density > 0 && !(mass >= FLT_MIN))
    doc.fail(path, fmt(radius) + " m at density " + fmt(density) + " makes a mass of " + short_number(mass) +
                       " kg in Box2D's float, whose inverse is infinite (its first step would turn the body NaN): at least " +
                       short_number(std::sqrt(FLT_MIN / (std::numbers::pi * density)) * 1.001) + " m");
}

constexpr const char* kShapeKeys[] = {"shape", "radius", "half_extents", "vertices", "offset", "density", "friction", "restitution"};

// The shape fields of `r` (a body with one inline shape, or one element of "fixtures") of a body of `type`.
// In a generator's template a circle's radius may be left out (0.5; random_box may draw it).
ShapeSpec read_shape(ObjectReader& r, bool angle_is_shapes, bool is_template, BodyType type) {
  const LocatedJson& doc = r.doc();
  ShapeSpec s;
  s.where = doc.locate(r.path());
  const std::string kind = read_string(doc, r.need("shape", "circle, box or polygon"), r.at("shape"));
  if (kind == "circle") {
    s.kind = ShapeKind::Circle;
    if (!is_template || r.has("radius"))
      s.radius = read_positive(doc, r.need("radius", "a circle needs its radius"), r.at("radius"), kMaxShapeSize);
  } else if (kind == "box") {
    s.kind = ShapeKind::Box;
    const Vec2 h = read_vec2(doc, r.need("half_extents", "a box needs [half width, half height]"), r.at("half_extents"), kMaxShapeSize);
    for (int a = 0; a < 2; ++a) {
      const double e = a == 0 ? h.x : h.y;
      if (!(e >= kMinPolygonFeature))
        doc.fail(LocatedJson::element(r.at("half_extents"), a), "must be at least " + fmt(kMinPolygonFeature) + ", got " + fmt(e));
    }
    s.half_extents = h;
    if (angle_is_shapes) s.angle = r.number_in("angle", 0, -1e6, 1e6, "a finite angle");
  } else if (kind == "polygon") {
    s.kind = ShapeKind::Polygon;
    const json& v = r.need("vertices", "a polygon needs 3 to 8 points");
    const Path vp = r.at("vertices");
    if (!v.is_array()) doc.fail(vp, "must be an array of [x, y] points, got " + type_of(v));
    if (v.size() < 3 || v.size() > 8) doc.fail(vp, "a polygon has 3 to 8 vertices, got " + std::to_string(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i) s.vertices.push_back(read_vec2(doc, v[i], LocatedJson::element(vp, i), kMaxShapeSize));
    check_polygon(doc, s.vertices, vp);
  } else {
    doc.fail(r.at("shape"), "must be \"circle\", \"box\" or \"polygon\", got " + show(r.get("shape")));
  }
  if (kind != "circle" && r.has("radius")) doc.fail(r.at("radius"), "only a circle has a radius");
  if (kind != "box" && r.has("half_extents")) doc.fail(r.at("half_extents"), "only a box has half_extents");
  if (kind != "polygon" && r.has("vertices")) doc.fail(r.at("vertices"), "only a polygon has vertices");
  if (kind == "polygon") {
    if (r.has("offset")) doc.fail(r.at("offset"), "a polygon's vertices are already body coordinates; it has no offset");
  } else {
    s.offset = r.vec2("offset", {}, kMaxShapeSize);
  }
  s.density = r.number_in("density", 1, 0, 1e6, "from 0 to 1e6");
  s.friction = r.number_in("friction", 0.6, 0, 100, "from 0 to 100");
  s.restitution = r.number_in("restitution", 0, 0, 1, "from 0 to 1");
  if (kind == "circle" && r.has("radius")) check_radius_in_float(doc, r.at("radius"), s.radius, type == BodyType::Dynamic ? s.density : 0);
  return s;
}

// ---- bodies --------------------------------------------------------------------------------

// A body, or with `is_template` a generator's body (no position: the generator sets it).
BodySpec read_body(const LocatedJson& doc, const json& v, const Path& path, bool is_template) {
  ObjectReader r(doc, v, path, is_template ? "a body template" : "a body");
  BodySpec b;
  b.where = doc.locate(path);
  if (r.has("type")) {
    const std::string t = read_string(doc, r.get("type"), r.at("type"));
    if (t == "dynamic") b.type = BodyType::Dynamic;
    else if (t == "static") b.type = BodyType::Static;
    else if (t == "kinematic") b.type = BodyType::Kinematic;
    else doc.fail(r.at("type"), "must be \"dynamic\", \"static\" or \"kinematic\", got " + show(r.get("type")));
  }
  if (is_template) {
    if (r.has("position")) doc.fail(r.at("position"), "the generator places its bodies; a template has no position");
  } else {
    b.position = r.vec2("position", {}, kMaxSceneCoordinate);
  }
  b.velocity = r.vec2("velocity", {}, 1e5);
  b.angular_velocity = r.number_in("angular_velocity", 0, -1e4, 1e4, "from -1e4 to 1e4");
  if (r.has("fixtures")) {
    b.angle = r.number_in("angle", 0, -1e6, 1e6, "a finite angle");
    for (const char* k : kShapeKeys)
      if (r.has(k)) doc.fail(r.at(k), "a body has either inline shape fields or \"fixtures\", not both");
    const json& f = r.get("fixtures");
    const Path fp = r.at("fixtures");
    if (!f.is_array() || f.empty()) doc.fail(fp, "must be a non-empty array of shapes");
    if (f.size() > 64) doc.fail(fp, "at most 64 fixtures per body, got " + std::to_string(f.size()));
    for (std::size_t i = 0; i < f.size(); ++i) {
      ObjectReader fr(doc, f[i], LocatedJson::element(fp, i), "a shape");
      b.fixtures.push_back(read_shape(fr, true, is_template, b.type));
      fr.finish();
    }
  } else {
    b.angle = r.number_in("angle", 0, -1e6, 1e6, "a finite angle");
    if (is_template && !r.has("shape")) {
      b.fixtures.push_back(ShapeSpec{});  // default: a circle of radius 0.5
      b.fixtures.back().where = b.where;
      for (const char* k : kShapeKeys)
        if (r.has(k)) doc.fail(r.at(k), "missing \"shape\" next to it");
    } else {
      b.fixtures.push_back(read_shape(r, false, is_template, b.type));
    }
  }
  r.finish();
  return b;
}

// ---- generators ----------------------------------------------------------------------------

// The smallest box half extent or polygon edge of `b` (1e300 without either): what scale may not shrink below Box2D's weld distance.
double smallest_feature(const BodySpec& b) {
  double m = 1e300;
  for (const ShapeSpec& s : b.fixtures) {
    if (s.kind == ShapeKind::Box) m = std::min({m, s.half_extents.x, s.half_extents.y});
    if (s.kind == ShapeKind::Polygon)
      for (std::size_t i = 0; i < s.vertices.size(); ++i)
        m = std::min(m, length(sub(s.vertices[(i + 1) % s.vertices.size()], s.vertices[i])));
  }
  return m;
}

// The largest size, offset or vertex distance of `b`'s shapes: what scale may not grow beyond kMaxShapeSize.
double largest_feature(const BodySpec& b) {
  double m = 0;
  for (const ShapeSpec& s : b.fixtures) {
    m = std::max({m, std::abs(s.offset.x), std::abs(s.offset.y), s.radius, s.half_extents.x, s.half_extents.y});
    for (const Vec2& v : s.vertices) m = std::max({m, std::abs(v.x), std::abs(v.y)});
  }
  return m;
}

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

// Scene files' bodies and shapes (io/scene_json_bodies.hpp): polygons held to what Box2D keeps as
// given, radii to what its float holds.
//
// Index: shapes and polygons | bodies | features of a template body.
#include "io/scene_json_bodies.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/error.hpp"
#include "io/scene_json.hpp"

namespace nbscope::scene_fields {

namespace {

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

}  // namespace

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
  // WorldRefused, not the scene check's Error: the scene reads, its world cannot be built (the window shows it).
  const auto refuse = [&](const std::string& what) { throw WorldRefused(doc.locate(path) + what); };
  const float r = static_cast<float>(radius);
  if (!(r >= FLT_MIN))
    refuse(fmt(radius) + " m is " + (r == 0 ? std::string("0") : "a denormal") + " in Box2D's float: at least " + short_number(FLT_MIN) + " m");
  const float mass = static_cast<float>(density) * 3.14159265359f * r * r;  // b2CircleShape::ComputeMass
  if (density > 0 && !(mass >= FLT_MIN))
    refuse(fmt(radius) + " m at density " + fmt(density) + " makes a mass of " + short_number(mass) +
                       " kg in Box2D's float, whose inverse is infinite (its first step would turn the body NaN): at least " +
                       short_number(std::sqrt(FLT_MIN / (std::numbers::pi * density)) * 1.001) + " m");
}

namespace {

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
}  // namespace

// ---- bodies --------------------------------------------------------------------------------

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

// ---- features of a template body ----------------------------------------------------------

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

double largest_feature(const BodySpec& b) {
  double m = 0;
  for (const ShapeSpec& s : b.fixtures) {
    m = std::max({m, std::abs(s.offset.x), std::abs(s.offset.y), s.radius, s.half_extents.x, s.half_extents.y});
    for (const Vec2& v : s.vertices) m = std::max({m, std::abs(v.x), std::abs(v.y)});
  }
  return m;
}

}  // namespace nbscope::scene_fields

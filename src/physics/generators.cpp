#include "physics/generators.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/error.hpp"

namespace nbscope {

namespace {

// Box2D's polygon skin (b2_polygonRadius), repeated here to keep this file free of Box2D.
constexpr double kPolygonSkin = 0.01;

void scale_body(BodySpec& b, double s) {
  for (ShapeSpec& f : b.fixtures) {
    f.radius *= s;
    f.half_extents = {f.half_extents.x * s, f.half_extents.y * s};
    f.offset = {f.offset.x * s, f.offset.y * s};
    for (Vec2& v : f.vertices) v = {v.x * s, v.y * s};
  }
}

void make_grid(const GeneratorSpec& g, std::vector<BodySpec>& out) {
  for (std::int64_t row = 0; row < g.rows; ++row) {
    for (std::int64_t col = 0; col < g.columns; ++col) {
      BodySpec b = g.body;
      b.position = {g.origin.x + g.spacing.x * static_cast<double>(col), g.origin.y + g.spacing.y * static_cast<double>(row)};
      out.push_back(std::move(b));
    }
  }
}

void make_random_box(const GeneratorSpec& g, std::vector<BodySpec>& out) {
  SceneRng rng(g.seed);
  for (std::int64_t k = 0; k < g.count; ++k) {
    BodySpec b = g.body;
    b.position = {rng.uniform(g.min.x, g.max.x), rng.uniform(g.min.y, g.max.y)};
    if (g.radius_range) b.fixtures[0].radius = rng.uniform((*g.radius_range)[0], (*g.radius_range)[1]);
    if (g.scale_range[0] != 1 || g.scale_range[1] != 1) scale_body(b, rng.uniform(g.scale_range[0], g.scale_range[1]));
    if (g.speed_range[1] > 0) {
      const double speed = rng.uniform(g.speed_range[0], g.speed_range[1]);
      const double dir = rng.uniform(0, 2 * std::numbers::pi);
      b.velocity = {speed * std::cos(dir), speed * std::sin(dir)};
    }
    if (g.random_angle) b.angle = rng.uniform(0, 2 * std::numbers::pi);
    out.push_back(std::move(b));
  }
}

void make_pile(const GeneratorSpec& g, std::vector<BodySpec>& out) {
  SceneRng rng(g.seed);
  const double spacing = g.spacing.x > 0 ? g.spacing.x : 2 * body_extent(g.body) * 1.05;
  const double row_height = spacing * std::sqrt(3.0) / 2;  // hexagonal packing
  // The pile's extent is known only here (its spacing may come from the body): keep it in the world.
  const double rows = std::ceil(static_cast<double>(g.count) / static_cast<double>(g.columns));
  const double half_width = (static_cast<double>(std::min(g.count, g.columns)) / 2 + 1) * spacing;
  if (g.count > 0 && (std::abs(g.position.x) + half_width > kMaxSceneCoordinate ||
                      std::abs(g.position.y) + rows * row_height + spacing > kMaxSceneCoordinate)) {
    char what[160];
    std::snprintf(what, sizeof what, "the pile would reach beyond +-%g m (%g rows of %lld, %g m apart)", kMaxSceneCoordinate,
                  rows, static_cast<long long>(g.columns), spacing);
    throw Error(g.where + what);
  }
  for (std::int64_t k = 0; k < g.count; ++k) {
    const std::int64_t row = k / g.columns, col = k % g.columns;
    const double shift = (row % 2 == 1) ? spacing / 2 : 0;
    BodySpec b = g.body;
    b.position = {g.position.x + (static_cast<double>(col) - static_cast<double>(g.columns - 1) / 2) * spacing + shift +
                      rng.uniform(-g.jitter, g.jitter) * spacing,
                  g.position.y + static_cast<double>(row) * row_height + rng.uniform(-g.jitter, g.jitter) * spacing};
    out.push_back(std::move(b));
  }
}

}  // namespace

std::uint64_t SceneRng::next() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double SceneRng::uniform(double lo, double hi) {
  const double u = static_cast<double>(next() >> 11) * 0x1.0p-53;
  return lo + (hi - lo) * u;
}

double body_extent(const BodySpec& body) {
  double e = 0;
  for (const ShapeSpec& f : body.fixtures) {
    switch (f.kind) {
      case ShapeKind::Circle:
        e = std::max(e, std::hypot(f.offset.x, f.offset.y) + f.radius);
        break;
      case ShapeKind::Box:
        e = std::max(e, std::hypot(f.offset.x, f.offset.y) + std::hypot(f.half_extents.x, f.half_extents.y) + kPolygonSkin);
        break;
      case ShapeKind::Polygon:
        for (const Vec2& v : f.vertices) e = std::max(e, std::hypot(v.x, v.y) + kPolygonSkin);
        break;
    }
  }
  return e;
}

std::vector<BodySpec> initial_bodies(const Scene& scene) {
  std::vector<BodySpec> out = scene.bodies;
  out.reserve(static_cast<std::size_t>(scene.total_bodies()));
  for (const GeneratorSpec& g : scene.generators) {
    switch (g.kind) {
      case GeneratorKind::Grid: make_grid(g, out); break;
      case GeneratorKind::RandomBox: make_random_box(g, out); break;
      case GeneratorKind::Pile: make_pile(g, out); break;
      case GeneratorKind::Emitter: break;  // over time, see Emitter
    }
  }
  return out;
}

Emitter::Emitter(const GeneratorSpec& spec) : spec_(&spec), rng_(spec.seed) {}

void Emitter::emit_until(double t, std::vector<BodySpec>& out) {
  const GeneratorSpec& g = *spec_;
  // Body k appears at start + k / rate; a tiny tolerance keeps frame-aligned times from slipping a frame.
  while (emitted_ < g.count && g.start + static_cast<double>(emitted_) / g.rate <= t + 1e-9) {
    BodySpec b = g.body;
    b.position = {g.position.x + rng_.uniform(-0.5, 0.5) * g.width, g.position.y};
    const double turn = rng_.uniform(-0.5, 0.5) * g.spread;
    const double c = std::cos(turn), s = std::sin(turn);
    b.velocity = {c * g.body.velocity.x - s * g.body.velocity.y, s * g.body.velocity.x + c * g.body.velocity.y};
    out.push_back(std::move(b));
    ++emitted_;
  }
}

}  // namespace nbscope

// nbscope physics: turning a scene's generators into bodies (physics/scene.hpp documents each kind).
// Everything random comes from a seeded generator of our own, so a scene makes the same bodies on
// every machine and every run.
#pragma once
#include <cstdint>
#include <vector>

#include "physics/scene.hpp"

namespace nbscope {

// A small reproducible random generator (splitmix64): same seed, same numbers, everywhere.
class SceneRng {
 public:
  explicit SceneRng(std::uint64_t seed) : state_(seed) {}
  // The next 64 random bits.
  std::uint64_t next();
  // Uniform in [lo, hi).
  double uniform(double lo, double hi);

 private:
  std::uint64_t state_;
};

// The bodies present from the start: the scene's own, then those of every grid, random_box and
// pile generator, in file order (body indices follow this order).
std::vector<BodySpec> initial_bodies(const Scene& scene);

// One emitter generator pouring its bodies over time.
class Emitter {
 public:
  explicit Emitter(const GeneratorSpec& spec);
  // The bodies due by simulated time `t` that were not handed out yet (appended to `out`).
  void emit_until(double t, std::vector<BodySpec>& out);
  [[nodiscard]] std::int64_t emitted() const { return emitted_; }

 private:
  const GeneratorSpec* spec_;
  SceneRng rng_;
  std::int64_t emitted_ = 0;
};

// Largest distance from the body's origin to any point of its shapes (+ Box2D's polygon skin):
// the pile generator's spacing and a bound used by tests.
double body_extent(const BodySpec& body);

}  // namespace nbscope

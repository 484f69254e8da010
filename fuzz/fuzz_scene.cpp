// Fuzz target: the scene loader (io/scene_json.hpp) on arbitrary bytes. A scene it accepts must be
// within its limits; a scene of at most a few thousand bodies is also expanded by the generators
// (physics/generators.hpp, plain code without Box2D), which must make exactly the bodies counted,
// each with a fixture, at finite positions and of finite extent. No Box2D world is built: stepping
// is the worlds' own work, and too slow per input.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "core/error.hpp"
#include "fuzz_check.hpp"
#include "io/scene_json.hpp"
#include "physics/generators.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  nbscope::Scene scene;
  try {
    scene = nbscope::parse_scene_json(text, "fuzz.json");
    if (nbscope::fuzz::planted_fault() == "foreign-exception") throw std::logic_error("planted");
  } catch (const nbscope::Error&) {
    return 0;  // refused: the normal outcome
  }
  if (nbscope::fuzz::planted_fault() == "bad-row") scene.time_step = -scene.time_step;
  const std::int64_t total = scene.total_bodies();
  FUZZ_CHECK(total >= 0 && total <= nbscope::kMaxSceneBodies, "scene: " + std::to_string(total) + " bodies accepted");
  FUZZ_CHECK(std::isfinite(scene.time_step) && scene.time_step > 0 && scene.sub_steps >= 1, "scene: bad time step");
  if (total > 3000) return 0;
  std::int64_t emitted = 0;
  for (const nbscope::GeneratorSpec& g : scene.generators)
    if (g.kind == nbscope::GeneratorKind::Emitter) emitted += g.count;
  const std::vector<nbscope::BodySpec> bodies = nbscope::initial_bodies(scene);
  FUZZ_CHECK(static_cast<std::int64_t>(bodies.size()) == total - emitted,
             "scene: generators made " + std::to_string(bodies.size()) + " bodies, counted " + std::to_string(total - emitted));
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const nbscope::BodySpec& b = bodies[k];
    const auto at = [k] { return "scene: body " + std::to_string(k) + ": "; };
    FUZZ_CHECK(!b.fixtures.empty(), at() + "no fixture");
    FUZZ_CHECK(std::isfinite(b.position.x) && std::isfinite(b.position.y) && std::isfinite(b.angle), at() + "position not finite");
    FUZZ_CHECK(std::isfinite(b.velocity.x) && std::isfinite(b.velocity.y), at() + "velocity not finite");
    FUZZ_CHECK(std::isfinite(nbscope::body_extent(b)), at() + "extent not finite");
  }
  // Emitters pour over time: the first few bodies of each.
  for (const nbscope::GeneratorSpec& g : scene.generators) {
    if (g.kind != nbscope::GeneratorKind::Emitter) continue;
    nbscope::Emitter emitter(g);
    std::vector<nbscope::BodySpec> out;
    emitter.emit_until(g.start + 10.0 / g.rate, out);
    FUZZ_CHECK(out.size() <= static_cast<std::size_t>(g.count), "scene: an emitter poured more than its count");
    for (const nbscope::BodySpec& b : out)
      FUZZ_CHECK(std::isfinite(b.position.x) && std::isfinite(b.velocity.x) && std::isfinite(b.velocity.y),
                 "scene: an emitted body not finite");
  }
  return 0;
}

// Where frame sources are made (frame_sources.hpp): recorded frames are io's RecordingSource; a
// scene is simulated by SimulatedSource (simulated_source.hpp).
#include "app/frame_sources.hpp"

#include <cstdio>

#include "app/simulated_source.hpp"
#include "core/error.hpp"
#include "io/recording_source.hpp"

namespace nbscope {

std::unique_ptr<FrameSource> simulated_source(const Scene& scene, std::optional<std::int64_t> max_contacts) {
  Scene copy = scene;
  if (max_contacts) copy.max_contacts = *max_contacts;  // the flag over the scene's key
  auto world = std::make_unique<PhysicsWorld>(copy);
  // A pinned cell size must hold the largest element from the start and every element an
  // emitter will add (the grid would refuse it mid-run, far from the field to fix).
  if (scene.grid.cell_size) {
    char d[64];
    if (world->elements().size() > 0 && *scene.grid.cell_size < 2 * world->elements().max_radius()) {
      std::snprintf(d, sizeof d, "%.6g", 2 * world->elements().max_radius());
      throw Error(scene.cell_size_where + "smaller than the largest element's diameter " + d);
    }
    std::string emitter;
    if (const double r = world->largest_emitted_radius(emitter); *scene.grid.cell_size < 2 * r) {
      std::snprintf(d, sizeof d, "%.6g", 2 * r);
      throw Error(scene.cell_size_where + "smaller than the diameter " + d + " of the elements emitted by " +
                  emitter.substr(0, emitter.size() - 2));
    }
  }
  return std::make_unique<SimulatedSource>(std::move(copy), std::move(world));
}

std::unique_ptr<FrameSource> recorded_source(std::unique_ptr<RecordedFrames> frames, std::size_t budget) {
  return std::make_unique<RecordingSource>(std::move(frames), budget);
}

}  // namespace nbscope

// A scene simulated by Box2D as a frame source (simulated_source.hpp).
#include "app/simulated_source.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "physics/world_limits.hpp"

namespace nbscope {

SimulatedSource::SimulatedSource(Scene scene, std::unique_ptr<PhysicsWorld> world)
    : scene_(std::move(scene)), live_(std::make_unique<LiveWorld>(std::move(world))) {}
SimulatedSource::~SimulatedSource() { live_->wait(); }

void SimulatedSource::show(std::int64_t frame, const std::shared_ptr<const WorldState>& kept) {
  if (frame == live_->world().frame()) {
    kept_.reset();
    return;
  }
  if (!kept) throw Error("frame " + std::to_string(frame) + " is not kept");
  live_->release_drag();  // leaving the live frame: nobody holds a body in the past
  kept_ = std::make_unique<KeptWorldFrame>(live_->world(), kept);
}

void SimulatedSource::rewind() {
  live_->discard_step();
  auto fresh = std::make_unique<PhysicsWorld>(scene_);
  kept_.reset();  // it reads the old world
  live_ = std::make_unique<LiveWorld>(std::move(fresh));
  resume_.reset();
}

KeptState SimulatedSource::keep(const PairList* box2d_contacts) const {
  auto state = std::make_shared<WorldState>();
  live_->world().capture(*state, box2d_contacts);
  const std::size_t bytes = state->bytes();
  return {std::move(state), bytes};
}

Elements SimulatedSource::previous_elements(const std::shared_ptr<const WorldState>& kept_before) const {
  if (kept_before) return KeptWorldFrame(live_->world(), kept_before).elements();
  return elements();
}

void SimulatedSource::element_path(const FrameHistory& history, ElementId k, std::int64_t from, std::int64_t to,
                                   std::vector<std::array<double, 2>>& out) const {
  out.clear();
  if (k < 0 || k >= live_->elements().size()) return;  // a row of the frame shown
  const std::int64_t newest = live_->newest_frame();
  // From the first summary at or after `from` (a trail is a few hundred frames of a long history).
  for (std::size_t i = history.first_from(from); i < history.size(); ++i) {
    const FrameSummary& f = history.at(i);
    if (f.frame > to) break;
    if (k >= f.elements) continue;
    if (const auto& state = history.state(i)) {
      std::array<double, 2> p{};
      live_->element_centre(*state, k, p[0], p[1]);  // the snapshot's while the worker steps: no wait
      out.push_back(p);
    } else if (f.frame == newest) {
      out.push_back({live_->elements().x[k], live_->elements().y[k]});
    }
  }
}

std::function<std::string()> SimulatedSource::step_note() const {
  const PhysicsWorld* w = &live_->world();
  return [w] { return "Box2D step: " + grouped(w->bodies_now()) + " bodies, about " + grouped(w->estimated_contacts()) + " contacts"; };
}

void SimulatedSource::begin_resume() {
  live_->release_drag();
  resume_.begin(scene_, kept_->frame());
}

bool SimulatedSource::advance_resume(double budget_ms, const std::function<std::uint64_t(std::int64_t)>& hash_of) {
  if (!resume_.advance(budget_ms, live_->drags(), hash_of)) return false;
  // Arrived: the re-simulated world is the live one at K.
  std::unique_ptr<PhysicsWorld> world = resume_.take_world();
  kept_.reset();
  live_->replace_world(std::move(world));  // the drags from K on go with the frames
  live_->release_drag();  // nobody holds the mouse now; recorded, so a later resume replays it too
  return true;
}

}  // namespace nbscope

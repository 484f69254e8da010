// nbscope physics: the live world's frames, its overlapped step and its drag log (live_world.hpp).
#include "physics/live_world.hpp"

#include <chrono>
#include <system_error>

namespace nbscope {

namespace {
double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

void replay_drag(PhysicsWorld& world, const DragInput& in) {
  if (in.kind == DragInput::Kind::Begin) world.begin_drag(in.x, in.y);
  else if (in.kind == DragInput::Kind::To) world.drag_to(in.x, in.y);
  else world.end_drag();
}

LiveWorld::LiveWorld(std::unique_ptr<PhysicsWorld> world) : world_(std::move(world)) {}
LiveWorld::~LiveWorld() { wait(); }

std::int64_t LiveWorld::frame() const { return pending() ? shown_.frame : world_->frame(); }
double LiveWorld::time() const { return pending() ? shown_.time : world_->time(); }
const Elements& LiveWorld::elements() const { return pending() ? shown_.elements : world_->elements(); }
const std::vector<ElementSource>& LiveWorld::element_sources() const { return pending() ? shown_.sources : world_->sources(); }
void LiveWorld::element_centre(const WorldState& state, ElementId k, double& x, double& y) const {
  if (!pending()) return world_->element_centre(state, k, x, y);
  const auto i = static_cast<std::size_t>(k);
  PhysicsWorld::element_centre(state, shown_.sources[i], shown_.local_centres[i], x, y);
}
std::int64_t LiveWorld::body_count() const { return pending() ? shown_.bodies : world_->body_count(); }
void LiveWorld::body_shapes(std::vector<BodyShape>& out) const {
  if (pending()) out = shown_.shapes;
  else world_->shapes(out);
}

double LiveWorld::step() {
  const auto t0 = std::chrono::steady_clock::now();
  world_->step();
  return ms_since(t0);
}

namespace {
// The world as a Frame for the worker, which owns it between begin_step() and finish_step().
class WorldFrame final : public Frame {
 public:
  explicit WorldFrame(const PhysicsWorld& world) : world_(world) {}
  [[nodiscard]] std::int64_t frame() const override { return world_.frame(); }
  [[nodiscard]] double time() const override { return world_.time(); }
  [[nodiscard]] const Elements& elements() const override { return world_.elements(); }
  [[nodiscard]] const std::vector<ElementSource>& element_sources() const override { return world_.sources(); }
  [[nodiscard]] std::int64_t body_count() const override { return world_.body_count(); }
  void body_shapes(std::vector<BodyShape>& out) const override { world_.shapes(out); }
  [[nodiscard]] const Box2dFrame* box2d() const override { return &world_; }

 private:
  const PhysicsWorld& world_;
};
}  // namespace

bool LiveWorld::begin_step(std::function<void(const Frame& next)> then) {
  if (pending()) return true;
  PhysicsWorld& world = *world_;
  shown_.frame = world.frame();
  shown_.time = world.time();
  shown_.bodies = world.body_count();
  shown_.dragging = world.dragging();
  shown_.elements = world.elements();
  shown_.sources = world.sources();
  shown_.local_centres = world.local_centres();
  world.shapes(shown_.shapes);
  try {
    stepping_ = std::async(std::launch::async, [&world, then = std::move(then)] {
      const auto t0 = std::chrono::steady_clock::now();
      world.step();
      const double physics_ms = ms_since(t0);
      if (then) then(WorldFrame(world));
      return physics_ms;
    });
  } catch (const std::system_error&) {
    return false;  // no thread to be had: the next step runs here as it always did
  }
  return true;
}

double LiveWorld::finish_step() { return stepping_.get(); }

bool LiveWorld::step_ready() const {
  return pending() && stepping_.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

void LiveWorld::discard_step() {
  if (!pending()) return;
  try {
    stepping_.get();
  } catch (const std::exception&) {
    // The world that failed to step is being replaced: its error goes with it.
  }
}

void LiveWorld::wait() const {
  if (stepping_.valid()) stepping_.wait();
}

void LiveWorld::replace_world(std::unique_ptr<PhysicsWorld> world) {
  discard_step();
  const std::int64_t k = world->frame();
  world_ = std::move(world);
  std::erase_if(drags_, [&](const DragInput& in) { return in.frame >= k; });
}

bool LiveWorld::begin_drag(double x, double y) {
  drags_.push_back({DragInput::Kind::Begin, world_->frame(), x, y});
  return world_->begin_drag(x, y);
}
void LiveWorld::drag_to(double x, double y) {
  if (!world_->dragging()) return;
  drags_.push_back({DragInput::Kind::To, world_->frame(), x, y});
  world_->drag_to(x, y);
}
void LiveWorld::end_drag() {
  if (!world_->dragging()) return;
  drags_.push_back({DragInput::Kind::End, world_->frame(), 0, 0});
  world_->end_drag();
}
void LiveWorld::release_drag() { end_drag(); }
bool LiveWorld::dragging() const { return pending() ? shown_.dragging : world_->dragging(); }

}  // namespace nbscope

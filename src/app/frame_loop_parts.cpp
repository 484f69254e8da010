// The parts FrameLoop hands out (app/frame_loop_parts.hpp): the frame shown, the pipeline's
// configuration and the drag; the history and resume are in frame_loop_history.cpp.
//
// Index: source | pipeline | drag.
#include "app/frame_loop_impl.hpp"

#include <algorithm>

namespace nbscope {

// ---- source --------------------------------------------------------------------------------

bool LoopSource::pending() const {
  const Simulation* sim = simulation();
  return sim != nullptr && sim->pending();
}
void LoopSource::wait_for_worker() const {
  if (const Simulation* sim = simulation()) sim->wait();
}

bool LoopSource::has_scene() const { return loaded(); }
const Scene& LoopSource::scene() const {
  static const Scene kNone;
  return loaded() ? frames_->scene() : kNone;
}
bool LoopSource::replaying() const { return recording() != nullptr; }
std::int64_t LoopSource::recorded_frames() const { return loaded() ? static_cast<std::int64_t>(frames_->entries().size()) : 0; }
bool LoopSource::carries_pairs() const { return recording() != nullptr && recording()->has_pairs; }
const Recording* LoopSource::recording() const { return loaded() ? frames_->recording() : nullptr; }
const PairList* LoopSource::recorded_pairs() const { return loaded() ? frames_->recorded_pairs() : nullptr; }
int LoopSource::pair_base() const { return recording() != nullptr ? recording()->pair_base : 0; }
bool LoopSource::at_end() const { return loaded() && !frames_->showing_past() && !frames_->can_step(); }
std::optional<double> LoopSource::written_at() const { return loaded() ? frames_->written_at() : std::nullopt; }
bool LoopSource::step_pending() const { return pending(); }
bool LoopSource::step_ready() const {
  const Simulation* sim = simulation();
  return sim != nullptr && sim->step_ready();
}
bool LoopSource::physics_overlapped() const { return physics_overlapped_; }
bool LoopSource::detection_overlapped() const { return detection_overlapped_; }
std::int64_t LoopSource::frame() const { return loaded() ? frames_->frame() : 0; }
double LoopSource::time() const { return loaded() ? frames_->time() : 0; }

const Elements& LoopSource::elements() const {
  static const Elements kNone;
  return loaded() ? frames_->elements() : kNone;
}
const std::vector<std::int32_t>* LoopSource::ranks() const { return loaded() ? frames_->ranks() : nullptr; }
const Subdomains* LoopSource::subdomains() const { return loaded() ? frames_->subdomains() : nullptr; }
const std::vector<ElementSource>& LoopSource::element_sources() const {
  static const std::vector<ElementSource> kNone;
  return loaded() ? frames_->element_sources() : kNone;
}
std::int64_t LoopSource::body_count() const { return loaded() ? frames_->body_count() : 0; }

void LoopSource::body_shapes(std::vector<BodyShape>& out) const {
  out.clear();
  if (loaded()) frames_->body_shapes(out);
}

// ---- pipeline ------------------------------------------------------------------------------

const std::string& LoopPipeline::algorithm() const { return pipeline_.options().algorithm; }
Fault LoopPipeline::fault() const { return pipeline_.options().fault; }
bool LoopPipeline::checks_enabled() const { return pipeline_.options().checks; }
Touching LoopPipeline::touching() const { return pipeline_.detect_options().touching; }
int LoopPipeline::threads() const { return threads_; }
std::string LoopPipeline::reference_policy() const { return pipeline_.reference_policy(); }
std::string LoopPipeline::scope_note() { return FrameChecker::scope_note(); }

const std::vector<std::string>& LoopPipeline::comparison_algorithms() const { return pipeline_.comparison_algorithms(); }
std::size_t LoopPipeline::detector_bytes() const { return on_worker() ? shown_detector_bytes_ : pipeline_.detector().own_bytes(); }

void LoopPipeline::record_traces(bool on) {
  if (on_worker()) wanted_traces_ = on;  // the worker reads the flag: set once it is back
  else pipeline_.set_record_traces(on);
}
bool LoopPipeline::record_traces() const { return wanted_traces_.value_or(pipeline_.record_traces()); }

std::shared_ptr<const FrameTrace> LoopPipeline::frame_trace() {
  if (!source_.loaded()) return nullptr;
  if (on_worker()) return shown_trace();  // the detector is the worker's now
  return pipeline_.trace(*source_.frames_);
}

// ---- drag ----------------------------------------------------------------------------------

Simulation* LoopDrag::live() const {
  Simulation* sim = loop_.simulation();
  return sim != nullptr && !loop_.frames().showing_past() && !sim->resuming() ? sim : nullptr;
}
bool LoopDrag::begin(double x, double y) {
  loop_.settle();  // the drag acts on the newest frame
  Simulation* sim = live();
  return sim != nullptr && sim->begin_drag(x, y);
}
void LoopDrag::move_to(double x, double y) {
  loop_.settle();
  if (Simulation* sim = live()) sim->drag_to(x, y);
}
void LoopDrag::end() {
  loop_.settle();
  if (Simulation* sim = live()) sim->end_drag();
}
bool LoopDrag::active() const {
  const Simulation* sim = loop_.simulation();
  return sim != nullptr && !loop_.frames().showing_past() && sim->dragging();
}

}  // namespace nbscope

// The parts FrameLoop hands out (app/frame_loop_parts.hpp): the frame shown, the pipeline's
// configuration and the drag; the history and resume are in frame_loop_history.cpp.
//
// Index: source | pipeline | drag.
#include "app/frame_loop_impl.hpp"

#include <algorithm>

namespace nbscope {

// ---- source --------------------------------------------------------------------------------

bool LoopSource::has_scene() const { return s_->loaded(); }
const Scene& LoopSource::scene() const {
  static const Scene kNone;
  return s_->loaded() ? s_->source().scene() : kNone;
}
bool LoopSource::replaying() const { return recording() != nullptr; }
std::int64_t LoopSource::recorded_frames() const {
  return s_->loaded() ? static_cast<std::int64_t>(s_->source().entries().size()) : 0;
}
bool LoopSource::carries_pairs() const { return recording() != nullptr && recording()->has_pairs; }
const Recording* LoopSource::recording() const { return s_->loaded() ? s_->source().recording() : nullptr; }
const PairList* LoopSource::recorded_pairs() const { return s_->loaded() ? s_->source().recorded_pairs() : nullptr; }
int LoopSource::pair_base() const { return recording() != nullptr ? recording()->pair_base : 0; }
bool LoopSource::at_end() const { return s_->loaded() && !s_->source().showing_past() && !s_->source().can_step(); }
bool LoopSource::step_pending() const { return s_->pending(); }
bool LoopSource::step_ready() const {
  const Simulation* sim = s_->simulation();
  return sim != nullptr && sim->step_ready();
}
bool LoopSource::physics_overlapped() const { return s_->physics_overlapped; }
bool LoopSource::detection_overlapped() const { return s_->detection_overlapped; }
std::int64_t LoopSource::frame() const { return s_->loaded() ? s_->frame_number() : 0; }
double LoopSource::time() const { return s_->loaded() ? s_->source().time() : 0; }

const Elements& LoopSource::elements() const {
  static const Elements kNone;
  return s_->loaded() ? s_->now() : kNone;
}
const std::vector<ElementSource>& LoopSource::element_sources() const {
  static const std::vector<ElementSource> kNone;
  return s_->loaded() ? s_->source().element_sources() : kNone;
}
std::int64_t LoopSource::body_count() const { return s_->loaded() ? s_->source().body_count() : 0; }

void LoopSource::body_shapes(std::vector<BodyShape>& out) const {
  out.clear();
  if (s_->loaded()) s_->source().body_shapes(out);
}

// ---- pipeline ------------------------------------------------------------------------------

const std::string& LoopPipeline::algorithm() const { return s_->pipeline.options().algorithm; }
Fault LoopPipeline::fault() const { return s_->pipeline.options().fault; }
bool LoopPipeline::checks_enabled() const { return s_->pipeline.options().checks; }
Touching LoopPipeline::touching() const { return s_->pipeline.detect_options().touching; }
int LoopPipeline::threads() const { return s_->options.threads; }
std::string LoopPipeline::reference_policy() const { return s_->pipeline.reference_policy(); }
std::string LoopPipeline::scope_note() { return FrameChecker::scope_note(); }

const std::vector<std::string>& LoopPipeline::comparison_algorithms() const { return s_->pipeline.comparison_algorithms(); }
std::size_t LoopPipeline::detector_bytes() const {
  return s_->pipeline_on_worker() ? s_->shown_detector_bytes : s_->pipeline.detector().own_bytes();
}

void LoopPipeline::record_traces(bool on) {
  if (s_->pipeline_on_worker()) s_->wanted_traces = on;  // the worker reads the flag: set once it is back
  else s_->pipeline.set_record_traces(on);
}
bool LoopPipeline::record_traces() const { return s_->wanted_traces.value_or(s_->pipeline.record_traces()); }

std::shared_ptr<const FrameTrace> LoopPipeline::frame_trace() {
  if (!s_->loaded()) return nullptr;
  if (s_->pipeline_on_worker()) return s_->shown_trace();  // the detector is the worker's now
  return s_->pipeline.trace(s_->source());
}

// ---- drag ----------------------------------------------------------------------------------

Simulation* LoopDrag::live() const {
  Simulation* sim = s_->simulation();
  return sim != nullptr && !s_->source().showing_past() && !sim->resuming() ? sim : nullptr;
}
bool LoopDrag::begin(double x, double y) {
  s_->settle();  // the drag acts on the newest frame
  Simulation* sim = live();
  return sim != nullptr && sim->begin_drag(x, y);
}
void LoopDrag::move_to(double x, double y) {
  s_->settle();
  if (Simulation* sim = live()) sim->drag_to(x, y);
}
void LoopDrag::end() {
  s_->settle();
  if (Simulation* sim = live()) sim->end_drag();
}
bool LoopDrag::active() const {
  const Simulation* sim = s_->simulation();
  return sim != nullptr && !s_->source().showing_past() && sim->dragging();
}

}  // namespace nbscope

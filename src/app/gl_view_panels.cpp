// The panels' part of GlView: the SimView each frame hands the ImGui panels: a pointer to the
// loop's shown FrameResult, and what it does not hold (the session, the history, the window's costs).
#include <tuple>

#include "app/gl_view.hpp"
#include "app/headless.hpp"
#include "check/recorded_lane.hpp"

namespace nbscope {

void GlView::fill_panels_view(const FrameLoop& loop, const Session& session, const std::shared_ptr<const FrameTrace>& trace,
                              ui::SimView& sim) {
  const Elements& e = loop.source().elements();
  sim.scene_path = session.scene_path;
  sim.scene_name = loop.source().scene().name;
  sim.scene_files = session.scene_files;
  for (const DetectorInfo& d : detector_infos())
    if (d.dim2) sim.detectors.push_back(d.name);
  sim.algorithms = sim.detectors;
  if (loop.source().carries_pairs()) sim.algorithms.emplace_back(kRecordedAlgorithm);  // the recording's own pairs, last
  sim.algorithm = loop.pipeline().algorithm();
  sim.error = session.error;
  sim.touching = loop.pipeline().touching();
  sim.frame_unit = frame_unit_of(loop.source());
  sim.units = choices_.units;
  sim.threads = loop.pipeline().threads();
  sim.paused = session.paused;
  sim.time_step = loop.source().scene().time_step;
  sim.speed = session.speed;
  sim.frame = &loop.result();  // the loop's own: read, not copied
  sim.bodies = loop.source().body_count();
  sim.elements = &e;
  sim.subdomains = loop.source().subdomains();
  sim.layer = layer();
  sim.lists = state_.overlays.lists ? &lists_.lists : nullptr;
  sim.trace = trace;
  sim.detector_bytes = loop.pipeline().detector_bytes();
  if (loop.pipeline().fault() != Fault::None) {
    sim.fault_name = fault_name(loop.pipeline().fault());
    sim.fault_description = fault_description(loop.pipeline().fault());
  }
  // The run: its frames for the Timeline, its violations for their panel.
  const FrameHistory& history = loop.history().frames();
  sim.timeline = &history.summaries();
  sim.newest_frame = loop.history().newest_frame();
  sim.showing_past = loop.history().showing_past();
  sim.replaying = loop.source().replaying();
  sim.play_direction = session.play_direction;
  sim.history_bytes = loop.history().bytes();
  sim.history_budget = history.budget();
  sim.history_dropped = history.dropped();
  sim.resuming = loop.resume().active();
  std::tie(sim.resume_done, sim.resume_target) = loop.resume().progress();
  sim.resume_note = session.resume_note;
  const ViolationLog& log = loop.history().violation_log();
  sim.violations = &log.listed();
  sim.violations_total = log.total();
  sim.violations_by_invariant = log.by_invariant();
  sim.violation_frames = log.frames();
  sim.violations_generation = log.generation();
  if (state_.current_violation >= static_cast<std::int64_t>(log.listed().size())) state_.current_violation = -1;
  sim.locate_status = stepper_open() ? stepper_->target_status()
                                     : "Open the Stepper (View menu) to see the operation that decided this pair.";
  sim.scene_insets = host_.insets(state_);
  sim.hide_timings = choices_.hide_timings;
  fill_drawing(loop, session, sim);
  sim.fps = session.fps;
  sim.sim_rate = session.sim_rate;
  sim.frame_history_ms = frame_history_;
  sim.render_stats = &renderer_->stats();
  sim.imgui_vertices = imgui_->last_vertices();
  sim.imgui_indices = imgui_->last_indices();
  sim.imgui_lists = imgui_->last_draw_lists();
  sim.trace_events = trace ? trace->log.events().size() : 0;
  sim.trace_bytes = trace ? trace->log.events().size() * sizeof(TraceEvent) : 0;
  sim.gl_description = gl_description_;
  sim.width = context_.width();
  sim.height = context_.height();
}

void GlView::fill_drawing(const FrameLoop& loop, const Session& session, ui::SimView& sim) const {
  sim.drawing = session.split.measured ? session.split : cost_;  // a window's whole frame split, else this view's parts
  sim.drawing.physics_overlapped = loop.source().physics_overlapped();
  sim.drawing.detection_overlapped = loop.source().detection_overlapped();
  if (!session.split.measured) sim.drawing.frame_ms = session.frame_ms;
}

}  // namespace nbscope

// FrameLoopState: loading a frame source, running the shown frame through the pipeline and
// recording it in the history (frame_loop_impl.hpp).
#include "app/frame_loop_impl.hpp"

#include "physics/world_limits.hpp"

namespace nbscope {

FrameLoopState::FrameLoopState(FrameLoopOptions o)
    : options(std::move(o)),
      pipeline(source, PipelineOptions{options.algorithm, options.fault, options.checks, options.brute_limit}, options.threads),
      history(source, options.history_budget, options.max_summaries) {}
FrameLoopState::~FrameLoopState() { wait_for_worker(); }

void FrameLoopState::detect_and_check(FrameChange::Kind kind) {
  // Every change of the shown frame comes through here: load, restart, step, show, redetect, resume.
  const std::string what =
      "detection (" + lanes().options().algorithm + ") and the check of " + grouped(now().size()) + " elements";
  watch.next_phase(frame_number(), [what] { return what; });
  const Unwatch unwatch{watch};
  FrameInput in;
  in.source = &frames();
  in.first = frames().first();
  in.previous = [this] { return elements_before(frame_number()); };
  in.where = frames().scene().path + ": frame " + std::to_string(frame_number()) + ": ";
  lanes().run(in);
  publish(kind);
}

void FrameLoopState::detect_on_worker(const Frame& next) {
  // On the worker, which owns the world and the pipeline until settle(): nothing of the history or
  // the views is read here (the stale-positions fault's positions were remembered by begin_step()).
  FrameInput in;
  in.source = &next;
  in.first = next.frame() == 0;
  in.previous = [&next] { return next.elements(); };
  in.where = frames().scene().path + ": frame " + std::to_string(next.frame()) + ": ";
  lanes().run(in);
}

bool FrameLoopState::detection_can_leave_thread() const {
  // A plugin's detector is called on the thread that loaded it: its frames are detected here.
  if (!detector_info(lanes().options().algorithm).library.empty()) return false;
  for (const std::string& name : lanes().comparison_algorithms())
    if (!detector_info(name).library.empty()) return false;
  return true;
}

void FrameLoopState::publish(FrameChange::Kind kind) {
  record_frame();
  // Published only now: a detection that threw leaves the views on the last whole frame.
  // (A redetect after such a throw shows a frame the views have not followed: it moved it.)
  const bool moved = kind != FrameChange::Kind::redetected || frame_number() != change.frame;
  if (options.track_cell_changes) {
    const FrameResult& result = lanes().result();
    if (kind == FrameChange::Kind::loaded || load_unpublished) cell_changes.start(frame_number(), result.selected().cells, result.ids);
    else if (moved) cell_changes.show(frame_number(), result.selected().cells, result.ids, kind == FrameChange::Kind::stepped);
  }
  ++change.generation;
  change.kind = kind;
  change.frame = frame_number();
  if (kind == FrameChange::Kind::loaded || load_unpublished) change.loaded_at = change.generation;
  load_unpublished = false;
  if (moved) change.moved_at = change.generation;
}

void FrameLoopState::redetect() {
  if (settle()) return;  // a step in flight is adopted, and so detected with what is set now
  if (loaded()) detect_and_check(FrameChange::Kind::redetected);
}

void FrameLoopState::record_frame() {
  const FrameResult& result = lanes().result();
  const FrameReport& r = result.report();
  FrameSummary s;
  s.frame = frame_number();
  s.time = frames().time();
  s.hash = r.hash;
  s.checked = r.checked;
  s.elements = now().size();
  s.pairs = static_cast<std::int64_t>(result.selected().pairs.size());
  s.violations = r.violation_count();
  s.physics_ms = static_cast<float>(r.timings.physics_ms);
  s.detection_ms = static_cast<float>(r.timings.detection_ms);
  s.check_ms = static_cast<float>(r.timings.check_ms);
  if (const auto index = kept().find(s.frame)) {
    const FrameSummary& before = kept().at(*index);
    s.physics_ms = before.physics_ms;  // a frame shown again is not simulated again
    if (!r.checked && before.checked) {
      // Checks switched off: what the frame's last check found stays (summary and violations).
      s.checked = true;
      s.violations = before.violations;
      s.check_ms = before.check_ms;
      kept().update(*index, s);
      return;
    }
    kept().update(*index, s);  // (update keeps its `kept`)
  } else {
    KeptState state;
    if (kept().budget() > 0) state = frames().keep(lanes().options().checks ? &result.box2d : nullptr);
    s.kept = state.state != nullptr;  // with no budget only the newest frame itself can be shown
    kept().push(s, std::move(state.state), state.bytes);
  }
  if (r.checked && options.log_violations) violations().set_frame(r);
}

void FrameLoopState::check_recorded_source(bool wanted, const Recording* rec, const std::string& path) {
  if (!wanted) return;
  if (rec == nullptr)
    throw Error(std::string(kRecordedAlgorithm) + ": the pairs a recording carries (nbscope replay FILE.nbsrec); the scene " + path +
                " has none: choose a detector, e.g. nbs");
  if (!rec->has_pairs)
    throw Error(std::string(kRecordedAlgorithm) + ": " + rec->path +
                " carries no pairs (no frame has a 'pairs' block): choose a detector, e.g. --algorithm nbs");
}

void FrameLoopState::accept_recorded() const {
  check_recorded_fault(lanes().options().fault);
  if (loaded()) check_recorded_source(true, frames().recording(), frames().scene().path);
}

void FrameLoopState::load(std::unique_ptr<FrameSource> fresh) {
  check_recorded_source(lanes().has_recorded_lane(), fresh->recording(), fresh->scene().path);
  DetectOptions opts;
  opts.touching = options.touching;
  opts.threads = options.threads;
  opts.grid = fresh->scene().grid;  // a recording's grid pins as a scene's does
  fresh->set_budget(history.budget());
  watch.disarm();  // its note describes the old source
  watch.reset();   // a new run
  discard_step();  // the world it steps goes
  source.frames_ = std::move(fresh);
  lanes().set_detect_options(opts);
  start();
}

void FrameLoopState::start() {
  lanes().clear_reports();
  source.physics_overlapped_ = false;
  source.detection_overlapped_ = false;
  kept().clear();
  violations().clear();
  entries_taken = 0;
  take_new_entries();
  lanes().remember_previous(frame_number(), now());
  load_unpublished = true;  // until a detection publishes it (this one may throw)
  detect_and_check(FrameChange::Kind::loaded);
}

void FrameLoopState::take_new_entries() {
  // Frames known in advance (a recording's) are showable from the start; each is checked when first shown.
  const std::vector<RecordedEntry>& entries = frames().entries();
  for (; entries_taken < entries.size(); ++entries_taken) {
    const RecordedEntry& f = entries[entries_taken];
    FrameSummary s;
    s.frame = f.number;
    s.time = f.time;
    s.kept = true;
    s.elements = f.elements;
    kept().push(s, nullptr, 0);
  }
}

Elements FrameLoopState::elements_before(std::int64_t frame) const {
  const auto index = kept().find(frame - 1);
  return frames().previous_elements(index ? kept().state(*index) : nullptr);
}

}  // namespace nbscope

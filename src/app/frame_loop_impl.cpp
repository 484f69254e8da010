// FrameLoopState: loading a frame source, running the shown frame through the pipeline and
// recording it in the history (frame_loop_impl.hpp).
#include "app/frame_loop_impl.hpp"

#include <cstdio>

namespace nbscope {

FrameLoopState::FrameLoopState(FrameLoopOptions o)
    : options(std::move(o)), pipeline(PipelineOptions{options.algorithm, options.fault, options.checks, options.brute_limit}) {
  history.set_budget(options.history_budget);
  history.set_max_summaries(options.max_summaries);
}
FrameLoopState::~FrameLoopState() { wait_for_worker(); }

void FrameLoopState::detect_and_check(FrameChange::Kind kind) {
  // Every change of the shown frame comes through here: load, restart, step, show, redetect, resume.
  const std::string what =
      "detection (" + pipeline.options().algorithm + ") and the check of " + grouped(now().size()) + " elements";
  watch.next_phase(frame_number(), [what] { return what; });
  const Unwatch unwatch{watch};
  FrameInput in;
  in.source = &source();
  in.first = live ? frame_number() == 0 : replay->index() == 0;
  in.given_pairs = replay ? &replay->current().pairs : nullptr;
  in.precision = replay ? replay->current().precision : 0;
  in.previous = [this] { return elements_before(frame_number()); };
  in.where = scene.path + ": frame " + std::to_string(frame_number()) + ": ";
  pipeline.run(in);
  record_frame();
  // Published only now: a detection that threw leaves the views on the last whole frame.
  // (A redetect after such a throw shows a frame the views have not followed: it moved it.)
  const bool moved = kind != FrameChange::Kind::redetected || frame_number() != change.frame;
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
  const FrameResult& result = pipeline.result();
  const FrameReport& r = result.report();
  FrameSummary s;
  s.frame = frame_number();
  s.time = source().time();
  s.hash = r.hash;
  s.checked = r.checked;
  s.elements = now().size();
  s.pairs = static_cast<std::int64_t>(result.selected().pairs.size());
  s.violations = r.violation_count();
  s.physics_ms = static_cast<float>(r.timings.physics_ms);
  s.detection_ms = static_cast<float>(r.timings.detection_ms);
  s.check_ms = static_cast<float>(r.timings.check_ms);
  if (const auto index = history.find(s.frame)) {
    const FrameSummary& before = history.at(*index);
    s.physics_ms = before.physics_ms;  // a frame shown again is not simulated again
    if (!r.checked && before.checked) {
      // Checks switched off: what the frame's last check found stays (summary and violations).
      s.checked = true;
      s.violations = before.violations;
      s.check_ms = before.check_ms;
      history.update(*index, s);
      return;
    }
    history.update(*index, s);  // (update keeps its `kept`)
  } else {
    std::shared_ptr<WorldState> state;
    if (live && history.budget() > 0) {
      state = std::make_shared<WorldState>();
      live->world().capture(*state, pipeline.options().checks ? &result.box2d : nullptr);
    }
    s.kept = state != nullptr;  // with no budget only the live frame itself can be shown
    history.push(s, state, state ? state->bytes() : 0);
  }
  if (r.checked && options.log_violations) violations.set_frame(r);
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
  check_recorded_fault(pipeline.options().fault);
  if (loaded()) check_recorded_source(true, replay ? &replay->header() : nullptr, scene.path);
}

void FrameLoopState::build(const Scene& s) {
  check_recorded_source(pipeline.has_recorded_lane(), nullptr, s.path);
  DetectOptions opts;
  opts.touching = options.touching;
  opts.threads = options.threads;
  opts.grid = s.grid;
  // No Box2D call beside the worker's; if the new scene is refused, the step in flight stays pending.
  wait_for_worker();
  Scene copy = s;
  if (options.max_contacts) copy.max_contacts = *options.max_contacts;  // the flag over the scene's key
  auto fresh = std::make_unique<PhysicsWorld>(copy);
  // A pinned cell size must hold the largest element from the start and every element an
  // emitter will add (the grid would refuse it mid-run, far from the field to fix).
  if (s.grid.cell_size) {
    char d[64];
    if (fresh->elements().size() > 0 && *s.grid.cell_size < 2 * fresh->elements().max_radius()) {
      std::snprintf(d, sizeof d, "%.6g", 2 * fresh->elements().max_radius());
      throw Error(s.cell_size_where + "smaller than the largest element's diameter " + d);
    }
    std::string emitter;
    if (const double r = fresh->largest_emitted_radius(emitter); *s.grid.cell_size < 2 * r) {
      std::snprintf(d, sizeof d, "%.6g", 2 * r);
      throw Error(s.cell_size_where + "smaller than the diameter " + d + " of the elements emitted by " +
                  emitter.substr(0, emitter.size() - 2));
    }
  }
  scene = std::move(copy);
  watch.disarm();  // its note describes the old world
  watch.reset();   // a new run
  kept.reset();    // it points into the old world
  discard_step();
  live = std::make_unique<LiveWorld>(std::move(fresh));
  replay.reset();
  pipeline.set_detect_options(opts);
  start();
}

void FrameLoopState::build(std::unique_ptr<RecordedFrames> frames) {
  const Recording& rec = frames->header();
  check_recorded_source(pipeline.has_recorded_lane(), &rec, rec.path);
  DetectOptions opts;
  opts.touching = options.touching;
  opts.threads = options.threads;
  Scene s;
  s.path = rec.path;
  s.name = std::filesystem::path(rec.path).stem().string();
  opts.grid = s.grid = rec.grid;
  // The recorded time per frame, for the panels (the recording's own times are shown per frame).
  const RecordedEntry& first = frames->entries().front();
  const RecordedEntry& last = frames->entries().back();
  if (last.number > first.number && last.time > first.time)
    s.time_step = (last.time - first.time) / static_cast<double>(last.number - first.number);
  // Its first frame read before anything is replaced: a frame refused leaves the old source.
  auto source = std::make_unique<RecordingSource>(std::move(frames), options.history_budget);
  discard_step();  // the world it steps goes
  scene = std::move(s);
  kept.reset();
  live.reset();
  looked_up.reset();
  replay = std::move(source);
  pipeline.set_detect_options(opts);
  start();
}

void FrameLoopState::start() {
  pipeline.clear_reports();
  physics_overlapped = false;
  if (replay) replay->rewind();
  kept.reset();
  resume.reset();
  history.clear();
  violations.clear();
  if (replay) {
    // Every recorded frame is showable from the start; each is checked when first shown.
    for (const RecordedEntry& f : replay->entries()) {
      FrameSummary s;
      s.frame = f.number;
      s.time = f.time;
      s.kept = true;
      s.elements = f.elements;
      history.push(s, nullptr, 0);
    }
  }
  pipeline.remember_previous(frame_number(), now());
  load_unpublished = true;  // until a detection publishes it (this one may throw)
  detect_and_check(FrameChange::Kind::loaded);
}

Elements FrameLoopState::elements_before(std::int64_t frame) const {
  if (replay) return replay->previous_elements();
  const auto index = history.find(frame - 1);
  if (index && history.state(*index)) return KeptWorldFrame(live->world(), history.state(*index)).elements();
  return now();
}

}  // namespace nbscope

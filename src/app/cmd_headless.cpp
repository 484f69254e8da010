// `nbscope headless`: load a scene, run N frames through the FrameLoop, check every frame, report;
// optionally record every frame's elements. `nbscope replay --headless` runs the same loop on
// recorded frames (app/cmd_replay.cpp).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <utility>
#include <vector>

#include "app/clock.hpp"
#include "app/commands.hpp"
#include "app/frame_loop.hpp"
#include "app/colour_by.hpp"
#include "app/export_vtk.hpp"
#include "app/frame_recorder.hpp"
#include "app/headless.hpp"
#include "app/headless_view.hpp"
#include "app/help.hpp"
#include "app/progress_bar.hpp"
#include "app/write_latency.hpp"
#include "check/subdomains.hpp"
#include "app/scaling_flags.hpp"
#include "app/threads_flag.hpp"
#include "check/recorded_lane.hpp"
#include "core/detector.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/data_dir.hpp"
#include "io/lammps_dump.hpp"
#include "io/plural.hpp"
#include "io/recording.hpp"
#include "io/report_json.hpp"
#include "physics/divergence.hpp"
#include "io/signals.hpp"

namespace nbscope {

namespace {

// The detectors `--algorithm` names: one, a comma-separated list, or "all" (every detector that
// handles `dim`-D frames, nbs first as the one shown and summarised first; brute only while brute
// force is the reference anyway; last `recorded` when `with_recorded`, a recording carrying pairs).
// Sets `note` when brute is left out, `other_dim` to the detectors left out for their dimension.
std::vector<std::string> algorithms_of(const std::string& text, std::int64_t elements, int dim, std::int64_t brute_limit, std::string& note,
                                       bool with_recorded, std::string& other_dim) {
  std::vector<std::string> names;
  if (text == "all") {
    for (const DetectorInfo& d : detector_infos()) {
      if (dim == 3 ? !d.dim3 : !d.dim2) {
        other_dim += (other_dim.empty() ? "" : ", ") + d.name;
        continue;
      }
      if (d.name == "brute" && elements > brute_limit) {
        note = "brute left out of 'all': " + plural(elements, "element") + " is past --brute-limit " + std::to_string(brute_limit);
        continue;
      }
      names.push_back(d.name);
    }
    if (const auto nbs = std::find(names.begin(), names.end(), "nbs"); nbs != names.end()) std::rotate(names.begin(), nbs, nbs + 1);
    if (with_recorded) names.emplace_back(kRecordedAlgorithm);
    return names;
  }
  return split_names("--algorithm", text);
}

// True when no frame of the loaded scene or recording can have a pair: no elements now, and no
// emitter (scene) or recorded frame (recording) that brings any.
bool nothing_to_check(const FrameLoop& loop) {
  if (loop.source().elements().size() > 0) return false;
  if (loop.source().replaying()) {
    for (const FrameSummary& f : loop.history().frames().summaries())
      if (f.elements > 0) return false;
    return true;
  }
  for (const GeneratorSpec& g : loop.source().scene().generators)
    if (g.kind == GeneratorKind::Emitter && g.count > 0) return false;
  return true;
}

}  // namespace

HeadlessOptions::Rewind parse_rewind(const std::string& text) {
  const std::size_t colon = text.find(':');
  const auto number = [&](const std::string& part) -> std::int64_t {
    if (part.empty() || part.size() > 12 || part.find_first_not_of("0123456789") != std::string::npos)
      throw Error("--rewind: expected FROM:TO, two frame numbers (e.g. 200:50), got '" + text + "'");
    return std::stoll(part);
  };
  if (colon == std::string::npos) throw Error("--rewind: expected FROM:TO, two frame numbers (e.g. 200:50), got '" + text + "'");
  HeadlessOptions::Rewind r{number(text.substr(0, colon)), number(text.substr(colon + 1))};
  if (r.to >= r.from)
    throw Error("--rewind: " + text + " goes forwards: TO (" + std::to_string(r.to) + ") must be before FROM (" +
                std::to_string(r.from) + ")");
  return r;
}

HeadlessOptions parse_headless_options(Args& args) {
  HeadlessOptions o;
  const auto scene = args.value("--scene");
  o.frames = args.integer("--frames").value_or(o.frames);
  o.algorithm = args.value("--algorithm").value_or(o.algorithm);
  o.report = args.value("--report");
  if (const auto f = args.value("--inject-fault")) o.fault = parse_fault(*f);
  o.brute_limit = args.integer("--brute-limit").value_or(o.brute_limit);
  o.quiet = args.flag("--quiet");
  o.touching = take_touching(args);
  o.threads = take_threads(args);
  parse_view_options(args, true, o.view);
  o.view.colour_by = take_colour_by(args);
  o.export_vtk = args.value("--export-vtk");
  o.record = args.value("--record");
  o.stop_at_violation = args.flag("--stop-at-violation");
  if (const auto r = args.value("--rewind")) o.rewind = parse_rewind(*r);
  if (const auto mb = args.integer("--history-mb")) o.history_mb = *mb;
  if (const auto n = args.integer("--max-contacts")) o.max_contacts = *n;
  o.back = args.integer("--back").value_or(0);
  o.violation = args.integer("--violation").value_or(0);
  o.scaling = args.value("--scaling");
  if (o.scaling && *o.scaling == "run") {
    o.scaling_plan = take_scaling_plan_flags(args, o.algorithm, o.threads);
    o.scaling_plan.touching = o.touching;
  } else {
    for (const char* flag : {"--layout", "--n", "--points-per-decade"})
      if (args.has(flag)) throw Error(std::string(flag) + ": only with --scaling run");
  }
  args.finish();
  if (!scene) throw Error("headless: --scene FILE is required");
  for (const std::string& name : split_names("--algorithm", o.algorithm))
    if (name == kRecordedAlgorithm)
      throw Error("--algorithm recorded: the pairs a recording carries (nbscope replay FILE.nbsrec); a scene has none");
  if (o.scaling) check_headless_scaling(*o.scaling, o.view);
  o.scene = resolve_scene_path(*scene);  // `--scene pile.json`: the bundled one, from any directory
  if (o.rewind && o.rewind->from > o.frames)
    throw Error("--rewind: FROM " + std::to_string(o.rewind->from) + " is past the end of the run (--frames " +
                std::to_string(o.frames) + ")");
  if (o.rewind && o.record) throw Error("--rewind: --record writes frames as they run; record a straight run");
  if (o.rewind && o.stop_at_violation) throw Error("--rewind: and --stop-at-violation are two runs; give one");
  if (o.back > o.frames)
    throw Error("--back: " + std::to_string(o.back) + " is more than the " + plural(o.frames, "frame") + " run");
  if (o.back > 0 && o.stop_at_violation) throw Error("--back: --stop-at-violation shows the violation's frame itself");
  if (o.violation > 0 && (o.stop_at_violation || o.back > 0))
    throw Error("--violation: goes to a violation's own frame; --back and --stop-at-violation choose another");
  check_stop_at_violation(o);
  check_colour_by_drawn(o.view);
  return o;
}

void check_stop_at_violation(const HeadlessOptions& o) {
  if (!o.stop_at_violation) return;
  if (o.algorithm == "all" || o.algorithm.find(',') != std::string::npos)
    throw Error("--stop-at-violation: shows one algorithm's violation; name one (got '" + o.algorithm + "')");
  if (o.view.step) throw Error("--step: --stop-at-violation puts the stepper at the violation's operation");
}

namespace {

// Before any frame runs: every output writable, none the same file as another or as an input.
void check_headless_paths(const HeadlessOptions& o) {
  if (o.report) check_output_path(*o.report);  // before any frame runs
  if (o.record) check_output_path(*o.record);
  {
    std::vector<NamedPath> outputs;
    if (o.report) outputs.push_back({"--report", *o.report});
    if (o.record) outputs.push_back({"--record", *o.record});
    if (o.export_vtk) outputs.push_back({"--export-vtk", *o.export_vtk + "/series.pvd"});
    if (o.view.screenshot) outputs.push_back({"--screenshot", *o.view.screenshot});
    std::vector<NamedPath> inputs{o.replay ? NamedPath{"recording", *o.replay} : NamedPath{"--scene", o.scene}};
    if (o.dump) {  // every file a glob names: `--record atoms.1000.dump` must not overwrite one
      inputs.clear();
      for (const auto& [flag, specs] : {std::pair{"--dump", &o.dump->dumps}, std::pair{"--contacts", &o.dump->contacts}})
        for (const std::string& spec : *specs)
          for (std::string& p : expand_dump_spec(flag, spec)) inputs.push_back({flag, std::move(p)});
    }
    if (o.scaling && *o.scaling != "run") inputs.push_back({"--scaling", *o.scaling});
    check_outputs_distinct(inputs, outputs);
  }
}

// The run's loop: its history budget, the scene or recording loaded, the algorithms set (`names`: the
// loop's own first, then those compared beside it; `note` says what was chosen and why).
std::unique_ptr<FrameLoop> open_headless_loop(const HeadlessOptions& o, std::vector<std::string>& names, std::string& note) {
  check_step_algorithm(o.view, o.algorithm);  // before any frame runs
  check_stop_at_violation(o);
  std::string other_dim;
  names = algorithms_of(o.algorithm, 0, 2, o.brute_limit, note, false, other_dim);
  FrameLoopOptions lo;
  lo.algorithm = o.algorithm == "all" ? "nbs" : names.front();
  lo.fault = o.fault;
  lo.brute_limit = o.brute_limit;
  lo.touching = o.touching;
  lo.threads = o.threads;
  lo.max_contacts = o.max_contacts;
  // Past frames are kept when the run goes back to one, or draws the Timeline as the window would
  // (the window's default budget), or the user asks for a budget; else none.
  const bool keep = o.rewind || o.view.screenshot || o.back > 0 || o.violation > 0;
  lo.history_budget = static_cast<std::size_t>(o.history_mb.value_or(keep ? 256 : 0)) << 20;
  // Nor the summaries (~100 bytes a frame) or the violation log then: a long run's memory stays that
  // of its first frames. A recording's frames are all summaries from the start (each is showable),
  // so replay keeps them.
  if (!keep && !o.history_mb && !o.replay) {
    lo.max_summaries = 16;
    lo.log_violations = false;  // nothing shows the run's violations again (the report has them)
    lo.track_cell_changes = false;  // nor flashes
  }
  auto owned = std::make_unique<FrameLoop>(lo);  // an unknown algorithm fails here, before the scene is read
  FrameLoop& loop = *owned;
  // A plugin's violation is located in the trace of its frame's one detection, not of a second call.
  if (traces_every_frame(lo.algorithm)) loop.pipeline().record_traces(true);
  for (const std::string& name : names)
    if (name != kRecordedAlgorithm) make_detector(name);
  if (o.replay) loop.load_recording(read_replay_input(o));
  else load_scene_file(loop, o.scene);
  if (o.algorithm == "all") {
    const int dim = loop.source().elements().dim;
    other_dim.clear();
    names = algorithms_of(o.algorithm, loop.source().elements().size(), dim, o.brute_limit, note, loop.source().carries_pairs(), other_dim);
    // One line, before the run's: 'all' is every detector these frames can run.
    if (!other_dim.empty())
      std::fprintf(stderr, "nbscope: note: --algorithm all: %s left out (%s only; the frames are %dD)\n", other_dim.c_str(),
                   dim == 3 ? "2D" : "3D", dim);
    loop.redetect_with_algorithm(names.front());
  } else if (o.algorithm_from_recording && loop.source().carries_pairs()) {
    // No --algorithm: a recording that carries the user's pairs is replayed to check them.
    names = {std::string(kRecordedAlgorithm)};
    check_step_algorithm(o.view, names.front());
    loop.redetect_with_algorithm(names.front());
  }
  if (loop.source().carries_pairs() && loop.source().pair_base() != 0)
    note += (note.empty() ? "" : "; ") + std::string("element ids are 0-based rows here; the recording numbers its pairs from ") +
            std::to_string(loop.source().pair_base());
  loop.redetect_with_comparisons(std::vector<std::string>(names.begin() + 1, names.end()));
  if (o.stop_at_violation && nothing_to_check(loop))
    throw Error("--stop-at-violation: " + (o.replay ? *o.replay : o.scene) +
                " has no elements in any frame (and nothing adds any): there is nothing to check");
  return owned;
}

// The run's report before its first frame: what runs, on what, checked how.
RunReport start_report(const HeadlessOptions& o, const FrameLoop& loop, const std::vector<std::string>& names, const std::string& note) {
  RunReport report;
  report.source = o.watch ? "watch" : o.dump ? "dump" : o.replay ? "recording" : "scene";
  report.touching = o.touching == Touching::strict ? "strict" : "inclusive";
  report.frame_unit = frame_unit_of(loop.source());
  report.units = o.view.units;
  report.scene_path = o.replay ? *o.replay : o.scene;
  report.scene_name = loop.source().scene().name;
  report.fault = fault_name(o.fault);
  report.fault_description = fault_description(o.fault);
  report.reference_policy = loop.pipeline().reference_policy();
  report.scope_note = LoopPipeline::scope_note();
  report.note = note;
  // A recording runs its frames (at most --frames); a scene frames 0..N (--frames N steps). Frame 0
  // is detected and checked like every other, in the window and here: one numbering (issue 37).
  // A watched run: at most --frames of what arrives (the count is set once the run has ended).
  report.frames_requested = o.watch ? o.frames : o.replay ? loop.source().recorded_frames() : o.frames + 1;
  for (const std::string& name : names) report.runs.push_back(AlgorithmRun{name});
  return report;
}

}  // namespace

int run_headless_loop(const HeadlessOptions& o) {
  check_headless_paths(o);
  std::vector<std::string> names;
  std::string note;
  const std::unique_ptr<FrameLoop> owned = open_headless_loop(o, names, note);
  FrameLoop& loop = *owned;
  // The screenshot's context and shaders are set up first, so a bad --gl/--shader-dir/path fails at once.
  ViewOptions view_options = o.view;
  // Ids drawn as the recording's own pairs count them (the window does the same).
  view_options.book_numbering = view_options.book_numbering || (loop.source().carries_pairs() && loop.source().pair_base() == 1);
  if (o.scaling) view_options.scaling = scaling_to_show(*o.scaling, o.scaling_plan, !o.quiet && ::isatty(STDERR_FILENO) == 1);
  std::unique_ptr<HeadlessView> view = o.view.screenshot ? make_headless_view(view_options, loop) : nullptr;

  RunReport report = start_report(o, loop, names, note);
  const std::int64_t frames = report.frames_requested;
  if (o.replay && o.back >= frames)  // before the frames run: a recording's first frame is as far back as it goes
    throw Error("--back: " + std::to_string(o.back) + " goes before the first recorded frame (" + plural(frames, "frame") + " replayed: at most " +
                std::to_string(frames - 1) + " back)");
  // Each frame's report is aggregated, and streamed to --report, as it is made: nothing per frame stays in memory.
  std::unique_ptr<RunReportWriter> writer = o.report ? std::make_unique<RunReportWriter>(*o.report, names.size(), report.box2d_fields()) : nullptr;
  const auto add_frame = [&] {
    const auto add = [&](std::size_t r, const FrameReport& f) {
      report.runs[r].add(f);
      if (writer) writer->add_frame(r, f, loop.result().ids.get());
    };
    for (std::size_t a = 0; a < 3; ++a) report.periodic[a] = report.periodic[a] || loop.source().elements().box.periodic[a];
    add(0, loop.result().report());
    for (std::size_t lane = 1; lane < loop.result().lanes.size(); ++lane) add(lane, loop.result().lanes[lane].report);
  };
  // --rewind FROM:TO: the report as it stood after frame TO (restored at FROM, as if the frames after
  // TO had not run), and the first pass's element hashes of frames TO+1..FROM to compare the second with.
  struct AtTo {
    std::vector<AlgorithmRun> runs;
    RunReportWriter::Mark mark;
  };
  std::optional<AtTo> at_to;
  std::vector<std::uint64_t> first_pass;
  Divergence second_pass;  // against the first, as a resume checks against the history (physics/resume.hpp)
  const auto save_at_to = [&] { at_to = AtTo{report.runs, writer ? writer->mark() : RunReportWriter::Mark{}}; };

  // The recording: the source's pinned grid, then frame 0 (the initial poses, detected before any step) and every step.
  std::unique_ptr<FrameRecorder> recorder;
  // Ctrl+C, SIGTERM or SIGHUP while recording: the loop stops at the next frame and throws, so the
  // recording's temporary file is removed and no half recording remains (exit 2, one error line).
  // Without --record nothing needs it: the report's temporary exists only while it is written at the
  // end, and io/signals' handler removes it if a signal comes then.
  std::optional<StopOnSignals> interrupts;
  if (o.record) {
    const std::string from = o.dump     ? "replay --record: dumps " + *o.replay
                             : o.replay ? "replay --record: recording " + *o.replay
                                        : "headless --record: scene " + o.scene;
    recorder = std::make_unique<FrameRecorder>(*o.record, loop, std::string("nbscope ") + kVersion + " " + from);
    interrupts.emplace();
  }
  const auto check_interrupt = [&] {
    if (stop_signal() != 0)
      throw Error("interrupted: " + *o.record + " not written (" + signal_name(stop_signal()) + "; a recording is whole or not at all)");
  };

  const std::unique_ptr<VtkSeries> vtk = o.export_vtk ? std::make_unique<VtkSeries>(*o.export_vtk) : nullptr;  // DIR made now
  Progress progress(!o.quiet && ::isatty(STDERR_FILENO) == 1 && !o.watch, frames);  // a watched run's length is not known
  WriteToCheck latency;  // a watched run's frames: from their write to their check
  SubdomainTally subdomains;  // per-rank dumps: missing contacts across subdomain boundaries
  const double watch_start = wall_seconds();
  bool rewound = false;
  for (std::int64_t k = 0; k < frames; ++k) {
    // The screenshot's lists and stepper read the last frame's trace: its one detection records it.
    if (view && k + 1 == frames) loop.pipeline().record_traces(true);
    if (k > 0) {  // the first frame was detected and checked on load
      const std::uint64_t before = loop.change().generation;
      loop.step();
      if (loop.change().generation == before) break;  // no next frame: a watched run has ended
    }
    add_frame();
    latency.add(loop.source().written_at(), watch_start);
    subdomains.add(loop.result().report(), loop.source().elements(), loop.source().ranks());
    AlgorithmRun& own = report.runs.front();  // the loop's own algorithm, the one traced
    if (own.first_listed && !own.located) own.located = locate_violation(loop, *own.first_listed);
    if (recorder) {
      check_interrupt();
      recorder->write(loop);
    }
    if (vtk) vtk->add(vtk_frame_of(loop.source().elements(), loop.result()));
    progress.update(k + 1);
    if (o.rewind && !rewound) {
      if (loop.source().frame() == o.rewind->to) save_at_to();
      else if (loop.source().frame() > o.rewind->to) first_pass.push_back(loop.result().report().hash);
    } else if (rewound && loop.source().frame() > o.rewind->to && !report.rewind->diverged_at) {
      const auto index = static_cast<std::size_t>(loop.source().frame() - o.rewind->to - 1);
      if (index < first_pass.size()) second_pass.compare(loop.source().frame(), first_pass[index], loop.result().report().hash);
      report.rewind->diverged_at = second_pass.first();
    }
    if (o.stop_at_violation && loop.result().report().violation_count() > 0) {
      report.stopped_at = loop.source().frame();
      break;
    }
    if (o.rewind && !rewound && loop.source().frame() == o.rewind->from) {
      rewind_for_flag(loop, *o.rewind, report);
      report.runs = at_to->runs;
      if (writer) writer->back_to(at_to->mark);
      rewound = true;
      k = o.rewind->to;  // the frames after TO run again (frame k is the loop's k-th)
    }
  }
  progress.finish();
  if (o.watch) report.frames_requested = report.runs.front().frames_run;  // every frame that arrived was run
  if (vtk) vtk->finish();
  if (recorder) {
    interrupts.reset();  // from here a signal ends the process, and io/signals removes the temporary
    check_interrupt();
    recorder->commit();
  }
  // --back K: through the history, one kept frame at a time, each detected and checked again.
  double back_ms = 0;
  for (std::int64_t k = 0; k < o.back; ++k) {
    const auto t0 = Clock::now();
    step_back_for_flag(loop);
    back_ms += ms_since(t0);
  }
  if (o.violation > 0) go_to_violation(loop, o.violation, view.get());
  std::string screenshot_line;
  if (view) {
    if (report.stopped_at) view->focus_violation(loop, loop.result().report().violations.front());
    screenshot_line = view->write_screenshot(loop);
  }
  if (writer) writer->commit(report);
  // Notes on stderr only once every output is written: an error is then the only line there.
  if (!screenshot_line.empty()) std::fprintf(stderr, "nbscope: %s\n", screenshot_line.c_str());
  if (!o.notice.empty()) std::fprintf(stderr, "nbscope: %s\n", o.notice.c_str());
  const std::string summary = headless_summary(o, loop, report, back_ms) + subdomains.text() + latency.text();
  std::printf("%s\n", summary.c_str());
  for (const AlgorithmRun& run : report.runs)  // a simulation's list that is mostly not contacts: say what it likely is
    if (const std::string hint = apart_pairs_hint(run.apart, run.pairs, run.apart_gap_max); !hint.empty()) std::printf("%s\n", hint.c_str());
  return report.passed() ? 0 : 1;
}

int run_headless(Args& args) { return run_headless_loop(parse_headless_options(args)); }

}  // namespace nbscope

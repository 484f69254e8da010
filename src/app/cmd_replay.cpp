// `nbscope replay FILE.nbsrec`: the frames of a recording (nbscope headless --record, or any
// simulation code writing the documented text format) detected and checked again, with any
// algorithm; headless by default without a window, in the window when there is one.
#include <cstdio>
#include <limits>

#include "app/colour_by.hpp"
#include "app/commands.hpp"
#include "app/replay.hpp"
#include "app/threads_flag.hpp"
#include "core/error.hpp"
#include "io/recording.hpp"

namespace nbscope {

std::unique_ptr<RecordedFrames> read_replay_input(const HeadlessOptions& o) {
  if (o.watch) return watched_dumps(*o.watch);  // watch DUMPS (cmd_watch.cpp): a list that grows
  if (o.dump) return read_dump_recording(*o.dump, o.frames);
  if (o.input) return read_input_recording(*o.replay, *o.input, o.frames);  // gui --input (input_window.cpp)
  return read_recorded_frames(*o.replay, o.frames);
}

int run_replay(Args& args) {
  HeadlessOptions o;
  const bool headless = args.flag("--headless");
  o.frames = args.integer("--frames").value_or(std::numeric_limits<std::int64_t>::max());
  const auto algorithm = args.value("--algorithm");
  o.algorithm = algorithm.value_or(o.algorithm);
  o.algorithm_from_recording = !algorithm;  // recorded when the file carries pairs, else nbs
  o.report = args.value("--report");
  if (const auto f = args.value("--inject-fault")) o.fault = parse_fault(*f);
  o.brute_limit = args.integer("--brute-limit").value_or(o.brute_limit);
  o.quiet = args.flag("--quiet");
  o.stop_at_violation = args.flag("--stop-at-violation");
  o.record = args.value("--record");
  o.back = args.integer("--back").value_or(0);
  o.violation = args.integer("--violation").value_or(0);
  if (const auto mb = args.integer("--history-mb")) o.history_mb = *mb;
  o.touching = take_touching(args);
  o.threads = take_threads(args);
  DumpFlags dump = take_dump_flags(args);
  dump.dumps = args.values("--dump");
  dump.contacts = args.values("--contacts");
  dump.dt = args.number("--dt");  // positive: its row's range
  const bool window = !headless && replay_window_available();
  parse_view_options(args, !window, o.view);
  o.view.colour_by = take_colour_by(args);
  o.export_vtk = args.value("--export-vtk");
  dump.options.keep_columns = o.view.colour_by || o.export_vtk;  // the dump's other columns colour and are exported
  const auto file = args.positional();  // after the flags, so a flag's value is not taken for it
  if (const auto extra = args.positional()) {
    // `--dump atoms.*.dump` unquoted: the shell made the glob's files into words.
    if (!dump.dumps.empty() || !dump.contacts.empty())
      throw Error("replay: " + *extra + ": unexpected argument (a glob the shell expanded? quote it: --dump 'atoms.*.dump')");
    throw Error("replay: " + *extra + ": unexpected argument (one recording at a time)");
  }
  args.finish();
  if (dump.contacts.empty() && (dump.columns.numbers || dump.columns.names))
    throw Error("--contact-ids: needs --contacts FILES (the dump local files whose columns it names)");
  if (!dump.dumps.empty() || !dump.contacts.empty()) {
    if (file)
      throw Error("replay: " + *file + ": give the frames either as FILE.nbsrec or with --dump, not both (a glob the shell expanded? quote it: --dump 'atoms.*.dump')");
    if (dump.dumps.empty()) throw Error("--contacts: needs --dump FILES (the frames the contacts belong to)");
    o.replay = dump.dumps.front();
    o.dump = std::move(dump);
  } else if (dump.columns.numbers || dump.columns.names || dump.dt || dump.options.radius || !dump.options.type_radius.empty() ||
             dump.options.force_2d || dump.options.tolerance || dump.options.periodic || dump.box) {
    throw Error("replay: --dt, --radius, --type-radius, --2d, --tolerance, --periodic and --box read dumps: they need --dump FILES");
  }
  if (!file && !o.dump) throw Error("replay: FILE.nbsrec or --dump FILES is required (nbscope replay FILE.nbsrec [--headless] ...)");
  // What the run's files say of it: its units, and a `dimension 2` run read as 2D.
  std::string planar;
  if (o.dump) {
    o.view.units = settle_units_and_log(*o.dump, o.dump->dumps);
    planar = settle_planar(*o.dump, o.dump->dumps);
  } else {
    o.view.units = settle_units_and_log(dump, {});
  }
  if (o.fault == Fault::DropBox2dContact)
    throw Error(std::string("--inject-fault ") + fault_name(o.fault) +
                ": recorded frames have no Box2D contact list (use drop-pair, drop-mask-cell, off-by-one-cell or stale-positions)");
  if (!o.dump) o.replay = *file;
  if (o.back > 0 && o.stop_at_violation) throw Error("--back: --stop-at-violation shows the violation's frame itself");
  if (o.violation > 0 && (o.stop_at_violation || o.back > 0))
    throw Error("--violation: goes to a violation's own frame; --back and --stop-at-violation choose another");
  if (window) {
    if (o.record) throw Error("--record: needs --headless (the window writes no recording)");
    if (o.export_vtk) throw Error("--export-vtk: needs --headless (the window plays frames back and forth: export a straight run)");
    if (o.back > 0 || o.violation > 0)
      throw Error(std::string(o.back > 0 ? "--back" : "--violation") + ": needs --headless (the window travels with its Timeline and Violations panel)");
    if (o.algorithm == "all" || o.algorithm.find(',') != std::string::npos)
      throw Error("--algorithm: the window shows one algorithm at a time (switch with 1..9); several need --headless");
    if (o.report) throw Error("--report: needs --headless (the window writes no report)");
    if (o.stop_at_violation)
      throw Error("--stop-at-violation: needs --headless (the window lists every violation in its Violations panel)");
    if (!planar.empty()) std::fprintf(stderr, "nbscope: %s\n", planar.c_str());
    return run_replay_window(o);
  }
  o.notice = planar;
  // Said after the run, not before it: when the recording is refused, the error is the only line.
  if (!headless) o.notice += std::string(o.notice.empty() ? "" : "\nnbscope: ") + "no window (no display, or built without it): replayed headless";
  check_colour_by_drawn(o.view);
  return run_headless_loop(o);
}

}  // namespace nbscope

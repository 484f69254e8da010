// `nbscope watch DUMPS`: the dumps of a LAMMPS or LIGGGHTS run that is still going, each frame
// checked as it lands (io/dump_watch.hpp: a frame is read once whole). The frames are a replay's
// (the same loop, window and headless run, the same report): only their list grows. docs/watch.md.
#include <cmath>
#include <cstdio>
#include <limits>

#include "app/colour_by.hpp"
#include "app/commands.hpp"
#include "app/replay.hpp"
#include "app/threads_flag.hpp"
#include "core/error.hpp"

namespace nbscope {

int run_watch(Args& args) {
  HeadlessOptions o;
  const bool headless = args.flag("--headless");
  o.frames = args.integer("--frames").value_or(std::numeric_limits<std::int64_t>::max());
  const auto algorithm = args.value("--algorithm");
  o.algorithm = algorithm.value_or(o.algorithm);
  o.algorithm_from_recording = !algorithm;  // recorded when --contacts gives the code's pairs, else nbs
  o.report = args.value("--report");
  if (const auto f = args.value("--inject-fault")) o.fault = parse_fault(*f);
  o.brute_limit = args.integer("--brute-limit").value_or(o.brute_limit);
  o.quiet = args.flag("--quiet");
  o.stop_at_violation = args.flag("--stop-at-violation");
  if (const auto mb = args.integer("--history-mb")) o.history_mb = *mb;
  o.touching = take_touching(args);
  o.threads = take_threads(args);
  DumpFlags dump = take_dump_flags(args);
  DumpWatchSpec spec;
  spec.contacts = args.values("--contacts");
  spec.dt = args.number("--dt");
  const auto idle = args.number("--idle");
  o.view.colour_by = take_colour_by(args);
  o.export_vtk = args.value("--export-vtk");
  dump.options.keep_columns = o.view.colour_by || o.export_vtk;  // the dump's other columns colour and are exported
  const bool window = !headless && replay_window_available();
  parse_view_options(args, !window, o.view);
  const auto dumps = args.positional();
  if (const auto extra = args.positional())
    throw Error("watch: " + *extra + ": unexpected argument (a glob the shell expanded? quote it: nbscope watch 'atoms.*.dump')");
  args.finish();
  if (!dumps) throw Error("watch: DUMPS is required (nbscope watch 'post/atoms.*.dump' [--contacts 'post/contacts.*.dump'])");
  if (dump.box) throw Error("--box: " + *dumps + " is a dump: its box is its BOX BOUNDS (--periodic x,y[,z] makes axes periodic)");
  if (spec.contacts.empty() && (dump.columns.numbers || dump.columns.names))
    throw Error("--contact-ids: needs --contacts FILES (the dump local files whose columns it names)");
  if (o.fault == Fault::DropBox2dContact)
    throw Error(std::string("--inject-fault ") + fault_name(o.fault) + ": dump frames have no Box2D contact list");
  o.view.units = settle_units_and_log(dump, {});  // --units, --log (the dumps themselves may not exist yet)
  spec.dumps = {*dumps};
  spec.columns = dump.columns;
  spec.options = dump.options;
  spec.options.max_frames = o.frames;
  // Headless ends with the run (no new frame for --idle S, default 60, or the writer gone); the window
  // follows it until it is closed, unless --idle is given.
  spec.wait = !window;
  spec.idle_s = idle.value_or(window ? std::numeric_limits<double>::infinity() : 60.0);
  o.replay = *dumps;
  o.watch = std::move(spec);
  if (window) {
    if (o.report) throw Error("--report: needs --headless (the window writes no report)");
    if (o.stop_at_violation) throw Error("--stop-at-violation: needs --headless (the window lists every violation in its Violations panel)");
    if (o.algorithm == "all" || o.algorithm.find(',') != std::string::npos)
      throw Error("--algorithm: the window shows one algorithm at a time (switch with 1..9); several need --headless");
    if (o.export_vtk) throw Error("--export-vtk: needs --headless (the window plays frames back and forth: export a straight run)");
    if (o.view.screenshot) {
      // Scripted: the window runs until N frames have landed, saves the picture and ends.
      if (o.frames == std::numeric_limits<std::int64_t>::max())
        throw Error("--screenshot: the window needs --frames N (the frames to wait for; a run being written may not end)");
      o.view.frames = o.frames - 1;  // steps after the first frame
    }
    return run_replay_window(o);
  }
  if (!headless) o.notice = "no window (no display, or built without it): watched headless";
  check_colour_by_drawn(o.view);
  return run_headless_loop(o);
}

}  // namespace nbscope

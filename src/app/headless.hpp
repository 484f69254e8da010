// nbscope app: `nbscope headless` — the frame loop with no window. Options live in one struct parsed
// in one function, so later flags (--screenshot, --size, --step, --record, --gl) are one field and
// one line each.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "app/cli.hpp"
#include "app/dump_input.hpp"
#include "app/view_options.hpp"
#include "check/faults.hpp"
#include "check/report.hpp"
#include "core/scaling.hpp"
#include "io/dump_watch.hpp"

namespace nbscope {

class HeadlessView;
struct RunReport;

class FrameLoop;
class LoopSource;

struct HeadlessOptions {
  std::string scene;                  // --scene FILE (required)
  std::int64_t frames = 600;          // --frames N
  std::string algorithm = "nbs";      // --algorithm NAME[,NAME...] or "all": compared on the same frames
  bool algorithm_from_recording = false;  // replay without --algorithm: `recorded` when the recording
                                          // carries pairs (check/recorded_lane.hpp), else `algorithm`
  std::optional<std::string> report;  // --report OUT.json
  Fault fault = Fault::None;          // --inject-fault NAME
  std::int64_t brute_limit = 2000;    // --brute-limit N: R is brute force up to N elements
  bool quiet = false;                 // --quiet: no progress bar even on a terminal
  ViewOptions view;                   // --screenshot, --size, --gl, --overlays, ... (app/view_options.hpp)
  std::optional<std::string> record;  // --record OUT.nbsrec: every frame's elements (io/recording.hpp)
  std::optional<std::string> export_vtk;  // --export-vtk DIR: every frame as VTK XML PolyData (app/export_vtk.hpp)
  std::optional<std::string> replay;  // `nbscope replay FILE`: recorded frames instead of a scene
                                      // (frames = at most that many of them)
  bool stop_at_violation = false;     // --stop-at-violation: stop on the first frame with a violation,
                                      // show it (pair, Violations panel, stepper) and exit 1
  struct Rewind {
    std::int64_t from = 0, to = 0;
  };
  std::optional<Rewind> rewind;       // --rewind FROM:TO: at frame FROM go back to TO and resume
  std::int64_t violation = 0;         // --violation N: after the run, go to its N-th violation (from 1, as
                                      // the Violations panel lists them) and show it as choosing it there does
  std::int64_t back = 0;              // --back K: after the frames, K frames back through the history
                                      // (each shown, detected and checked again); the screenshot shows it
  std::optional<std::string> scaling;  // --scaling FILE.csv | run: the Scaling panel in the screenshot
  ScalingPlan scaling_plan;            // --scaling run: --algorithm, --layout, --n, --points-per-decade
  std::string notice;                  // a line for stderr once the run has ended without an error
                                       // (replay: why no window opened); "" for none
  std::optional<std::int64_t> history_mb;  // --history-mb N: memory for kept frames (default: 256 with
                                           // --rewind, --back, --violation or --screenshot, else none)
  std::optional<std::int64_t> max_contacts;  // --max-contacts N: Box2D contacts a frame may create
  Touching touching = Touching::inclusive;   // --touching: whether a pair at zero gap is a contact
  int threads = 1;                           // --threads N: threads one detection may use (and --scaling run's plan)
  std::optional<DumpFlags> dump;             // replay --dump: frames from LAMMPS/LIGGGHTS dumps (`replay` names the first)
  std::optional<DumpFlags> input;            // gui --input FILE: ELEMENTS.csv or a dump (`replay` names it), no pairs
  std::optional<DumpWatchSpec> watch;        // watch DUMPS: a run still being written (`replay` names it), frames = at most that many
};

// The frames `options.replay` names: a .nbsrec, or the dumps of options.dump (read as they are
// shown: io/dump_frames.hpp); at most options.frames frames.
std::unique_ptr<RecordedFrames> read_replay_input(const HeadlessOptions& options);

// Error when --stop-at-violation is combined with what it cannot show (several algorithms, --step).
void check_stop_at_violation(const HeadlessOptions& options);
// One frame back through `loop`'s history for --back (headless and the window alike); Error when
// the frame shown is the oldest kept.
void step_back_for_flag(FrameLoop& loop);
// --violation N: the run's N-th listed violation's frame shown again, and (`view`, when drawing) the
// violation chosen as in the Violations panel. Error when there is none or it is no longer kept.
void go_to_violation(FrameLoop& loop, std::int64_t n, HeadlessView* view);
// --rewind FROM:TO at frame FROM: back to kept frame TO, the world re-simulated to it, the resume's
// divergence into report.rewind (the caller puts the report back as it stood after frame TO).
void rewind_for_flag(FrameLoop& loop, const HeadlessOptions::Rewind& rewind, RunReport& report);
// Violation `v` of the frame `loop` shows, followed to the operation of its traced detection that
// decided it (check/diagnosis.hpp); none for another frame or a detection that records nothing
// (recorded pairs, box2d, over 50,000 elements). headless_locate.cpp.
std::optional<LocatedViolation> locate_violation(FrameLoop& loop, const Violation& v);
// True when `algorithm` is a plugin that traces: a headless run records every frame's trace in its
// one detection, so that locating a violation calls the plugin no second time for that frame.
bool traces_every_frame(const std::string& algorithm);
// "FROM:TO" of --rewind; Error names the flag and what is wrong.
HeadlessOptions::Rewind parse_rewind(const std::string& text);

// What `source`'s frames are called: a dump's are timesteps (Recording::frame_unit), else frames.
FrameUnit frame_unit_of(const LoopSource& source);
// The one line on stdout after the run (headless_summary.cpp): what ran, whether every invariant
// held, where it broke, the mean timings; --back's cost (`back_ms` in all) and --violation's pair.
std::string headless_summary(const HeadlessOptions& options, const FrameLoop& loop, const RunReport& report, double back_ms);

// Reads every headless flag from `args` and refuses leftovers; throws Error on bad values.
HeadlessOptions parse_headless_options(Args& args);
// Runs the frames (of the scene, or of the recording when `replay` is set); prints the one-line summary on stdout (progress on stderr when it is a
// terminal); writes the report. Returns 0 when every frame passed, 1 when a check failed.
int run_headless_loop(const HeadlessOptions& options);

}  // namespace nbscope

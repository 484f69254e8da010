// The command table's rows: the window's commands (gui, headless, replay) here, the file commands
// (pairs, dump, verify, scaling, algorithms) in command_table_files.cpp.
#include "app/command_table.hpp"

#include "app/colour_by.hpp"
#include "app/command_table_parts.hpp"
#include "app/commands.hpp"
#include "app/dump_input.hpp"
#include "app/export_vtk.hpp"
#include "app/threads_flag.hpp"
#include "physics/scene.hpp"

namespace nbscope {

const std::vector<OptionSpec>& rendering_options() {
  static const std::vector<OptionSpec> options = {
      {"--overlays", "SPEC", "", "comma list: all, none, NAME (only the names listed), +NAME, -NAME; names: bodies elements grid lists mask "
                                 "pairs checks broadphase ids trails flash"},
      {"--panels", "SPEC", "", "the same for panels: controls scenes algorithm overlays stats selection metrics violations timeline "
                               "stepper pseudocode arrays scaling"},
      {"--select", "K", "", "select element K as shown (its cell, lists and pairs highlighted, its trail drawn): from 0, or from 1 with "
                            "--book-numbering; on a dump's frames, the atom id K", integer_value(0, 100'000'000)},
      {"--lists", "FILTER", "row past 300 elements, else all",
       "the lists overlay draws all lists, the selected element's, or one row's (all | selected | row)",
       choice_value({"all", "selected", "row"})},
      {"--layer", "K|auto", "auto",
       "the layer of a 3D frame shown (from 0, the bottom; K past the top layer, or on a 2D frame, is an error); auto: the "
       "selected or violating pair's layer, else the selected element's, else the busiest (Up/Down move it in the window)"},
      {"--camera", "X,Y,PPM", "", "put (X, Y) in the middle of the view the panels leave free, at PPM pixels per metre, instead of fitting "
                                  "the scene"},
      {"--no-timings", "", "", "show \"-\" for wall-clock numbers (reproducible screenshots)", flag_value()},
      {"--step", "K", "", "open the Stepper, Arrays and Pseudocode panels on the state after K operations of the last frame's detection "
                          "of one algorithm that records them (not box2d); K past its last operation is an error (headless: needs "
                          "--screenshot)", integer_value(0, std::int64_t{1} << 53)},
      {"--book-numbering", "", "", "number elements and cells from 1 everywhere, as the book does", flag_value()},
      {"--shader-dir", "DIR", "$NBSCOPE_SHADER_DIR if set, else $NBSCOPE_DATA_DIR/shaders, else an installed share/nbscope/shaders "
                              "beside the binary, else the source tree's shaders/ (nbscope --version says which)",
       "GLSL sources"},
  };
  return options;
}

const std::vector<OptionSpec>& grid_options() {
  static const std::vector<OptionSpec> options = {
      {"--cell-size", "D", "cells of the largest diameter", "pins the grid's cell size (D must be at least the largest diameter)",
       number_value()},
      {"--origin", "X,Y[,Z]", "the smallest centre coordinates", "pins the grid's origin"},
      {"--cells", "NX,NY[,NZ]", "", "pins the number of cells per axis (the book's Fig. 3.15 is --cell-size 1 --origin 0,0 --cells 10,10)"},
  };
  return options;
}

const std::vector<OptionSpec>& plugin_options() {
  static const std::vector<OptionSpec> options = {
      {"--detector-lib", "PATH.so", "",
       "loads a detector plugin (include/nbscope/detector.h), named as a built-in (or by its file name); repeatable; "
       "without --algorithm, the one run. One unusable stops the run (exit 2); a detection that breaks the API, crashes "
       "or hangs is its frame's violation", repeated_value()},
      {"--detector-timeout", "SECONDS", "60",
       "how long one call into a plugin (its load, describe, detect, release, own_bytes) may take (0: no limit)",
       number_value(0, 1e6, "the seconds must be from 0 (no limit) to 1e6")},
      {"--detector-isolation", "process|none", "process",
       "where a plugin's calls run: in a host process of its own (a crash or a write out of bounds takes only the host "
       "down: nbscope starts a new one), or in nbscope's process (cheaper; a crash in a detection then ends the run, exit 2)",
       choice_value({"process", "none"}, "{} is not process or none")},
  };
  return options;
}

OptionSpec gl_option() {
  return {"--gl", "osmesa|egl|auto", "auto",
          "the off-screen GL of --screenshot: OSMesa or EGL (surfaceless); auto takes OSMesa when libOSMesa.so.8 is there, else EGL",
          choice_value({"osmesa", "egl", "auto"})};
}

namespace {

// gui --input's dump flags: the dump's own (no --timestep: every frame is shown; --contact-ids hidden:
// taken only to be refused with its reason, gui --input reads no contacts).
const std::vector<OptionSpec>& gui_input_options() {
  static const std::vector<OptionSpec> options = [] {
    std::vector<OptionSpec> o;
    for (const OptionSpec& s : dump_input_options())
      if (std::string_view(s.name) != "--timestep") o.push_back(s);
    for (OptionSpec& s : o) s.hidden = std::string_view(s.name) == "--contact-ids";
    return o;
  }();
  return options;
}

}  // namespace

OptionGroup rendering_group() { return {"rendering options (gui, headless, replay, verify --screenshot)", rendering_options()}; }
OptionGroup plugin_group() { return {kPluginOptionsTitle, plugin_options()}; }
OptionGroup dump_input_group() { return {"--input FILE.dump: a LAMMPS or LIGGGHTS dump, or a LAMMPS data file (docs/dem.md)", dump_input_options()}; }
OptionGroup dump_replay_group() { return {"frames from LAMMPS and LIGGGHTS dumps (docs/dem.md)", dump_replay_options()}; }
OptionGroup gui_input_group() { return {"gui --input FILE (without --arrays): a dump or ELEMENTS.csv", gui_input_options()}; }

std::vector<OptionSpec> joined(std::initializer_list<std::vector<OptionSpec>> parts) {
  std::vector<OptionSpec> out;
  for (const std::vector<OptionSpec>& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

namespace {

// `nbscope [gui]`: the window.
CommandSpec gui_command() {
  std::vector<OptionSpec> arrays = {
      {"--input", "ELEMENTS.csv", "", "with --arrays: the elements the arrays index (x,y,r a line); without --arrays: ELEMENTS.csv "
                                      "(x,y,r or x,y,z,r) or a dump, opened in the window"},
      {"--arrays", "ARRAYS.json", "", "with --input: your heads and next arrays, in the schema dump writes (see verify --arrays)"},
      {"--base", "1", "0", "the arrays count elements from 1 (numbered as the file counts: from 1)", integer_value(0, 1)},
      {"--exact", "", "", "also the book's order within every list (as verify --exact)", flag_value()},
  };
  arrays.insert(arrays.end(), grid_options().begin(), grid_options().end());
  return {
      "gui",
      run_gui,
      "the window: Box2D bodies, the grid, the detector's lists, pairs and checks (default)",
      {"nbscope [gui] [--scene FILE] [--algorithm NAME] [--inject-fault NAME] [--size WxH] [--history-mb N]",
       "              [--frames N [--back K] --screenshot OUT.png] [--overlays SPEC] [--panels SPEC] [--select K]",
       "              [--max-contacts N]",
       "nbscope gui --input ELEMENTS.csv|FILE.dump [--algorithm NAME] [--inject-fault NAME] [--layer K|auto]",
       "            [--frames N --screenshot OUT.png] [--overlays SPEC] [--panels SPEC] [--select K]",
       "nbscope gui --input ELEMENTS.csv --arrays ARRAYS.json [--algorithm NAME] [--base 1] [--exact]",
       "            [--cell-size D] [--origin X,Y] [--cells NX,NY] [--frames N --screenshot OUT.png]",
       "            [--overlays SPEC] [--panels SPEC] [--select K]"},
      {"The window (default: the last scene and algorithm used, else assets/scenes/default.json and nbs; $NBSCOPE_DATA_DIR overrides "
       "where assets/ is found): Box2D bodies, the cell grid, the detector's lists, pairs and check results over them, ImGui panels. "
       "`nbscope` alone, or with options only (`nbscope --scene F`), is `nbscope gui`.",
       "Keys: P play/pause, O single step, R restart, Home fit, 1..N algorithm (the Algorithm panel's numbers), Esc clear the selection, overlays B E G L M C K F I T H; "
       "the Timeline: , and . one frame back/forward (Shift: 10), J play backwards; the Violations panel: [ and ] previous/next, "
       "Shift+[ the first; the Stepper (a paused frame): -> and <- one operation (Shift: one phase), Space play/pause, PageDown and "
       "PageUp the operation after/before on the selected element (Shift: on the selected cell); a 3D frame: Up and Down the layer above/below (see Help in the menu bar). Mouse: left "
       "selects an element and drags its body, right-drag pans, wheel zooms.",
       "Every frame is kept for the Timeline within --history-mb N (oldest frames dropped first). Settings persist in "
       "$XDG_CONFIG_HOME/nbscope/settings.json (~/.config/...); a stale one opens the window all the same, its bad keys named in one note.",
       "Without a display it renders --frames N (default 120) headless into --screenshot (default $TMPDIR/nbscope-SCENE.png) and prints "
       "the path.",
       "A world that stops (too many contacts, a body not finite or leaving the world: see headless --max-contacts), also at load, shows "
       "its message in the Scenes panel and pauses; with --frames the screenshot shows it and the exit code is 2.",
       "gui --input ELEMENTS.csv|FILE.dump without --arrays: the window on those elements (x,y,r or x,y,z,r a line; a dump's "
       "frames) as a recording without pairs, detected and checked as replay does; --frames N draws it N times (a one-frame input "
       "too: the frame rate is of redraws). A 3D frame is shown one layer of cells at a time, as NBS 3D works through it "
       "(--layer, Up/Down; docs/window.md).",
       "gui --input ELEMENTS.csv --arrays ARRAYS.json: your heads and next arrays, checked as verify --arrays checks them, in the window: "
       "your lists as arrow chains with their heads named (C[5][7]), every problem in red (the wrong link, the elements at fault ringed, "
       "a cut list's end), the first problem selected and its text in the legend. Problems panel: a click selects one and puts the "
       "camera on it ([ and ] the previous/next); Lists panel: a click goes to the list; the hovered element's lists and problems in a "
       "tooltip. Numbered as the file counts (--base 1: from 1). Panels: overlays, problems, lists. Exit 0 right, 1 wrong. Without a "
       "display it renders headless into --screenshot (default $TMPDIR/nbscope-verify-ARRAYS.png) and prints the path."},
      {{"options",
        joined({{{"--scene", "FILE", "the last scene used, else assets/scenes/default.json", "the scene to simulate (assets/scenes/*.json)"},
         {"--algorithm", "NAME", "a --detector-lib's detector, else the last algorithm used, else nbs",
          "the detector (nbscope algorithms); with --arrays the arrays' algorithm, as verify --arrays"},
         {"--inject-fault", "NAME", "", "breaks the detection (or Box2D's side) on purpose, as headless --inject-fault"},
         {"--history-mb", "N", "256, saved with the settings", "memory for the frames the Timeline keeps", integer_value(0, 1'000'000)},
         {"--max-contacts", "N", "1,000,000", "the Box2D contacts a frame may create, as headless --max-contacts",
          integer_value(0, kMaxMaxContacts)},
         {"--frames", "N", "", "runs N frames of simulation (drawn at the window's own pace meanwhile; stderr gives both rates), "
                               "saves --screenshot and exits (no input, no settings: for tests under Xvfb); with "
                               "--arrays: the frames drawn before the screenshot", integer_value(0, kMaxFrames)},
         {"--back", "K", "", "with --frames: then goes K frames back through the history first, each drawn, and says how long a frame "
                             "took", integer_value(1, 100'000'000)},
         {"--screenshot", "OUT.png", "", "with --frames: the picture saved before exiting (without a display: where the headless "
                                         "rendering goes)"},
         {"--size", "WxH", "", "the window's (and the screenshot's) size in pixels; without it the window opens to the screen's work area, or at the size it last closed at (a scripted --frames run: 1280x720)"}},
                {threads_option(), touching_option(), colour_by_option()}})},
       gui_input_group(),
       {"your arrays (gui --input ELEMENTS.csv --arrays ARRAYS.json)", arrays},
       rendering_group(),
       plugin_group()},
      {"nbscope", "nbscope --scene assets/scenes/gas.json --algorithm sort",
       "xvfb-run nbscope gui --scene assets/scenes/pile.json --frames 60 --screenshot pile.png",
       "nbscope gui --input assets/examples/nine.csv --arrays assets/examples/nine_screen_bug.json"},
      "0 all well (gui --arrays: the arrays right), 1 gui --arrays: the arrays wrong, 2 bad input, or a world that stopped with "
      "--frames (one line on stderr)",
  };
}

// `nbscope headless`: a scene's frames with no window.
CommandSpec headless_command() {
  std::vector<OptionSpec> output = {
      {"--screenshot", "OUT.png", "",
       "renders the last frame exactly as the window shows it (scene, overlays, panels) off-screen, no display needed"},
      {"--size", "WxH", "", "the screenshot's size in pixels"},
      gl_option(),
  };
  return {
      "headless",
      run_headless,
      "runs a scene's frames with no window, each checked against Box2D and brute force",
      {"nbscope headless --scene FILE [--frames N] [--algorithm NAME[,NAME...]|all] [--report OUT.json]",
       "                 [--inject-fault NAME] [--brute-limit N] [--quiet] [--record OUT.nbsrec]",
       "                 [--stop-at-violation | --rewind FROM:TO] [--back K | --violation N] [--history-mb N]",
       "                 [--max-contacts N]",
       "                 [--scaling FILE.csv | --scaling run [--layout L] [--n MIN..MAX] [--points-per-decade K]]",
       "                 [--screenshot OUT.png [--size WxH] [--gl osmesa|egl|auto] [rendering options]]"},
      {"Runs N frames of a scene (assets/scenes/*.json) with no window: Box2D steps, the algorithm detects, and every frame is checked: "
       "A==R (R: brute force up to --brute-limit elements, then sort, or nbs when sort is tested; brute itself is checked against sort), "
       "A-in-F (Box2D's contact list, its filters applied to A), T-in-A (shapes touching now), AABB-in-cells (tight-AABB pairs in "
       "neighbouring cells). One summary line on stdout; a progress bar on stderr when it is a terminal. Exit 1 if any check failed.",
       "Several algorithms (a,b,c or all: every 2D detector) run and are checked on the same frames.",
       "A frame running over 5 s (or 10 frames together) says so once on stderr. A body that is not finite after a step, or beyond "
       "+-1e6 m, stops the run with exit 2 naming the body and the frame."},
      {{"options",
        joined({{{"--scene", "FILE", "", "the scene to run (required)"},
         {"--frames", "N", "600", "the steps to run: frames 0..N, frame 0 (the initial poses) checked and counted too",
          integer_value(1, kMaxFrames)},
         {"--algorithm", "NAME[,NAME...]|all", "the --detector-lib detectors, else nbs", "the detectors run and checked on the same frames"},
         {"--report", "OUT.json", "", "writes per-frame counts, timings and every violation as JSON"},
         {"--inject-fault", "NAME", "",
          "drop-mask-cell | off-by-one-cell | stale-positions | drop-pair | drop-box2d-contact breaks the detection (or Box2D's "
          "side) on purpose: proofs that each invariant can fail. Bugs in a detector's own code, to follow to the operation that "
          "lost a pair, are the plugins of examples/detectors/ (--detector-lib)"},
         {"--brute-limit", "N", "2000", "the elements up to which brute force is the reference R (sort above)", integer_value(0, 1'000'000)},
         {"--quiet", "", "", "no progress bar", flag_value()},
         {"--record", "OUT.nbsrec", "", "writes every frame's elements (frame 0 too) and the scene's pinned grid"},
         {"--stop-at-violation", "", "",
          "stops on the first frame with a violation and (with --screenshot) shows it as the window's Violations panel does: the pair "
          "selected, the camera on it, the stepper at the operation that decided it; exit 1, or 0 when no frame broke (one algorithm "
          "only)", flag_value()},
         {"--rewind", "FROM:TO", "",
          "runs to frame FROM, goes back to kept frame TO and resumes to --frames: the frames after TO are simulated again "
          "(deterministically, from the scene) and replace the first ones; every report frame carries \"hash\", the hash of its "
          "elements, so a rewound run can be compared with a straight one frame by frame"},
         {"--back", "K", "", "after the last frame goes K frames back through the history (each detected and checked again); "
                             "--screenshot then shows that frame", integer_value(1, 100'000'000)},
         {"--violation", "N", "", "instead of --back, goes to the run's N-th violation (from 1, as the Violations panel lists them) and shows it as "
                                  "choosing it there does", integer_value(1, 1'000'000'000)},
         {"--history-mb", "N", "256 with --rewind, --back, --violation or --screenshot, else 0",
          "memory for kept frames (0: a run that never goes back keeps only summaries)", integer_value(0, 1'000'000)},
         {"--max-contacts", "N", "1,000,000, ~1.7 GB",
          "the Box2D contacts a frame may create (the scene's \"max_contacts\" sets it too): before every step the pairs of fat AABBs "
          "are counted and a world past it stops with exit 2 naming the count; no more than the memory this process can get (rlimits, "
          "cgroup, MemAvailable) at ~1.7 kB a contact, whatever N says", integer_value(0, kMaxMaxContacts)},
         {"--scaling", "FILE.csv|run", "",
          "(with --screenshot) opens the Scaling panel on a CSV of nbscope scaling (a bad row: exit 2 naming FILE:LINE); --scaling run "
          "measures first, as nbscope scaling does, the detectors of --algorithm on --layout, --n and --points-per-decade (nbs at 1 "
          "and --threads threads)"},
         {"--layout", "L[,L...]", "loose", "with --scaling run: the layouts, as nbscope scaling --layout"},
         {"--n", "MIN..MAX", "1000..1000000", "with --scaling run: the sizes, as nbscope scaling --n"},
         {"--points-per-decade", "K", "2", "with --scaling run: sizes a decade, as nbscope scaling --points-per-decade",
                  integer_value(1, 20)}},
                {threads_option(), touching_option(), colour_by_option(), export_vtk_option()}})},
       {"screenshot (no display needed)", output},
       rendering_group(),
       plugin_group()},
      {"nbscope headless --scene assets/scenes/default.json --frames 120 --algorithm all",
       "nbscope headless --scene assets/scenes/pile.json --inject-fault drop-pair --stop-at-violation --screenshot v.png",
       "nbscope headless --scene assets/scenes/gas.json --record gas.nbsrec --report gas.json"},
      "0 every check passed, 1 a check failed, 2 bad input or a world that stopped (one line on stderr)",
  };
}

// `nbscope replay`: recorded frames detected and checked again.
CommandSpec replay_command() {
  return {
      "replay",
      run_replay,
      "detects and checks recorded frames (.nbsrec) again, in a window or headless",
      {"nbscope replay FILE.nbsrec [--headless] [--frames N] [--algorithm NAME[,NAME...]|all]",
       "nbscope replay --dump 'post/atoms*.dump' [--contacts 'post/contacts*.dump'] [--dt S] [--touching strict] ...",
       "               [--report OUT.json] [--inject-fault NAME] [--brute-limit N] [--quiet]",
       "               [--stop-at-violation | --back K | --violation N] [--record OUT.nbsrec]",
       "               [--screenshot OUT.png --size WxH --gl osmesa|egl|auto ...]"},
      {"Detects and checks recorded frames again (the first N with --frames), as headless does (--stop-at-violation too); a window "
       "plays them (P, O, R, the Timeline over every recorded frame, the Violations panel, the stepper on any frame) when there is a "
       "display and no --headless.",
       "No Box2D world: only A==R is checked; A-in-F, T-in-A, AABB-in-cells are reported as not checked (a dump's run leaves them "
       "out), and the faults are drop-pair, drop-mask-cell, off-by-one-cell, stale-positions.",
       "When the frames carry your simulation's pairs, --algorithm recorded checks them (the default then; nbs,recorded compares; all "
       "adds recorded last): a missing, extra, repeated or i == j pair fails (exit 1), named with its frame; of the faults only "
       "drop-pair acts on them.",
       "--dump reads LAMMPS and LIGGGHTS dump custom files instead (id, x y [z], radius or diameter; any order, ids with gaps, atoms "
       "lost or inserted: an element is its atom id), ordered by timestep, and --contacts the code's own contact list (dump local of "
       "LIGGGHTS's compute pair/gran/local pos id) as the recorded pairs. LIGGGHTS counts rsq < radsum^2: compare with --touching "
       "strict. A disagreement within what the file's printed digits resolve is listed as at the boundary, not a violation. "
       "A dump's frames are named by their timesteps; its summary ends with the periodic axes and the touching convention; a contact "
       "frame with no atoms frame is skipped with a note.",
       "The format (text; docs/formats.md):",
       "  nbsrec 1                 first line; '#' comments and blank lines anywhere\n"
       "  dim 3                    optional, before the first frame: 3D, rows x,y,z,r (dim 2 is the default)\n"
       "  cell_size D | origin X,Y[,Z] | cells NX,NY[,NZ]    optional, before the first frame: pin the grid\n"
       "  base 1                   optional, before the first frame: pairs count elements from 1\n"
       "  frame NUMBER TIME        NUMBER increasing, TIME (seconds) non-decreasing\n"
       "  x,y,r                    one element a line, as ELEMENTS.csv (x,y,z,r with dim 3)\n"
       "  pairs                    optional, after the rows: then one contact pair a line, i,j\n"
       "                           (every frame has a pairs block, or none)"},
      {{"options",
        joined({{{"--headless", "", "", "no window even when there is a display", flag_value()},
         {"--frames", "N", "every recorded frame", "the first N frames only", integer_value(1, kMaxFrames)},
         {"--algorithm", "NAME[,NAME...]|all", "the --detector-lib detectors, else nbs, or recorded when the frames carry pairs", "the detectors run and checked"},
         {"--report", "OUT.json", "", "as headless --report"},
         {"--inject-fault", "NAME", "", "drop-pair, drop-mask-cell, off-by-one-cell or stale-positions (as headless)"},
         {"--brute-limit", "N", "2000", "as headless --brute-limit", integer_value(0, 1'000'000)},
         {"--quiet", "", "", "no progress bar", flag_value()},
         {"--stop-at-violation", "", "", "as headless --stop-at-violation", flag_value()},
         {"--back", "K", "", "headless: after the last frame goes K frames back (as headless --back)", integer_value(1, 100'000'000)},
         {"--violation", "N", "", "headless: goes to the N-th listed violation (as headless --violation)", integer_value(1, 1'000'000'000)},
         {"--history-mb", "N", "256 with --back, --violation or --screenshot, else 0",
          "memory for kept frames: a dump's frames are read as shown, and this many MB of them stay (a frame dropped is read again)",
          integer_value(0, 1'000'000)},
         {"--record", "OUT.nbsrec", "", "headless: writes the frames replayed (2D or 3D, with their pairs); a recording recorded again is the same file"},
         {"--screenshot", "OUT.png", "", "headless: renders the last frame off-screen, as headless --screenshot"},
         {"--size", "WxH", "", "the window's or the screenshot's size in pixels (without it the window opens to the screen's work area)"},
         gl_option()},
                {threads_option(), touching_option(), colour_by_option(), export_vtk_option()}})},
       dump_replay_group(),
       rendering_group(),
       plugin_group()},
      {"nbscope replay gas.nbsrec", "nbscope replay gas.nbsrec --headless --algorithm all --report replay.json"},
      "0 every check passed, 1 a check failed, 2 bad input (one line on stderr)",
  };
}

// `nbscope watch`: the dumps of a run still being written, each frame checked as it lands.
CommandSpec watch_command() {
  std::vector<OptionSpec> dumps;  // replay's dump flags, but the frames' files: DUMPS is the argument
  for (const OptionSpec& s : dump_replay_options())
    if (std::string_view(s.name) != "--dump") dumps.push_back(s);
  dumps.push_back({"--idle", "S", "60 headless; the window: never",
                   "the run has ended after S seconds without a new frame (or once the writer's process is gone)",
                   number_value(0.05, 1e9, "must be at least 0.05 (seconds)")});
  return {
      "watch",
      run_watch,
      "follows the dumps of a LAMMPS or LIGGGHTS run still being written, checking each frame as it lands",
      {"nbscope watch 'post/atoms.*.dump' [--contacts 'post/contacts.*.dump'] [--idle S] [--headless] [--touching strict] ...",
       "               [--frames N] [--algorithm NAME[,NAME...]|all] [--report OUT.json] [--stop-at-violation]",
       "               [--screenshot OUT.png --size WxH ...]"},
      {"Follows DUMPS (a dump custom file that grows, or a quoted glob that new files join) while the simulation writes it: a frame "
       "is read once it is whole (a half-written one is waited for), detected and checked as replay --dump does, with --contacts "
       "the code's own contact list paired by timestep.",
       "The window (without --headless) shows each frame as it lands: the Timeline grows, time travel goes over what arrived, "
       "pause holds the frame shown. Headless ends with the run (no new frame for --idle S, or the writer's process gone) and "
       "prints replay's summary and how long after its write each frame was checked; --stop-at-violation ends at the first "
       "violation (exit 1)."},
      {{"options",
        joined({{{"--headless", "", "", "no window even when there is a display", flag_value()},
                 {"--frames", "N", "every frame that arrives", "the first N frames, then end", integer_value(1, kMaxFrames)},
                 {"--algorithm", "NAME[,NAME...]|all", "recorded with --contacts, else nbs", "the detectors run and checked"},
                 {"--report", "OUT.json", "", "headless: as headless --report"},
                 {"--inject-fault", "NAME", "", "drop-pair, drop-mask-cell, off-by-one-cell or stale-positions (as replay)"},
                 {"--brute-limit", "N", "2000", "as headless --brute-limit", integer_value(0, 1'000'000)},
                 {"--quiet", "", "", "no progress bar", flag_value()},
                 {"--stop-at-violation", "", "", "headless: ends at the first frame with a violation, shown (exit 1)", flag_value()},
                 {"--history-mb", "N", "256 in the window, 0 headless without --screenshot",
                  "memory for frames kept beside the one shown (a frame dropped is read again where it lies)", integer_value(0, 1'000'000)},
                 {"--screenshot", "OUT.png", "", "renders the last frame: headless at the run's end, the window after --frames N"},
                 {"--size", "WxH", "", "the window's or the screenshot's size in pixels"},
                 gl_option()},
                {threads_option(), touching_option(), colour_by_option(), export_vtk_option()}})},
       {"dumps being written (docs/watch.md)", dumps},
       rendering_group(),
       plugin_group()},
      {"nbscope watch 'post/atoms.*.dump' --contacts 'post/contacts.*.dump' --touching strict",
       "nbscope watch atoms.dump --headless --idle 10 --stop-at-violation --screenshot first_violation.png"},
      "0 every check passed, 1 a check failed, 2 bad input (one line on stderr)",
  };
}

}  // namespace

const std::vector<CommandSpec>& command_table() {
  // The order is the order "it is one of ..." names commands in, and --help lists them in.
  static const std::vector<CommandSpec> table = [] {
    std::vector<CommandSpec> t = {gui_command(), headless_command(), replay_command(), watch_command()};
    for (CommandSpec& c : file_commands()) t.push_back(std::move(c));
    return t;
  }();
  return table;
}

const CommandSpec* find_command(const std::string& name) {
  for (const CommandSpec& c : command_table())
    if (name == c.name) return &c;
  return nullptr;
}

std::vector<std::string> option_names(const CommandSpec& command) {
  std::vector<std::string> names;
  for (const OptionGroup& g : command.groups)
    for (const OptionSpec& o : g.options)
      if (!o.hidden) names.emplace_back(o.name);
  return names;
}

}  // namespace nbscope

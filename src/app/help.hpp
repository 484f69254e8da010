// nbscope app: the text of `nbscope --help` and the version.
#pragma once

namespace nbscope {

inline constexpr const char* kVersion = "0.1.0";

inline constexpr const char* kHelpText = R"(nbscope - a visual debugger for grid-based contact detection (Munjiza-NBS and its ancestors)

usage:
  nbscope [gui] [--scene FILE] [--algorithm NAME] [--inject-fault NAME] [--size WxH] [--history-mb N]
                [--frames N [--back K] --screenshot OUT.png] [--overlays SPEC] [--panels SPEC] [--select K]
                [--max-contacts N]
      The window (default: the last scene and algorithm used, else assets/scenes/default.json
      and nbs; $NBSCOPE_DATA_DIR overrides where assets/ is found): Box2D bodies, the cell grid, the
      detector's lists, pairs and check results over them, ImGui panels. Keys: P play/pause,
      O single step, R restart, Home fit, 1..9 algorithm, Esc clear the selection, overlays
      B E G L M C K F I T H; the Timeline: , and . one frame back/forward (Shift: 10), J play
      backwards; the Violations panel: [ and ] previous/next, Shift+[ the first; the Stepper (a
      paused frame): -> and <- one operation (Shift: one phase), Space play/pause, PageDown and
      PageUp the operation after/before on the selected element (Shift: on the selected cell)
      (see Help in the menu bar). Mouse: left selects an element and drags its body, right-drag
      pans, wheel zooms. Every frame is kept
      for the Timeline within --history-mb N (default 256, saved with the settings; oldest frames
      dropped first). Settings persist in $XDG_CONFIG_HOME/nbscope/settings.json (~/.config/...);
      a stale one opens the window all the same, its bad keys named in one note.
      --frames N runs N frames, saves --screenshot and exits (no input, no settings: for tests
      under xvfb-run); --back K then goes K frames back through the history first, each drawn,
      and says how long a frame took. Without a display it renders --frames N (default 120)
      headless into --screenshot (default $TMPDIR/nbscope-SCENE.png) and prints the path.
      A world that stops (too many contacts, a body not finite or leaving the world: see
      headless --max-contacts), also at load, shows its message in the Scenes panel and pauses;
      with --frames the screenshot shows it and the exit code is 2.
  nbscope gui --input ELEMENTS.csv --arrays ARRAYS.json [--algorithm NAME] [--base 1] [--exact]
              [--cell-size D] [--origin X,Y] [--cells NX,NY] [--frames N --screenshot OUT.png]
              [--overlays SPEC] [--panels SPEC] [--select K]
      Your heads and next arrays, checked as verify --arrays checks them, in the window: your
      lists as arrow chains with their heads named (C[5][7]), every problem in red (the wrong
      link, the elements at fault ringed, a cut list's end), the first problem selected and its
      text in the legend. Problems panel: a click selects one and puts the camera on it ([ and ]
      the previous/next); Lists panel: a click goes to the list; the hovered element's lists and
      problems in a tooltip. Numbered as the file counts (--base 1: from 1). Panels: overlays,
      problems, lists. Exit 0 right, 1 wrong. Without a display it renders headless into
      --screenshot (default $TMPDIR/nbscope-verify-ARRAYS.png) and prints the path.
  nbscope pairs --input ELEMENTS.csv [--algorithm NAME] [--output PAIRS.csv] [--repeat K]
                [--cell-size D] [--origin X,Y[,Z]] [--cells NX,NY[,NZ]] [--max-pairs M]
      Contact pairs of the elements (rows x,y,r or x,y,z,r) as CSV "i,j" (0-based, i < j, sorted),
      to PAIRS.csv or stdout (algorithm default nbs). Detection time (without I/O) and pair
      count go to stderr.
      --repeat K runs detection K times and checks that every run agrees.
      --cell-size/--origin/--cells pin the grid (default: cells of the largest diameter from the
      smallest centre coordinates; D must be at least the largest diameter).
      --max-pairs M stops with an error past M pairs (default 50,000,000: 400 MB of pairs,
      about 600 MB at the peak while the list grows).
  nbscope dump --input ELEMENTS.csv --algorithm NAME [--cell-size D] [--origin X,Y[,Z]]
               [--cells NX,NY[,NZ]] [--format json]
      The algorithm's integer arrays as JSON on stdout, as they stand when its lists are complete:
      0-based, -1 for an empty list and for the end of a list, with the grid (cell_size, origin,
      nx, ny, nz) and the bytes of every array. screen: heads[ix][iy] and next; nbs: y_heads,
      y_next and per non-empty row its x-lists (3D: z_heads, z_next, layers); tree: its leaves'
      bounds and HEADs and next; sort: sorted cell keys and order; brute, box2d: counts only.
      --cells pins the number of cells per axis (the book's Fig. 3.15 is --cell-size 1
      --origin 0,0 --cells 10,10).
  nbscope verify --input ELEMENTS.csv --pairs PAIRS.csv [--base 1] [--brute-limit N]
                 [--cell-size D] [--origin X,Y[,Z]] [--cells NX,NY[,NZ]]
      Your contact pairs (one a line, i,j in either order) against brute force (sort above
      --brute-limit, default 2000): a summary line, then every missing, extra, duplicated,
      i == j and out-of-range pair with both elements' cells and distance - radii.
  nbscope verify --input ELEMENTS.csv --arrays ARRAYS.json [--algorithm screen|nbs|tree|sort]
                 [--base 1] [--exact] [--cell-size D] [--origin X,Y[,Z]] [--cells NX,NY[,NZ]]
                 [--screenshot OUT.png [--size WxH] [--overlays SPEC] [--panels SPEC] [--select K]
                 [--lists F] [--camera X,Y,PPM] [--no-timings] [--shader-dir DIR] [--book-numbering]
                 [--gl osmesa|egl|auto]]
      Your heads and next arrays, in the schema dump writes ("base": 1 for 1-based), against
      the book: every list ends (a cycle or a bad index is found, never followed), every
      element on one list, the list of its own cell; --exact also the book's order. The first
      problem in the book's terms (E[7] = 5, but element 5 lies in cell (2,7) ...), then the
      count. --screenshot draws your lists with the wrong links red, as gui --arrays shows them
      (its rendering flags as below; numbered as the file counts, so --book-numbering only with
      --base 1; --step does not apply). Exit 0 right, 1 wrong.
  nbscope scaling [--algorithm NAME[,NAME...]|all] [--layout NAME[,NAME...]] [--n MIN..MAX]
                  [--points-per-decade K] [--output OUT.csv] [--quiet]
      Times every detector named (default all) on generated layouts (default loose; also dense,
      clustered, touching, unequal_radii, far_away, on_line) at N from MIN to MAX (default
      1000..1000000; 1e3-style powers too), K sizes a decade on a log scale (default 2): each
      point's best of a few detect() runs (repeated for at least 0.05 s, at most 0.2 s). Prints
      a table (ns per element, bytes of the detector's own arrays per element, pairs, repeats)
      and writes it as CSV "algorithm,layout,n,ns_per_element,bytes_per_element,pairs,repeats",
      one row per (detector, layout, N). brute is skipped above N = 10,000, and a detector whose
      one run would take over 2 s at an N (its last time, scaled by N) is skipped there (noted).
      A progress bar on stderr when it is a terminal. The window's Scaling panel (View menu) runs
      the same in the background and plots it; nbscope headless renders that panel (below).
  nbscope headless --scene FILE [--frames N] [--algorithm NAME[,NAME...]|all] [--report OUT.json]
                   [--inject-fault NAME] [--brute-limit N] [--quiet] [--record OUT.nbsrec]
                   [--stop-at-violation | --rewind FROM:TO] [--back K | --violation N] [--history-mb N]
                   [--max-contacts N]
                   [--scaling FILE.csv | --scaling run [--layout L] [--n MIN..MAX] [--points-per-decade K]]
      Runs N frames (default 600) of a scene (assets/scenes/*.json) with no window: Box2D steps,
      the algorithm (default nbs) detects, and every frame is checked: A==R (R: brute force up to
      --brute-limit elements, default 2000, then sort, or nbs when sort is tested; brute itself
      is checked against sort), A-in-F (Box2D's contact
      list, its filters applied to A), T-in-A (shapes touching now), AABB-in-cells (tight-AABB
      pairs in neighbouring cells). One summary line on stdout; a progress bar on stderr when it
      is a terminal; --report writes per-frame counts, timings and every violation as JSON.
      Exit 1 if any check failed.
      Several algorithms (a,b,c or all: every 2D detector) run and are checked on the same frames.
      --inject-fault drop-mask-cell | off-by-one-cell | stale-positions | drop-pair |
      drop-box2d-contact breaks the detection (or Box2D's side) on purpose, to see the checks
      catch it.
      --screenshot OUT.png [--size WxH] [--gl osmesa|egl|auto] renders the last frame exactly as the
      window shows it (scene, overlays, panels) off-screen, no display needed: with OSMesa or EGL
      (surfaceless); auto (default) takes OSMesa when libOSMesa.so.8 is there, else EGL.
      --record OUT.nbsrec writes every frame's elements (frame 0 too) and the scene's pinned grid.
      --stop-at-violation stops on the first frame with a violation and (with --screenshot) shows
      it as the window's Violations panel does: the pair selected, the camera on it, the stepper
      at the operation that decided it; exit 1, or 0 when no frame broke (one algorithm only).
      --rewind FROM:TO runs to frame FROM, goes back to kept frame TO and resumes to --frames:
      the frames after TO are simulated again (deterministically, from the scene) and replace
      the first ones; every report frame carries "hash", the hash of its elements, so a rewound
      run can be compared with a straight one frame by frame.
      --back K after the last frame goes K frames back through the history (each detected and
      checked again); --screenshot then shows that frame. --violation N goes to the run's N-th
      violation instead (from 1, as the Violations panel lists them) and shows it as choosing it
      there does.
      --history-mb N memory for kept frames (default 256 with --rewind, --back, --violation or
      --screenshot, else 0: a run that never goes back keeps only summaries).
      --max-contacts N the Box2D contacts a frame may create (default 1,000,000, ~1.7 GB; the
      scene's "max_contacts" sets it too): before every step the pairs of fat AABBs are counted
      and a world past it stops with exit 2 naming the count; no more than the memory this
      process can get (rlimits, cgroup, MemAvailable) at ~1.7 kB a contact, whatever N says.
      A frame running over 5 s (or 10 frames together) says so once on stderr. A body that is not finite after a step, or beyond +-1e6 m, stops the run
      with exit 2 naming the body and the frame.
      --scaling FILE.csv (with --screenshot) opens the Scaling panel on a CSV of nbscope scaling
      (a bad row: exit 2 naming FILE:LINE); --scaling run measures first, as nbscope scaling does,
      the detectors of --algorithm on --layout, --n and --points-per-decade.
  nbscope replay FILE.nbsrec [--headless] [--frames N] [--algorithm NAME[,NAME...]|all]
                 [--report OUT.json] [--inject-fault NAME] [--brute-limit N] [--quiet]
                 [--stop-at-violation] [--screenshot OUT.png --size WxH --gl osmesa|egl|auto ...]
      Detects and checks recorded frames again (the first N with --frames), as headless does
      (--stop-at-violation too); a window plays them (P, O, R, the Timeline over every recorded
      frame, the Violations panel, the stepper on any frame) when there is a display and no
      --headless. No Box2D world: only
      A==R is checked; A-in-F, T-in-A, AABB-in-cells are reported as not checked, and the faults
      are drop-pair, drop-mask-cell, off-by-one-cell, stale-positions. When the frames carry your
      simulation's pairs, --algorithm recorded checks them (the default then; nbs,recorded
      compares; all adds recorded last): a missing, extra, repeated or i == j pair fails (exit 1),
      named with its frame; of the faults only drop-pair acts on them. The format (text):
        nbsrec 1                 first line; '#' comments and blank lines anywhere
        cell_size D | origin X,Y | cells NX,NY    optional, before the first frame: pin the grid
        base 1                   optional, before the first frame: pairs count elements from 1
        frame NUMBER TIME        NUMBER increasing, TIME (seconds) non-decreasing
        x,y,r                    one element a line, as ELEMENTS.csv (2D only)
        pairs                    optional, after the rows: then one contact pair a line, i,j
                                 (every frame has a pairs block, or none)
  rendering flags (gui, headless and replay):
      --overlays SPEC   comma list: all, none, NAME (only the names listed), +NAME, -NAME; names:
                        bodies elements grid lists mask pairs checks broadphase ids trails flash
      --panels SPEC     the same for panels: controls scenes algorithm overlays stats selection
                        metrics violations timeline stepper pseudocode arrays scaling
      --select K        select element K as shown (its cell, lists and pairs highlighted, its trail
                        drawn): from 0, or from 1 with --book-numbering
      --lists FILTER    the lists overlay draws all lists, the selected element's, or one row's
                        (all | selected | row; default: row past 300 elements, else all)
      --camera X,Y,PPM  put (X, Y) in the middle of the view the panels leave free, at PPM pixels
                        per metre, instead of fitting the scene
      --no-timings      show "-" for wall-clock numbers (reproducible screenshots)
      --step K          open the Stepper, Arrays and Pseudocode panels on the state after K
                        operations of the last frame's detection of one algorithm that records
                        them (not box2d); K past its last operation is an error (headless: needs
                        --screenshot)
      --book-numbering  number elements and cells from 1 everywhere, as the book does
      --shader-dir DIR  GLSL sources (default: $NBSCOPE_SHADER_DIR if set, else
                        $NBSCOPE_DATA_DIR/shaders, else the source tree's shaders/)
  nbscope algorithms      list the detectors
  nbscope --help | --version

Sub-commands take no --help of their own: this text is the reference.
exit codes: 0 all well, 1 a check failed, 2 bad input or usage (one line on stderr).
)";

}  // namespace nbscope

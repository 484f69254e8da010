// nbscope app: the text of `nbscope --help` and the version.
#pragma once

namespace nbscope {

inline constexpr const char* kVersion = "0.1.0";

inline constexpr const char* kHelpText = R"(nbscope - a visual debugger for grid-based contact detection (Munjiza-NBS and its ancestors)

usage:
  nbscope pairs --input ELEMENTS.csv [--algorithm NAME] [--output PAIRS.csv] [--repeat K]
                [--cell-size D] [--origin X,Y[,Z]] [--max-pairs M]
      Contact pairs of the elements (rows x,y,r or x,y,z,r) as CSV "i,j" (0-based, i < j, sorted),
      to PAIRS.csv or stdout. Detection time (without I/O) and pair count go to stderr.
      --repeat K runs detection K times and checks that every run agrees.
      --cell-size/--origin pin the grid (default: largest diameter, minimum corner).
      --max-pairs M stops with an error past M pairs (default 50,000,000: 400 MB).
  nbscope dump --input ELEMENTS.csv --algorithm NAME [--cell-size D] [--origin X,Y[,Z]]
               [--cells NX,NY[,NZ]] [--format json]
      The algorithm's integer arrays as JSON on stdout, as they stand when its lists are complete:
      0-based, -1 for an empty list and for the end of a list, with the grid (cell_size, origin,
      nx, ny, nz) and the bytes of every array. screen: heads[ix][iy] and next; nbs: y_heads,
      y_next and per non-empty row its x-lists (3D: z_heads, z_next, layers); tree: its leaves'
      bounds and HEADs and next; sort: sorted cell keys and order. --cells pins the number of
      cells per axis (the book's Fig. 3.15 is --cell-size 1 --origin 0,0 --cells 10,10).
  nbscope headless --scene FILE [--frames N] [--algorithm NAME] [--report OUT.json]
                   [--inject-fault NAME] [--brute-limit N] [--quiet]
      Runs N frames (default 600) of a scene (assets/scenes/*.json) with no window: Box2D steps,
      the algorithm detects, and every frame is checked: A==R (R: brute force up to --brute-limit
      elements, default 2000, then another detector), A-in-F (Box2D's contact list, its filters
      applied to A), T-in-A (shapes touching now), AABB-in-cells (tight-AABB pairs in neighbouring
      cells). One summary line on stdout; a progress bar on stderr when it is a terminal; --report
      writes per-frame counts, timings and every violation as JSON. Exit 1 if any check failed.
      --inject-fault drop-mask-cell | off-by-one-cell | stale-positions | drop-pair |
      drop-box2d-contact breaks the detection (or Box2D's side) on purpose, to see the checks catch it.
  nbscope algorithms      list the detectors
  nbscope --help | --version

exit codes: 0 all well, 1 a check failed, 2 bad input or usage (one line on stderr).
)";

}  // namespace nbscope

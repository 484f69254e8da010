// The command table's rows of the file commands: pairs, dump, verify, scaling, algorithms.
#include <cstdio>

#include "app/command_table_parts.hpp"
#include "app/commands.hpp"
#include "app/dump_input.hpp"
#include "app/threads_flag.hpp"
#include "core/detector.hpp"

namespace nbscope {

namespace {

// The options of a command: `own`, then the grid pins, then `shared` (--threads, --touching).
std::vector<OptionSpec> with_grid(std::vector<OptionSpec> own, const std::vector<OptionSpec>& shared) {
  return joined({own, grid_options(), shared});
}

CommandSpec pairs_command() {
  return {
      "pairs",
      run_pairs,
      "contact pairs of an elements file as CSV",
      {"nbscope pairs --input ELEMENTS.csv [--algorithm NAME] [--output PAIRS.csv] [--repeat K]",
       "              [--cell-size D] [--origin X,Y[,Z]] [--cells NX,NY[,NZ]] [--max-pairs M] [--threads N]"},
      {"Contact pairs of the elements (rows x,y,r or x,y,z,r) as CSV \"i,j\" (0-based, i < j, sorted), to PAIRS.csv or stdout; "
       "of a dump's frame (--input FILE.dump) \"id1,id2\", the atoms' ids. Detection time (without I/O) and pair count go to stderr."},
      {{"options", with_grid({{"--input", "ELEMENTS.csv", "", "the elements, one x,y,r or x,y,z,r a row (required)"},
                              {"--algorithm", "NAME", "a --detector-lib's detector, else nbs", "the detector (nbscope algorithms)"},
                              {"--output", "PAIRS.csv", "stdout", "where the pairs go"},
                              {"--repeat", "K", "1", "runs detection K times and checks that every run agrees", integer_value(1, 1'000'000)},
                              {"--max-pairs", "M", "50,000,000: 400 MB of pairs, about 600 MB at the peak while the list grows",
                               "stops with an error past M pairs", integer_value(0, 1'000'000'000)}},
                             {threads_option(), touching_option()})},
       dump_input_group(),
       plugin_group()},
      {"nbscope pairs --input assets/examples/nine.csv", "nbscope pairs --input big.csv --algorithm sort --output pairs.csv --repeat 3"},
      "0 pairs written, 2 bad input (one line on stderr)",
  };
}

CommandSpec dump_command() {
  return {
      "dump",
      run_dump,
      "an algorithm's integer arrays (heads, next, ...) as JSON",
      {"nbscope dump --input ELEMENTS.csv --algorithm NAME [--cell-size D] [--origin X,Y[,Z]]",
       "             [--cells NX,NY[,NZ]] [--format json]"},
      {"The algorithm's integer arrays as JSON on stdout, as they stand when its lists are complete: 0-based, -1 for an empty list and "
       "for the end of a list, with the grid (cell_size, origin, nx, ny, nz) and the bytes of every array. screen: heads[ix][iy] and "
       "next; nbs: y_heads, y_next and per non-empty row its x-lists (3D: z_heads, z_next, layers); tree: its leaves' bounds and HEADs "
       "and next; sort: sorted cell keys and order; brute, box2d: counts only."},
      {{"options", with_grid({{"--input", "ELEMENTS.csv", "", "the elements (required)"},
                              {"--algorithm", "NAME", "a --detector-lib's detector", "the detector whose arrays are written (required without --detector-lib)"},
                              {"--format", "json", "json", "the output format (JSON is the only one)"}},
                             {touching_option()})},  // no --threads: the arrays are its traced run, the book's serial loops
       dump_input_group(),
       plugin_group()},
      {"nbscope dump --input assets/examples/nine.csv --algorithm screen --cell-size 1 --origin 0,0 --cells 10,10"},
      "0 arrays written, 2 bad input (one line on stderr)",
  };
}

CommandSpec verify_command() {
  std::vector<OptionSpec> screenshot = {
      {"--screenshot", "OUT.png", "", "with --arrays: draws your lists with the wrong links red, as gui --arrays shows them"},
      {"--size", "WxH", "", "the screenshot's size in pixels"},
      gl_option(),
  };
  return {
      "verify",
      run_verify,
      "checks your pairs, or your heads and next arrays, against brute force and the book",
      {"nbscope verify --input ELEMENTS.csv --pairs PAIRS.csv [--base 1] [--brute-limit N]",
       "               [--cell-size D] [--origin X,Y[,Z]] [--cells NX,NY[,NZ]]",
       "nbscope verify --input ELEMENTS.csv --arrays ARRAYS.json [--algorithm screen|nbs|tree|sort]",
       "               [--base 1] [--exact] [--cell-size D] [--origin X,Y[,Z]] [--cells NX,NY[,NZ]]",
       "               [--screenshot OUT.png [--size WxH] [--overlays SPEC] [--panels SPEC] [--select K]",
       "               [--lists F] [--layer K|auto] [--camera X,Y,PPM] [--no-timings] [--shader-dir DIR]",
       "               [--book-numbering] [--gl osmesa|egl|auto]]"},
      {"--pairs: your contact pairs (one a line, i,j in either order; atom ids with --input FILE.dump) against brute force (sort above "
       "--brute-limit): a summary line, then every missing, extra, duplicated, i == j and out-of-range pair with both elements' cells and distance - radii.",
       "--arrays: your heads and next arrays, in the schema dump writes (\"base\": 1 for 1-based), against the book: every list ends (a "
       "cycle or a bad index is found, never followed), every element on one list, the list of its own cell; --exact also the book's "
       "order. The first problem in the book's terms, led by the contract it breaks (contract list-cell broken: E[7] = 5, but element 5 "
       "lies in cell (2,7) ...), then the count. Exit 0 right, 1 wrong.",
       "--screenshot draws your lists with the wrong links red, as gui --arrays shows them (its rendering options as below; numbered as "
       "the file counts, so --book-numbering only with --base 1; --step does not apply). 3D arrays are drawn one layer of cells at a "
       "time, as the window draws a 3D frame: --layer K, or auto, the first problem's layer."},
      {{"options", with_grid({{"--input", "ELEMENTS.csv", "", "the elements (required)"},
                              {"--pairs", "PAIRS.csv", "", "your contact pairs, one i,j a line"},
                              {"--arrays", "ARRAYS.json", "", "your heads and next arrays, in the schema dump writes"},
                              {"--algorithm", "screen|nbs|tree|sort", "", "with --arrays: the algorithm the arrays belong to"},
                              {"--base", "1", "0", "your file counts elements from 1", integer_value(0, 1)},
                              {"--exact", "", "", "with --arrays: also the book's order within every list", flag_value()},
                              {"--brute-limit", "N", "2000", "with --pairs: the elements up to which brute force is the reference "
                                                             "(sort above)", integer_value(0, 1'000'000)}},
                             {threads_option(), touching_option()})},
       dump_input_group(),
       {"screenshot (with --arrays)", screenshot},
       rendering_group()},
      {"nbscope verify --input assets/examples/nine.csv --pairs my_pairs.csv",
       "nbscope verify --input assets/examples/nine.csv --arrays assets/examples/nine_screen_bug.json --screenshot bug.png"},
      "0 right, 1 wrong, 2 bad input (one line on stderr)",
  };
}

CommandSpec scaling_command() {
  return {
      "scaling",
      run_scaling_command,
      "times detectors on generated layouts against N (ns and bytes per element)",
      {"nbscope scaling [--algorithm NAME[,NAME...]|all] [--layout NAME[,NAME...]] [--n MIN..MAX]",
       "                [--points-per-decade K] [--threads N] [--output OUT.csv] [--quiet]"},
      {"Times every detector named on generated layouts at N from MIN to MAX, K sizes a decade on a log scale: each point's best of a "
       "few detect() runs (repeated for at least 0.05 s, at most 0.2 s). Prints a table (ns per element, bytes of the detector's own "
       "arrays per element, pairs, repeats, threads) and writes it as CSV "
       "\"algorithm,layout,n,ns_per_element,bytes_per_element,pairs,repeats,threads\", one row per (detector, threads, layout, N).",
       "--threads N compares one thread with N: nbs, which detects bands of rows on threads, is measured at 1 and at N (\"nbs\" and "
       "\"nbs xN\"), every other detector once, at 1.",
       "brute is skipped above N = 10,000, and a detector whose one run would take over 2 s at an N (its last time, scaled by N) is "
       "skipped there (noted). A progress bar on stderr when it is a terminal. The window's Scaling panel (View menu) runs the same in "
       "the background and plots it; nbscope headless --scaling renders that panel."},
      {{"options", {{"--algorithm", "NAME[,NAME...]|all", "the --detector-lib detectors, else all", "the detectors timed"},
                    {"--layout", "NAME[,NAME...]", "loose", "the generated layouts: loose, dense, clustered, touching, unequal_radii, "
                                                            "far_away, on_line"},
                    {"--n", "MIN..MAX", "1000..1000000", "the range of N (1e3-style powers too)"},
                    {"--points-per-decade", "K", "2", "sizes a decade, on a log scale", integer_value(1, 20)},
                    {"--output", "OUT.csv", "", "writes the table as CSV"},
                    {"--quiet", "", "", "no progress bar", flag_value()},
                    threads_option(),
                    touching_option()}},
       plugin_group()},
      {"nbscope scaling --algorithm nbs,sort --n 1e3..1e5 --output scaling.csv"},
      "0 measured, 2 bad input (one line on stderr)",
  };
}

CommandSpec algorithms_command() {
  return {"algorithms",
          run_algorithms,
          "lists the detectors",
          {"nbscope algorithms [--detector-lib PATH.so ...]"},
          {"One line per detector: its name, the dimensions it handles (2D, 3D) and what it is; a plugin's (--detector-lib) too."},
          {plugin_group()},
          {"nbscope algorithms", "nbscope algorithms --detector-lib ./my_nbs.so"},
          "0, 2 bad input (one line on stderr)"};
}

}  // namespace

std::vector<CommandSpec> file_commands() {
  return {pairs_command(), dump_command(), verify_command(), scaling_command(), algorithms_command()};
}

int run_algorithms(Args& args) {
  args.finish();
  for (const DetectorInfo& d : detector_infos())
    std::printf("%-7s %-6s %s\n", d.name.c_str(), d.dim3 ? (d.dim2 ? "2D,3D" : "3D") : "2D", d.summary.c_str());
  return 0;
}

}  // namespace nbscope

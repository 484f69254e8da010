// nbscope app: the rendering options shared by `nbscope gui` and `nbscope headless`: screenshot,
// size, GL backend, shader directory, overlays, panels, selection. Parsing needs no GL, so it is
// built without the GUI too (where any rendering request is then refused).
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "app/cli.hpp"
#include "check/units.hpp"
#include "core/scaling.hpp"

namespace nbscope {

// Rows the Scaling panel opens on (headless --scaling): read from a CSV or measured before the capture.
struct ScalingShown {
  ScalingResult result;
  ScalingPlan plan;
  std::string source;  // the CSV, or "" for a run
  double seconds = 0;  // the run's wall time
};

struct ViewOptions {
  std::optional<std::string> screenshot;  // --screenshot OUT.png
  int width = 1280;                       // --size WxH (a scripted or headless picture's size without it)
  int height = 720;
  bool size_given = false;                // --size was given: the window opens at it, whatever the screen
  std::string gl = "auto";                // --gl osmesa|egl|auto (headless only)
  std::string shader_dir;                 // --shader-dir DIR ("" = $NBSCOPE_SHADER_DIR or the built-in one)
  std::string overlays;                   // --overlays SPEC, e.g. "all,-lists" or "+lists" (see help)
  std::string panels;                     // --panels SPEC, e.g. "none" or "+metrics"
  std::int32_t select = -1;               // --select K: element selected from the start
  std::optional<std::array<double, 3>> camera;  // --camera X,Y,PPM: view centre and pixels per metre
  bool no_timings = false;                // --no-timings: "-" instead of wall-clock numbers
  std::optional<std::int64_t> step;       // --step K: the stepper shows the state after K trace events
  bool book_numbering = false;            // --book-numbering: the stepper numbers from 1, as the book
  std::string lists;                      // --lists all|selected|row: the lists overlay's filter ("" = by size)
  std::string layer;                      // --layer K|auto: the layer of a 3D frame shown ("" = the view's choice)
  std::optional<ScalingShown> scaling;    // headless --scaling: the Scaling panel open on these rows
  std::optional<std::string> colour_by;   // --color-by WHAT (app/colour_by.hpp; taken by the commands that draw frames)
  std::optional<std::int64_t> frames;     // gui --frames N of a scripted window (set by the command, not parse_view_options)
  Units units;                            // the run's units (set by the command from --units, a data file, --log): panels and reports use them
};

// Takes the rendering flags out of `args`; `headless` also accepts --gl. Error names a bad value.
void parse_view_options(Args& args, bool headless, ViewOptions& out);

// Error("--step: ...") when --step is given and `algorithm` (an --algorithm value) is not one
// detector that records its operations (several names, `all`, or one like box2d that records none).
void check_step_algorithm(const ViewOptions& options, const std::string& algorithm);

// True when any flag asks for rendering (a screenshot); the others only matter with one.
[[nodiscard]] inline bool wants_rendering(const ViewOptions& v) { return v.screenshot.has_value(); }

}  // namespace nbscope

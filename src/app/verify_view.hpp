// nbscope app: a `verify --arrays` run drawn — the user's own lists as arrow chains over the
// elements and the grid, every problem in red (wrong links, elements at fault, cut lists' ends),
// the selected problem's text in the legend and a Problems panel — as a screenshot rendered
// off-screen (OSMesa or EGL) or in a window (`nbscope gui --input E.csv --arrays A.json`). Numbers are
// shown as the arrays file counts them (its base: 1 numbers elements and cells from 1). GUI build
// only: without it both refuse with Error (exit 2).
#pragma once
#include <string>

#include "app/cli.hpp"
#include "app/verify_run.hpp"
#include "app/view_options.hpp"

namespace nbscope {

// Renders `run` off-screen (view.gl) at view.width x view.height — the camera fitted to the
// elements (or view.camera), grid, elements, lists, red marks, the first problem selected with its
// text on the image, the panels (view.panels: overlays, problems, lists) — and writes
// view.screenshot atomically. Returns a one-line summary (path, size, what was drawn). Error when
// rendering is unavailable or the file cannot be written.
std::string write_verify_screenshot(const VerifyArraysRun& run, const ViewOptions& view);

// The window on `run`: pan/zoom, overlay toggles, the Problems panel (a click selects a problem and
// centres the camera on it), the Lists panel, a tooltip on the hovered element. With view.frames
// (gui --frames N) it draws N frames and the settling ones, saves view.screenshot when given and
// returns. Returns 0 when the arrays have no problem, 1 otherwise; Error when the window cannot open.
int run_verify_window(const VerifyArraysRun& run, const ViewOptions& view);

// `nbscope gui --input ELEMENTS.csv --arrays ARRAYS.json [--algorithm A] [grid flags] [--base 1]
// [--exact] [--frames N --screenshot OUT.png] [view flags]`: the window, or without a display the
// same picture headless (it says where). Exit 0 no problem, 1 problems, 2 bad input.
int run_verify_gui(Args& args);

}  // namespace nbscope

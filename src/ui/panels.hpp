// nbscope ui: the standard panels (one file each).
#pragma once
#include <memory>

#include "ui/panel.hpp"

namespace nbscope::ui {

// Play/pause (P), single step (O), restart (R), time step, speed, camera Home.
std::unique_ptr<Panel> make_controls_panel();
// Every scene in assets/scenes, and a field to open any scene file.
std::unique_ptr<Panel> make_scenes_panel();
// The detection algorithm, switched live (keys 1..9).
std::unique_ptr<Panel> make_algorithm_panel();
// One checkbox per overlay, with its key.
std::unique_ptr<Panel> make_overlays_panel();
// N, cells, pairs, per-algorithm time and bytes, check status, FPS, frame time split.
std::unique_ptr<Panel> make_stats_panel();
// The selected element: position, cell, lists with their next entries, pairs.
std::unique_ptr<Panel> make_selection_panel();
// Self-inspection: draw calls, batches, buffers, frame time history, trace size.
std::unique_ptr<Panel> make_metrics_panel();

// The Selection panel's line for list `l` around element k: "B[1][8]: 11 -> [12] -> 191 -> ... ",
// the head named as the Arrays panel names it, every number from 1 with `book`.
std::string describe_chain(const render::TracedList& l, ElementId k, bool book);

// Formats milliseconds for a panel, or "-" when timings are hidden (reproducible screenshots).
std::string format_ms(const SimView& sim, double ms);

}  // namespace nbscope::ui

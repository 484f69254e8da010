// nbscope ui: the standard panels (one file each).
#pragma once
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ui/panel.hpp"

namespace nbscope::ui {

// Play/pause (P), single step (O), restart (R), time step, speed, camera Home.
std::unique_ptr<Panel> make_controls_panel();
// Every scene in assets/scenes, and a field to open any scene file.
std::unique_ptr<Panel> make_scenes_panel();
// The detection algorithm, switched live (keys 1..N, N the algorithms offered, at most 9).
std::unique_ptr<Panel> make_algorithm_panel();
// What the Algorithm panel says when digit `key` names none of the `offered` algorithms:
// "key 7: no algorithm 7 here; keys 1..6 choose those above".
std::string algorithm_key_note(std::size_t key, std::size_t offered);
// One checkbox per overlay, with its key.
std::unique_ptr<Panel> make_overlays_panel();
// What the Overlays panel says when the lists shown are empty: "nbs has built no lists yet" (the
// stepper before its first push), "brute builds no lists".
std::string no_lists_note(const std::string& algorithm);
// N, cells, pairs, per-algorithm time and bytes, check status, FPS, frame time split.
std::unique_ptr<Panel> make_stats_panel();
// The selected element: position, cell, lists with their next entries, pairs.
std::unique_ptr<Panel> make_selection_panel();
// Self-inspection: draw calls, batches, buffers, frame time history, trace size.
std::unique_ptr<Panel> make_metrics_panel();
// The run's frames under the scene: scrub, step and play through the kept ones, resume from a past one.
std::unique_ptr<Panel> make_timeline_panel();
// Every violation of the run, filtered by invariant; choosing one goes to it.
std::unique_ptr<Panel> make_violations_panel();

// Panel titles the app and the host refer to (also their keys in the settings file).
inline constexpr const char* kTimelineTitle = "Timeline";
inline constexpr const char* kViolationsTitle = "Violations";
inline constexpr const char* kStatsTitle = "Stats";

// The violation to go to from the current one (UiState::current_violation) among those the filter
// lists: direction 0 the first, +1 the next, -1 the previous; with none chosen, +1 the first at or
// after the frame on screen, -1 the last at or before it; nullopt when there is none.
std::optional<std::size_t> step_violation(const SimView& sim, const UiState& state, int direction);
// The index in SimView::violations (the run's log) of `violation`, one of a frame's report, or
// nullopt when the log does not list it.
std::optional<std::size_t> violation_index(const SimView& sim, const Violation& violation);
// "A==R in frame 3: (4, 6) missing from A (in R); the detector's cells (5,6) and (4,7)", in the
// chosen numbering (cells of a 3D frame, `dim` 3, with iz); its elements named "atoms (2753, 12)" when
// it carries their atom ids (a dump's frame: Violation::atom_i, atom_j).
std::string describe_violation(const Violation& violation, bool book, int dim = 2, FrameUnit unit = FrameUnit::frame);
// The cells the grid gives the violation's two elements (core/cells.hpp's integerisation: what the
// Selection panel and the picture show), to hold against the detector's (Violation::cell_i, cell_j);
// nullopt unless the violation is of the frame on screen (only its elements are at hand).
std::optional<std::array<CellIndex, 2>> grid_cells(const SimView& sim, const Violation& violation);
// "(5,6) (4,7)": two cells in the chosen numbering; "(5,6,1) (4,7,0)" in 3D (`dim` 3).
std::string cell_pair_text(const CellIndex& a, const CellIndex& b, bool book, int dim = 2);
// The Stats panel's line for one of the frame's violations: "A==R: (4, 6) missing from A (in R),
// cells (5,6) (4,7)", in the chosen numbering; its elements named by the atom ids it carries.
std::string violation_line(const Violation& violation, bool book);
// The Violations panel's line for a pair at the boundary: "atoms (2753, 12): at the boundary, within ... (R has it, A not)";
// its gap in the run's `units` when it has named ones (null or nbscope's own: bare numbers).
std::string boundary_line(const BoundaryPair& b, bool book, const std::vector<std::int64_t>* ids, const Units* units = nullptr);
// The Stats panel's line for the contact convention: "touching: inclusive (<=)" or "touching: strict (<)".
std::string touching_line(Touching touching);

// The Selection panel's line for list `l` around element k: "B[1][8]: 11 -> [12] -> 191 -> ... ",
// the head named as the Arrays panel names it, every number from 1 with `book`.
std::string describe_chain(const TracedList& l, ElementId k, bool book);

// The Selection panel's lines on element k of a 3D frame: its cell (ix, iy, iz), its row (iy, iz),
// and its layer against the one the view shows ("in layer 3 (shown)", "in layer 2 (layer shown:
// 3)"), in the chosen numbering; none for a 2D frame.
std::vector<std::string> selection_layer_lines(const SimView& sim, ElementId k, bool book);
// Where an element at `position` (0: the head) of list `l` is: "C[2]: position 3 of 40", with the
// pass it was built in for a 3D NBS list ("A[1][4]: position 1 of 2 (pass of layer 3)").
std::string list_place_text(const TracedList& l, std::size_t position, bool book);

// Formats milliseconds for a panel, or "-" when timings are hidden (reproducible screenshots).
std::string format_ms(const SimView& sim, double ms);

}  // namespace nbscope::ui

// nbscope ui: what the panels read (SimView: one frame's facts, given by the app), what they
// change (UiState: view state, persisted in the settings file), and what they ask the app to do
// (UiRequests: applied by the app after the UI frame). The ui never sees the frame loop itself,
// so it depends only on check, render and core. SimView points at the shown frame's FrameResult
// instead of copying it: the app owns the frame, the ui reads it (and formats what it shows, such
// as the violation lines in the book's numbering); SimView's own fields are what the FrameResult
// does not hold (the session, the run's history, the window's costs, self-inspection).
#pragma once
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "check/frame_result.hpp"
#include "check/report.hpp"
#include "check/units.hpp"
#include "core/elements.hpp"
#include "core/frame_trace.hpp"
#include "core/grid.hpp"
#include "core/pairs.hpp"
#include "render/camera.hpp"
#include "core/traced_lists.hpp"
#include "render/overlays.hpp"
#include "render/renderer.hpp"

namespace nbscope::ui {

// Shown index of an element id or array index: itself, or one more in book numbering (-1 stays -1).
[[nodiscard]] inline std::int64_t shown(std::int64_t value, bool book) { return (book && value >= 0) ? value + 1 : value; }
// How panels number element `row` of a frame whose rows are the atoms `ids` (a dump's; null: none):
// its atom id, else the row in the chosen numbering.
[[nodiscard]] inline std::int64_t element_number(std::int64_t row, bool book, const std::vector<std::int64_t>* ids) {
  return ids != nullptr && row >= 0 && static_cast<std::size_t>(row) < ids->size() ? (*ids)[static_cast<std::size_t>(row)] : shown(row, book);
}
// A pair as panels write it: "(4, 6)", or "atoms (2753, 12)" when the frame's rows are atoms.
[[nodiscard]] inline std::string pair_text(const Pair& p, bool book, const std::vector<std::int64_t>* ids) {
  return std::string(ids != nullptr ? "atoms (" : "(") + std::to_string(element_number(p.i, book, ids)) + ", " +
         std::to_string(element_number(p.j, book, ids)) + ")";
}
// Violation `v`'s pair as its frame named it: "atoms (12, 40)" for a dump's ("atoms (4 of rank 1, 22
// of rank 0)" across two ranks' files), else "(4, 6)".
[[nodiscard]] inline std::string pair_text(const Violation& v, bool book) {
  return std::string(v.atom_i >= 0 ? "atoms (" : "(") + violation_pair_text(v, book ? 1 : 0) + ")";
}

// Where the window's own part of a frame's time went, in milliseconds (the pipeline's part, physics,
// detection and check, is FrameTimings, check/report.hpp).
struct DrawTimings {
  bool physics_overlapped = false;  // the physics ran on a worker thread while the frame before was drawn
  bool detection_overlapped = false;  // so did the detection and the check (not a plugin's)
  double trace_ms = 0;    // the traced detection for the list overlay
  double overlay_ms = 0;  // building the overlays (CPU)
  double render_ms = 0;   // submitting the scene to GL
  double ui_ms = 0;       // ImGui panels and their draw data
  double frame_ms = 0;    // wall time of the whole frame
  // A window's loop fills the rest (app/window_pacing.hpp: FrameSplitClock), averaged over about half
  // a second as FPS is, so that the parts sum to frame_ms; off-screen, `measured` stays false.
  bool measured = false;  // the fields below and every part above are of the same frames
  bool idle = false;      // paused with nothing moving: the loop sleeps until input comes
  double wait_ms = 0;     // waiting for input at the top of the frame (the idle sleep included)
  double swap_ms = 0;     // presenting the frame: the buffer swap (vsync)
  double physics_ms = 0, detection_ms = 0, check_ms = 0;  // the pipeline's runs on these frames (physics: not overlapped)
};

// The facts of the current frame that panels show. Pointers may be null (nothing loaded yet).
struct SimView {
  const FrameResult* frame = nullptr;  // the shown frame's result, the loop's own (null: nothing loaded)

  std::string scene_path;
  std::string scene_name;
  std::vector<std::string> scene_files;  // every scene in assets/scenes
  std::vector<std::string> algorithms;  // what the picker offers: the detectors, and `recorded` for a recording with pairs
  std::vector<std::string> detectors;   // the registry's 2D detectors (what the Scaling panel can time)
  std::string algorithm;
  std::string error;  // the last failed request (bad scene file, ...), shown in red
  Touching touching = Touching::inclusive;  // the contact convention (--touching), shown in Stats
  FrameUnit frame_unit = FrameUnit::frame;  // what frame numbers are: a dump's are timesteps (every label says so)
  Units units;  // the run's units (--units, a data file's, a LAMMPS log's): every length and time shown is in them
  int threads = 1;  // threads a detection may use (--threads): the Scaling panel compares 1 and this

  bool paused = false;
  double time_step = 1.0 / 60.0;
  double speed = 1.0;

  // The shown frame's source (the FrameResult holds no elements).
  std::int64_t bodies = 0;
  const Elements* elements = nullptr;
  const Subdomains* subdomains = nullptr;  // each MPI rank's subdomain (per-rank dumps), else null: no subdomains overlay
  // The layer of a 3D frame the view shows (core/layers.hpp: every element's layer, the layer's
  // neighbours), null for a 2D frame.
  const LayerSlice* layer = nullptr;
  const std::vector<TracedList>* lists = nullptr;  // only while the list overlay is on
  // The frame's FrameResult::trace, handed only when the lists overlay or the stepper asked for it
  // this frame (null otherwise; the stepper then asks for the next frame's, StepperSession::wants_trace).
  std::shared_ptr<const FrameTrace> trace;
  std::size_t detector_bytes = 0;  // the chosen detector's own arrays

  std::string fault_name;                    // an injected fault ("" for none): a banner says so
  std::string fault_description;

  // The run's history (Timeline panel) and violations (Violations panel).
  const std::deque<FrameSummary>* timeline = nullptr;  // every frame of the run, oldest first
  std::int64_t newest_frame = 0;     // the live frame (a recording: its last)
  bool showing_past = false;         // the frame shown is a kept past frame
  bool replaying = false;            // recorded frames: nothing to resume
  int play_direction = 1;            // while not paused: +1 forwards, -1 backwards through the kept frames
  std::size_t history_bytes = 0, history_budget = 0;
  std::int64_t history_dropped = 0;  // frames whose states the budget dropped
  bool resuming = false;             // re-simulating towards the shown frame
  std::int64_t resume_done = 0, resume_target = 0;
  std::string resume_note;           // how the last resume went ("identical to the first run", ...)
  const std::vector<Violation>* violations = nullptr;  // every violation of the run, in frame order
  std::int64_t violations_total = 0;  // listed or not
  std::array<std::int64_t, kInvariantCount> violations_by_invariant{};
  std::int64_t violation_frames = 0;  // frames with any
  std::uint64_t violations_generation = 0;  // changes whenever the list does
  std::string locate_status;          // where the stepper found the chosen violation's pair
  render::ScreenInsets scene_insets;  // pixels the panels cover at each edge (last frame)

  bool hide_timings = false;  // reproducible screenshots: no wall-clock numbers
  DrawTimings drawing;   // the window's own work on the frame (the pipeline's: frame->report().timings)
  double fps = 0;
  double sim_rate = -1;  // the simulation's own frames a second, apart from FPS (< 0: not measured, off-screen)
  std::vector<float> frame_history_ms;  // oldest first

  // Self-inspection.
  const render::RenderStats* render_stats = nullptr;
  int imgui_vertices = 0, imgui_indices = 0, imgui_lists = 0;
  std::size_t trace_events = 0, trace_bytes = 0;
  std::string gl_description;
  int width = 0, height = 0;

  // "frame 12" or "timestep 20000": frame `number` as every panel names it.
  [[nodiscard]] std::string frame_label(std::int64_t number) const { return nbscope::frame_label(frame_unit, number); }
  // The shown frame's number (0 with nothing loaded).
  [[nodiscard]] std::int64_t frame_number() const { return frame != nullptr ? frame->frame : 0; }
  // The shown frame's simulated time in seconds (0 with nothing loaded).
  [[nodiscard]] double sim_time() const { return frame != nullptr ? frame->time : 0; }
  // The chosen detector's grid this frame (null with nothing loaded).
  [[nodiscard]] const Grid* grid() const { return frame != nullptr ? &frame->selected().grid : nullptr; }
  // The chosen detector's pairs A this frame (null with nothing loaded).
  [[nodiscard]] const PairList* pairs() const { return frame != nullptr ? &frame->selected().pairs : nullptr; }
  // The chosen detector's report this frame: counts, timings, check, violations (null with nothing loaded).
  [[nodiscard]] const FrameReport* report() const { return frame != nullptr ? &frame->report() : nullptr; }
  // The atom ids of the shown frame's rows as the frame carries them (a dump's), or null when its
  // elements are named by their rows: every panel names an element by them. A violation of another
  // frame names its own atoms (Violation::atom_i, atom_j).
  [[nodiscard]] const std::vector<std::int64_t>* ids() const { return frame != nullptr ? frame->ids.get() : nullptr; }
};

// Open/closed panels, overlays and interaction state: owned by the app, edited by the UI.
struct UiState {
  render::OverlayFlags overlays;
  std::map<std::string, bool> panel_open;  // by panel title; absent = the panel's default
  ElementId selected = -1;
  std::optional<Pair> selected_pair;  // a violation's pair: both elements marked, the camera on them
  std::optional<std::array<std::int32_t, 2>> selected_cell;  // the cell last clicked (stepper: its operations)
  std::int64_t current_violation = -1;  // index into SimView::violations of the one gone to
  std::array<bool, kInvariantCount> violation_filter{true, true, true, true, true, true};  // invariants listed
  bool follow_operation = false;  // the camera follows the stepper's current operation
  // The lists overlay's filter; unset: Row past render::kRowFilterAbove elements, else All.
  std::optional<render::ListFilter> list_filter;
  std::int64_t history_budget_mb = 256;  // the Timeline's memory budget, saved in the settings
  bool book_numbering = false;  // element ids and cell indices shown (and typed) from 1, as the book prints them
  std::optional<std::array<std::int32_t, 2>> hovered_cell;
  // The layer of a 3D frame the user chose (slider, keys, the side view's band); unset: the view
  // chooses (the selected element's or pair's layer, else the busiest). Clamped to the frame's layers.
  std::optional<std::int32_t> layer;
  bool side_view_yz = false;  // the side view shows y-z instead of x-z
  std::optional<Eigen::Vector2d> mouse_world;
  bool dragging = false;
  std::string open_path;  // the Scenes panel's file field
  std::string algorithm_key_note;  // a digit key with no algorithm: the Algorithm panel says so
};

// What the user asked for this frame; the app applies it after the UI is drawn.
struct UiRequests {
  bool toggle_pause = false;
  bool step_once = false;
  bool restart = false;
  bool quit = false;
  std::optional<std::string> algorithm;
  std::optional<std::string> scene;
  std::optional<double> time_step;
  std::optional<double> speed;
  bool camera_home = false;
  // History: a kept frame, a step through the kept frames (, . and Shift), play backwards (J) or
  // forwards, resume the simulation from the past frame shown, a new memory budget.
  std::optional<std::int64_t> show_frame;
  std::optional<std::int64_t> frame_delta;
  std::optional<int> play;  // +1 forwards, -1 backwards (toggles when already playing that way)
  bool resume_here = false;
  bool cancel_resume = false;
  std::optional<std::int64_t> history_budget_mb;
  // Violations: go to SimView::violations[index] (its frame, both elements, the camera, the stepper).
  std::optional<std::size_t> go_to_violation;
  // Mouse joint: begin at a world point, move to one, end.
  std::optional<Eigen::Vector2d> drag_begin;
  std::optional<Eigen::Vector2d> drag_to;
  bool drag_end = false;

  // Equal requests; a default-constructed UiRequests asks for nothing.
  friend bool operator==(const UiRequests&, const UiRequests&) = default;
};

// What the host lets one panel's window take this frame.
struct PanelRoom {
  float height = 1e9f;   // the most its window may be tall (a docked panel windows its rows to it)
  bool stepping = false;  // the stepping layout (the Stepper open): show the essentials only
};

// Everything a panel gets each frame.
struct UiContext {
  const SimView& sim;
  UiState& state;
  UiRequests& requests;
  render::Camera& camera;
  PanelRoom room{};  // set by the host before each panel draws
};

}  // namespace nbscope::ui

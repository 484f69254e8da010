// nbscope app: the GL side of one frame, shared by the window and the headless screenshot: the
// scene and its overlays through the renderer, then the ImGui panels, from one FrameLoop. The two
// loops differ only in where the pixels go and whether input is live.
//
// Index: Session (what the surrounding loop knows) | GlView (following the loop's changes, frame).
#pragma once
#include <chrono>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "app/frame_loop.hpp"
#include "app/scaling_job.hpp"
#include "app/view_options.hpp"
#include "core/frame_trace.hpp"
#include "core/layers.hpp"
#include "io/png.hpp"
#include "render/camera_framing.hpp"
#include "render/colour_map.hpp"
#include "render/gl_context.hpp"
#include "render/imgui_layer.hpp"
#include "render/renderer.hpp"
#include "ui/host.hpp"
#include "ui/stepper_session.hpp"
#include "ui/window_input.hpp"

struct GLFWwindow;

namespace nbscope {

// The panel (ui/panel_scenes.cpp) that shows Session::error in red: opened when a world stops.
inline constexpr const char* kScenesPanel = "Scenes";

// What the loop around the view knows and the panels show.
struct Session {
  std::string scene_path;
  std::vector<std::string> scene_files;
  bool paused = false;
  int play_direction = 1;  // +1 forwards (past frames: through the kept ones, then live), -1 backwards
  double speed = 1.0;
  std::string resume_note;  // how the last resume went
  std::string error;
  double fps = 0;
  double frame_ms = 0;
  std::int64_t frames_simulated = 0;  // frames the simulation completed (stepped forwards), for sim_rate
  double sim_rate = -1;               // the simulation's own frames a second (app/window_pacing.hpp: SimRate); < 0 off-screen
  ui::DrawTimings split;  // the window loop's frame split, averaged (app/window_pacing.hpp); off-screen: not measured
};

// Every scene file in the bundled assets/scenes directory, sorted.
std::vector<std::string> bundled_scene_files();
// The bundled default scene (assets/scenes/default.json).
std::string default_scene_path();

class GlView {
 public:
  // ImGui sizes auto-resizing windows over its first frames, the host then fits its columns, and
  // the camera refits to the space the panels leave: a scripted screenshot (window or headless) is
  // taken after this many frames drawn on the final state, so both show the same settled layout.
  static constexpr int kSettleFrames = 5;

  // Loads the shaders (Error when missing) and sets overlays, panels and selection from `options`
  // (Error for an unknown name), then takes its first look at `loop` (its scene fitted as loaded).
  // `context` must be current; `window` is null headless. From then on the view follows the loop's
  // changes by itself whenever it draws (frame(), focus_violation()): nobody tells it.
  GlView(render::GlContext& context, GLFWwindow* window, const ViewOptions& options, const FrameLoop& loop);
  ~GlView();
  GlView(const GlView&) = delete;
  GlView& operator=(const GlView&) = delete;

  // Error("--select: ...") when the element chosen on the command line (in the shown numbering) is
  // not in `loop`'s scene.
  void check_selection(const FrameLoop& loop) const;
  // Error("--layer: ...") when --layer K was given and `loop`'s frame is 2D, or K is past its top
  // layer (call once the frame is loaded and detected).
  void check_layer(const FrameLoop& loop) const;
  // Error("--step: ...") when --step asked for more operations than the shown frame's detection
  // has, or its algorithm records none (call after frame(), before the screenshot).
  void check_step() const;
  // Shows `violation` (of the loop's current frame) as choosing it in the Violations panel does: both
  // elements selected, the camera on them, the Violations panel open; with `open_stepper` (or the
  // stepper already open) the stepper moves to the operation that decided the pair.
  void focus_violation(const FrameLoop& loop, const Violation& violation, bool open_stepper = true);
  // Draws one frame (scene, overlays, panels) into the current framebuffer and returns what the
  // user asked for. `live_input` lets keys and mouse act (the window, not scripted runs).
  ui::UiRequests frame(FrameLoop& loop, const Session& session, bool live_input, float dt);
  // True while the view changes without input (the stepper playing through a frame's operations, a
  // Scaling run filling its plots, key taps still to be given to the panels), so the window must
  // keep drawing even when paused.
  [[nodiscard]] bool animating() const;
  // The window's key and mouse-button events since the last frame, in order: live frames give them
  // to the panels one change of a key or button a frame (ui::InputReplay), so no tap is lost.
  void queue_input(std::span<const render::InputEvent> events) { input_.add(events); }
  // The framebuffer as an image (after frame(), before presenting).
  [[nodiscard]] Image screenshot() const { return context_.read_pixels(); }

  [[nodiscard]] ui::UiState& state() { return state_; }
  [[nodiscard]] render::Camera& camera() { return camera_; }
  [[nodiscard]] ui::UiHost& host() { return host_; }
  // The stepper panels' session (its trace is the frame loop's) and the lists the overlay drew last.
  [[nodiscard]] ui::StepperSession& stepper() { return *stepper_; }
  [[nodiscard]] const std::vector<TracedList>& lists() const { return lists_.lists; }
  // The layer of a 3D frame the last frame() showed (null for a 2D frame): gl_view_layer.cpp.
  [[nodiscard]] const LayerSlice* layer() const { return layer_ ? &*layer_ : nullptr; }
  // The layer --layer K pinned (headless: it wins over a violation's layer); nullopt: the view chooses.
  [[nodiscard]] std::optional<std::int32_t> layer_option() const { return choices_.layer; }
  // The bodies the last frame() handed the renderer (a 3D frame: the layer shown's and the one below's).
  [[nodiscard]] const std::vector<render::ShapeDraw>& shapes() const { return scratch_.shapes; }
  // --layer's value ("", "auto" or a whole number, as parse_view_options checked it): a number pins
  // UiState::layer; "auto" leaves the view to choose.
  void set_layer_option(const std::string& text);
  // The selection's trail and each element's cell-change flash (1 on the frame its cell changed,
  // then fading each step), as the last frame() drew them.
  [[nodiscard]] const std::vector<std::vector<render::Vec2>>& trails() const { return followed_.trails; }
  [[nodiscard]] const std::vector<float>& flashes() const { return followed_.flashes; }
  // The Scaling panel's background run (owned here; cancelled when the panel closes).
  [[nodiscard]] ScalingJob& scaling() { return *scaling_; }
  // Where the last frame's time went (overlays, GL submit, panels, traced detection), in ms.
  using Cost = ui::DrawTimings;  // the window's one timings type (its frame_ms: the panels' copy only)
  [[nodiscard]] const Cost& last_cost() const { return cost_; }

 private:
  void update_lists(const FrameLoop& loop, const std::shared_ptr<const FrameTrace>& trace);
  // The lists overlay's part of `scene` from the stepper's current operation and the filter.
  void describe_lists(const FrameLoop& loop, const std::shared_ptr<const FrameTrace>& trace, render::OverlayScene& scene) const;
  void build_shapes(const FrameLoop& loop);
  // The layer shown of a 3D frame (layer_), chosen and sliced once per change of frame or layer.
  void update_layer(const FrameLoop& loop, const std::shared_ptr<const FrameTrace>& trace);
  // The layer the view shows: the stepper's mid-frame, else the user's (clamped), else the focus
  // pair's, the selected element's, the busiest.
  [[nodiscard]] std::int32_t choose_layer(const FrameLoop& loop, const std::shared_ptr<const FrameTrace>& trace,
                                          const LayerSlice& slice);
  // The stepper's position while it is mid-way through `trace`, this frame's (nullptr otherwise).
  [[nodiscard]] const Stepper* stepping_through(const std::shared_ptr<const FrameTrace>& trace) const;
  void build_checks(const FrameLoop& loop);
  // --color-by's fills and legend for the frame shown, made again when the loop changes it
  // (gl_view_scene.cpp); Error for a column the frame does not have.
  void update_colours(const FrameLoop& loop);
  // Fills the panels' view of this frame (gl_view_panels.cpp).
  void fill_panels_view(const FrameLoop& loop, const Session& session, const std::shared_ptr<const FrameTrace>& trace,
                        ui::SimView& sim);
  // The view's drawing costs into `sim` (the window's whole frame split when it measured one).
  void fill_drawing(const FrameLoop& loop, const Session& session, ui::SimView& sim) const;
  void fit_camera(const FrameLoop& loop);
  // Catches up with what the loop did since the last look (FrameLoop::change): a new source forgets
  // lists and the focus (the camera fits a scene this view had not shown; a restart keeps it); a
  // frame moved to (a step, a frame shown, however many since) brings the selection along by atom
  // id, the trail from the history and the flashes from the loop's cell changes; a redetect
  // changes nothing seen. Nothing changed: no-op. Called first by frame() and focus_violation().
  void follow(const FrameLoop& loop);
  // follow()'s new source (with `fit`, the camera on it).
  void source_loaded(const FrameLoop& loop, bool fit);
  // The selected element's trail over the kept frames up to the one shown.
  void rebuild_trail(const FrameLoop& loop);
  // A dump's frame replaced the one last followed: the selection, a violation's pair, the trail and
  // the flashes follow their atoms' ids to their new rows (none when the atom is gone).
  void follow_atoms(const FrameLoop& loop);
  // The Stepper just opened: it goes to the operation of the violation chosen before (as if it had
  // been open when the violation was chosen).
  void aim_stepper_at_chosen_violation(const FrameLoop& loop);
  // True when the panel titled `title` is open.
  [[nodiscard]] bool panel_open(std::string_view title) const;
  [[nodiscard]] bool stepper_open() const;
  // Any of the Stepper, Arrays and Pseudocode panels is open: each shows the held trace.
  [[nodiscard]] bool stepper_panels_open() const;

  // What the command line chose (ViewOptions), kept for the loads and checks to come.
  struct Choices {
    bool hide_timings = false;
    Units units;                                  // the run's units (ViewOptions::units): the panels show lengths and times in them
    std::optional<std::array<double, 3>> camera;  // --camera: replaces the fit on load
    std::int64_t select = -1;                     // --select K as typed (book numbering: from 1)
    std::optional<std::int64_t> step;             // --step K
    std::optional<std::int32_t> layer;            // --layer K
    std::optional<std::string> colour_by;         // --color-by WHAT
  };
  // --color-by's colours of the frame shown, and the loop's generation they were made for.
  struct Colours {
    std::optional<std::uint64_t> generation;
    std::vector<render::Rgba> fills;
    render::ColourKey key;
  };
  // The view's catch-up with the loop (follow()) and what it derived from it.
  struct Followed {
    std::optional<std::uint64_t> generation;  // the loop's generation last followed (none: never)
    std::string scene;                        // the scene last loaded: a selection survives a restart, not a new scene
    bool had_scene = false;                   // the last source followed had a scene (not a world stopped at load)
    std::shared_ptr<const std::vector<std::int64_t>> ids;  // its atom ids (a dump's), kept with it
    ElementId trail_element = -1;             // the element `trails` was built for (a new selection rebuilds it)
    std::vector<std::vector<render::Vec2>> trails;  // from the loop's history
    std::vector<float> flashes;                     // from the loop's cell changes
    bool fitted_empty = false;  // Home fitted a frame without elements: the first frame with some is fitted again
  };
  // The lists overlay, rebuilt from the frame loop's trace when it or the stepper's position changes.
  struct ListsCache {
    std::vector<TracedList> lists;
    std::uint64_t serial = 0;  // the trace they were built from
    std::size_t upto = 0;      // the events applied (SIZE_MAX: all)
    std::chrono::steady_clock::time_point built_at;  // the last rebuild (throttled while playing)
  };
  // Per-frame scratch, kept to avoid reallocating.
  struct Scratch {
    std::vector<BodyShape> body_shapes;
    std::vector<render::ShapeDraw> shapes;
    std::vector<render::Vec2> shape_points;
    render::CheckDraw checks;
    std::vector<std::pair<ElementId, float>> flash_list;
  };

  render::GlContext& context_;
  std::unique_ptr<render::Renderer> renderer_;
  std::unique_ptr<render::ImGuiLayer> imgui_;
  ui::UiHost host_;
  ui::UiState state_;
  render::Camera camera_;
  Choices choices_;
  std::shared_ptr<ui::StepperSession> stepper_;
  std::shared_ptr<ScalingJob> scaling_ = std::make_shared<ScalingJob>();
  // Home (the scene fitted, or --camera's view on load), a violation's pair kept in view, the refit
  // when the panels change the free space.
  render::CameraFraming framing_;
  ui::InputReplay input_;  // the window's key and button events, given to ImGui in order
  std::string gl_description_;
  Cost cost_;
  Scratch scratch_;
  Colours colours_;
  // The layer shown of a 3D frame, and the frame change it was sliced for.
  std::optional<LayerSlice> layer_;
  std::uint64_t layer_generation_ = 0;
  ListsCache lists_;
  Followed followed_;
  bool stepper_was_open_ = false;  // the Stepper was open in the last frame()
  std::vector<float> frame_history_;
};

}  // namespace nbscope

// Index: scene files | GlView: set-up, following the loop's changes, frame. The --overlays and --panels
// specs are parsed in view_spec.hpp; the lists overlay's part is in gl_view_lists.cpp; the bodies
// and check sets drawn, in gl_view_scene.cpp.
#include "app/gl_view.hpp"

#include "app/clock.hpp"
#include "app/headless.hpp"
#include "check/recorded_lane.hpp"
#include "app/view_spec.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <tuple>

#include "core/error.hpp"
#include "core/pairs.hpp"
#include "io/data_dir.hpp"
#include "render/overlays.hpp"
#include "render/shader.hpp"
#include "ui/panels.hpp"
#include "ui/scaling_panel.hpp"
#include "ui/stepper_panels.hpp"

namespace nbscope {

namespace {

constexpr std::size_t kTrailPoints = 240;
constexpr float kFlashDecay = 0.8f;  // per frame: a flash fades over ~10 frames
constexpr std::size_t kFrameHistory = 240;
// A fit leaves this much below the scene for the legend (render::draw_scene's lower right corner).
constexpr double kLegendReservePx = 44.0;

}  // namespace

// ---- scene files ------------------------------------------------------------------------------

std::vector<std::string> bundled_scene_files() {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(data_dir().path + "/assets/scenes", ec))
    if (entry.path().extension() == ".json") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

std::string default_scene_path() { return data_dir().path + "/assets/scenes/default.json"; }

// ---- GlView -----------------------------------------------------------------------------------

GlView::GlView(render::GlContext& context, GLFWwindow* window, const ViewOptions& options, const FrameLoop& loop)
    : context_(context), framing_(kLegendReservePx, render::FocusZoom{6, 2}) {
  renderer_ = std::make_unique<render::Renderer>(render::resolve_shader_dir(options.shader_dir));
  imgui_ = std::make_unique<render::ImGuiLayer>(window);
  gl_description_ = context.describe();
  choices_.hide_timings = options.no_timings;
  choices_.units = options.units;
  camera_.set_viewport(context.width(), context.height());

  apply_overlay_spec(options.overlays, state_.overlays);
  stepper_ = ui::add_stepper_panels(
      host_, ui::StepperConfig{options.step ? std::optional<std::size_t>(*options.step) : std::nullopt, options.book_numbering});
  choices_.step = options.step;
  state_.book_numbering = options.book_numbering;
  if (options.step) ui::open_stepper_panels(state_);
  host_.add_panel(ui::make_scaling_panel(scaling_));
  if (options.scaling) {
    scaling_->show(options.scaling->result, options.scaling->plan, options.scaling->source, options.scaling->seconds);
    state_.panel_open[ui::kScalingTitle] = true;
  }
  std::vector<std::string> panel_names;
  for (const auto& p : host_.panels()) panel_names.push_back(lower(p->title()));
  apply_spec(
      "--panels", options.panels, panel_names,
      [&](bool on) {
        for (const auto& p : host_.panels()) state_.panel_open[p->title()] = on;
      },
      [&](const std::string& name, bool on) {
        for (const auto& p : host_.panels())
          if (name == lower(p->title())) state_.panel_open[p->title()] = on;
      });
  // --select takes the number shown: from 1 in book numbering (0 then selects nothing; check_selection refuses it).
  choices_.select = options.select;
  state_.selected = options.select < 0 ? -1 : options.book_numbering ? options.select - 1 : options.select;
  followed_.trail_element = state_.selected;
  choices_.camera = options.camera;
  choices_.colour_by = options.colour_by;
  set_layer_option(options.layer);
  for (std::size_t f = 0; f < std::size(render::kListFilterNames); ++f)
    if (options.lists == render::kListFilterNames[f]) state_.list_filter = static_cast<render::ListFilter>(f);
  follow(loop);  // the scene as loaded: the camera fits it (a saved camera or a focus may replace the fit)
  if (loop.source().has_scene()) update_colours(loop);  // an unknown --color-by column: refused before anything is drawn
}

GlView::~GlView() {
  // ImGui's GL objects go before the renderer's, both while the context is still current.
  imgui_.reset();
  renderer_.reset();
}

void GlView::fit_camera(const FrameLoop& loop) {
  // The elements and half a cell around them: the neighbour cells and the list heads stay in view
  // even when the grid is pinned much larger (the book's 10x10 figure).
  camera_.set_viewport(context_.width(), context_.height());
  framing_.set_home_box(render::elements_box(loop.source().elements(), loop.result().selected().grid));
  framing_.go_home(camera_, host_.insets(state_));
  followed_.fitted_empty = loop.source().elements().size() == 0;
}

void GlView::check_selection(const FrameLoop& loop) const {
  if (choices_.select < 0) return;
  // A dump's frame shows atom ids: --select names one of them.
  if (const std::vector<std::int64_t>* ids = loop.result().ids.get()) {
    if (std::find(ids->begin(), ids->end(), choices_.select) == ids->end())
      throw Error("--select: atom " + std::to_string(choices_.select) + " is not in " + frame_label(frame_unit_of(loop.source()), loop.source().frame()) +
                  " (its elements are named by their atom ids)");
    return;
  }
  const std::int64_t n = loop.source().elements().size();
  const bool book = state_.book_numbering;
  if (!(book ? (choices_.select < 1 || choices_.select > n) : choices_.select >= n)) return;
  const std::string numbered = n == 0                ? ""
                               : book                ? ", numbered 1.." + std::to_string(n) + " in book numbering"
                                                     : ", numbered 0.." + std::to_string(n - 1) + "; --book-numbering counts from 1";
  throw Error("--select: element " + std::to_string(choices_.select) + " does not exist (the scene has " + std::to_string(n) +
              " elements" + numbered + ")");
}

void GlView::check_step() const {
  if (!choices_.step) return;
  const ui::StepperSession& s = *stepper_;
  if (!s.has_capture()) throw Error("--step: " + (s.message().empty() ? std::string("nothing was recorded") : s.message()));
  const std::size_t n = s.stepper().size();
  if (static_cast<std::uint64_t>(*choices_.step) > n)
    throw Error("--step: " + std::to_string(*choices_.step) + " is past the last of the " + std::to_string(n) +
                " operations of frame " + std::to_string(s.frame()) + " (" + s.algorithm() + ")");
}

void GlView::follow(const FrameLoop& loop) {
  const FrameChange& c = loop.change();
  if (followed_.generation && *followed_.generation == c.generation) return;
  const bool new_source = !followed_.generation || c.loaded_at > *followed_.generation;
  const bool moved = followed_.generation && c.moved_at > *followed_.generation;
  followed_.generation = c.generation;
  if (new_source) {
    // The camera fits a scene it had not shown (or the first that runs); a restart keeps it.
    source_loaded(loop, !followed_.had_scene || followed_.scene != loop.source().scene().path);
  } else if (moved) {
    follow_atoms(loop);
    // A run's first frame may have no atoms (LIGGGHTS's timestep 0, before insertion): the first
    // frame with some is what Home fits, unless the user has moved the camera or --camera pins it.
    if (followed_.fitted_empty && loop.source().elements().size() > 0 && camera_.at_home() && !choices_.camera) fit_camera(loop);
  }
  followed_.ids = loop.result().ids;
  // Only redetected: the same frame, nothing seen changes (the lists follow the trace, update_lists).
  if (!new_source && !moved) return;
  rebuild_trail(loop);
  const CellChanges& changes = loop.cell_changes();
  followed_.flashes.resize(changes.size());
  for (std::size_t k = 0; k < followed_.flashes.size(); ++k) followed_.flashes[k] = changes.flash(static_cast<ElementId>(k), kFlashDecay);
}

void GlView::source_loaded(const FrameLoop& loop, bool fit) {
  // Element k of another scene is another body: the selection is kept across a restart only (and
  // for the first scene, where --select chose it).
  if (!followed_.scene.empty() && followed_.scene != loop.source().scene().path) {
    state_.selected = -1;
    stepper_->focus_element = -1;
  }
  // --select on a dump's first frame names an atom id (as shown), not a row.
  const std::vector<std::int64_t>* ids = loop.result().ids.get();
  if (followed_.scene.empty() && choices_.select >= 0 && ids != nullptr) {
    const auto it = std::find(ids->begin(), ids->end(), choices_.select);
    state_.selected = it == ids->end() ? -1 : static_cast<ElementId>(it - ids->begin());
  }
  followed_.scene = loop.source().scene().path;
  followed_.had_scene = loop.source().has_scene();
  lists_.lists.clear();
  lists_.serial = 0;
  if (state_.selected >= loop.source().elements().size()) state_.selected = -1;
  state_.selected_pair.reset();
  state_.selected_cell.reset();
  state_.current_violation = -1;
  framing_.forget_focus();
  if (fit) fit_camera(loop);
  if (fit && choices_.camera) {
    // --camera X,Y,PPM: (X, Y) in the middle of the part of the view the panels leave free.
    framing_.set_home_view(*choices_.camera);
    framing_.go_home(camera_, host_.insets(state_));
  }
}

void GlView::follow_atoms(const FrameLoop& loop) {
  // The ids of the frame last followed, of the same recording (a new source is not followed here);
  // the flashes follow their atoms in the loop (check/cell_changes.hpp), the trail the selection.
  const std::vector<std::int64_t>* before = followed_.ids.get();
  const std::vector<std::int64_t>* after = loop.result().ids.get();
  if (before == nullptr || after == nullptr || before == after) return;
  state_.selected = row_of_atom(*before, *after, state_.selected);
  stepper_->focus_element = row_of_atom(*before, *after, stepper_->focus_element);
  if (state_.selected_pair) {
    const ElementId i = row_of_atom(*before, *after, state_.selected_pair->i), j = row_of_atom(*before, *after, state_.selected_pair->j);
    if (i < 0 || j < 0) state_.selected_pair.reset();
    else state_.selected_pair = Pair{std::min(i, j), std::max(i, j)};
  }
}

void GlView::rebuild_trail(const FrameLoop& loop) {
  // The selected element over the kept frames up to the one shown (at most kTrailPoints of them).
  followed_.trails.clear();
  followed_.trail_element = state_.selected;
  if (followed_.trail_element < 0) return;
  std::vector<std::array<double, 2>> path;
  loop.history().element_path(followed_.trail_element, loop.source().frame() - static_cast<std::int64_t>(kTrailPoints) + 1, loop.source().frame(), path);
  auto& t = followed_.trails.emplace_back();
  for (const auto& p : path) t.emplace_back(static_cast<float>(p[0]), static_cast<float>(p[1]));
}

void GlView::focus_violation(const FrameLoop& loop, const Violation& v, bool open_stepper) {
  follow(loop);  // the change that brought this frame (e.g. it was just shown) before the focus
  const Elements& e = loop.source().elements();
  if (v.pair.i < 0 || v.pair.j < 0 || v.pair.i >= e.size() || v.pair.j >= e.size()) return;
  state_.selected = v.pair.i;
  state_.selected_pair = v.pair;
  state_.selected_cell = std::array<std::int32_t, 2>{v.cell_i.ix, v.cell_i.iy};
  state_.layer.reset();  // a 3D frame shows the layer whose pass finds the pair (choose_layer)
  state_.panel_open[ui::kViolationsTitle] = true;
  const auto& log = loop.history().violation_log().listed();
  state_.current_violation = -1;  // unless it is still listed (the frame was checked again)
  for (std::size_t k = 0; k < log.size(); ++k)
    if (log[k].frame == v.frame && log[k].pair == v.pair && log[k].invariant == v.invariant) {
      state_.current_violation = static_cast<std::int64_t>(k);
      break;
    }
  // The pair as the check measures it: i and j's nearest image (across a periodic edge, not the box apart).
  const Eigen::Vector2d a(e.x[v.pair.i], e.y[v.pair.i]);
  const Eigen::Vector2d b = a + Eigen::Vector2d(axis_delta(e, 0, e.x[v.pair.j] - a.x()), axis_delta(e, 1, e.y[v.pair.j] - a.y()));
  // The pair's middle in the middle of the free view, zoomed so that it spans a sixth to a half of it.
  camera_.set_viewport(context_.width(), context_.height());
  framing_.focus(camera_, 0.5 * (a + b), (b - a).norm() + e.r[v.pair.i] + e.r[v.pair.j], host_.insets(state_));
  rebuild_trail(loop);
  if (open_stepper) state_.panel_open[ui::kStepperTitle] = true;
  if (stepper_open()) stepper_->set_target(ui::StepperSession::PairTarget{v.frame, v.pair, v.invariant, v.what});
}

void GlView::aim_stepper_at_chosen_violation(const FrameLoop& loop) {
  // Still chosen: listed, on the frame shown, its pair still the one marked (no click since).
  const auto& log = loop.history().violation_log().listed();
  if (state_.current_violation < 0 || static_cast<std::size_t>(state_.current_violation) >= log.size()) return;
  const Violation& v = log[static_cast<std::size_t>(state_.current_violation)];
  if (v.frame != loop.source().frame() || state_.selected_pair != v.pair) return;
  stepper_->set_target(ui::StepperSession::PairTarget{v.frame, v.pair, v.invariant, v.what});
}

bool GlView::panel_open(std::string_view title) const {
  for (const auto& p : host_.panels())
    if (p->title() == title) return ui::UiHost::is_open(*p, state_);
  return false;
}

bool GlView::stepper_open() const { return panel_open(ui::kStepperTitle); }

bool GlView::animating() const {
  return (stepper_->stepper().playing() && stepper_panels_open()) || scaling_->running() ||  // a Scaling run fills its plots
         input_.pending();  // taps given one frame each
}

bool GlView::stepper_panels_open() const {
  return panel_open(ui::kStepperTitle) || panel_open(ui::kArraysTitle) || panel_open(ui::kPseudocodeTitle);
}

ui::UiRequests GlView::frame(FrameLoop& loop, const Session& session, bool live_input, float dt) {
  const auto frame_start = Clock::now();
  follow(loop);
  if (state_.selected != followed_.trail_element) rebuild_trail(loop);  // a new selection: its own trail
  const bool stepper_now_open = stepper_open();
  if (stepper_now_open && !stepper_was_open_) aim_stepper_at_chosen_violation(loop);
  stepper_was_open_ = stepper_now_open;
  camera_.set_viewport(context_.width(), context_.height());
  const Elements& e = loop.source().elements();
  if (state_.selected >= e.size()) state_.selected = -1;

  // The one traced detection of this frame, made when the lists overlay or the stepper wants it.
  cost_.trace_ms = 0;
  auto t0 = Clock::now();
  const bool stepper_wants = stepper_panels_open() && stepper_->wants_trace(loop.source().frame(), session.paused);
  // The frames to come record it in their one detection, while it is wanted: a plugin is called once a frame.
  // A plugin that traces records every frame, as headless does: its contracts are checked along each.
  loop.pipeline().record_traces(state_.overlays.lists || stepper_wants || traces_every_frame(loop.pipeline().algorithm()));
  const std::shared_ptr<const FrameTrace> trace = state_.overlays.lists || stepper_wants ? loop.pipeline().frame_trace() : nullptr;
  cost_.trace_ms = ms_since(t0);
  update_lists(loop, trace);
  update_layer(loop, trace);
  t0 = Clock::now();
  build_shapes(loop);
  build_checks(loop);
  update_colours(loop);
  scratch_.flash_list.clear();
  for (std::size_t k = 0; k < followed_.flashes.size(); ++k)
    if (followed_.flashes[k] > 0.05f) scratch_.flash_list.emplace_back(static_cast<ElementId>(k), followed_.flashes[k]);

  render::OverlayScene scene;
  scene.elements = &e;
  scene.grid = &loop.result().selected().grid;
  scene.shapes = scratch_.shapes;
  scene.shape_points = scratch_.shape_points;
  scene.pairs = &loop.result().selected().pairs;
  scene.checks = &scratch_.checks;
  scene.lists = state_.overlays.lists ? &lists_.lists : nullptr;
  scene.layer = layer();
  scene.selected = state_.selected;
  scene.focus_pair = state_.selected_pair;
  scene.hovered_cell = state_.hovered_cell;
  describe_lists(loop, trace, scene);
  scene.trails = followed_.trails;
  scene.flashes = scratch_.flash_list;
  scene.insets = host_.insets(state_);  // last frame's panels: labels keep to the part of the view they leave free
  scene.covered = host_.covered();
  scene.book_numbering = state_.book_numbering;
  if (!choices_.units.name.empty()) scene.length_unit = choices_.units.length;  // d = 1.2 sigma (a scene's metres unsaid, as ever)
  scene.ids = loop.result().ids.get();  // a dump's atoms are labelled by their ids
  scene.subdomains = loop.source().subdomains();
  if (choices_.colour_by) {
    scene.element_fills = colours_.fills;
    scene.colour_key = &colours_.key;
  }
  if (loop.drag().active() && state_.selected >= 0 && state_.mouse_world)
    scene.drag = std::array<render::Vec2, 2>{
        render::Vec2(static_cast<float>(e.x[state_.selected]), static_cast<float>(e.y[state_.selected])),
        state_.mouse_world->cast<float>()};

  // The panels' view of this frame, filled before anything draws: the panels' scene parts read it too.
  ui::UiRequests requests;
  ui::SimView sim;
  const auto fill_start = Clock::now();
  fill_panels_view(loop, session, trace, sim);
  const double fill_ms = ms_since(fill_start);
  ui::UiContext ctx{sim, state_, requests, camera_};
  renderer_->begin_frame(camera_);
  render::draw_scene(scene, state_.overlays, camera_, *renderer_);
  host_.draw_scene(ctx, *renderer_);
  cost_.overlay_ms = ms_since(t0) - fill_ms;
  t0 = Clock::now();
  renderer_->draw(render::palette::kBackground);
  cost_.render_ms = ms_since(t0);
  fill_drawing(loop, session, sim);  // this frame's overlay and render times

  t0 = Clock::now();

  imgui_->new_frame(live_input, context_.width(), context_.height(), dt,
                    live_input ? std::function<void()>([this] { input_.apply(); }) : std::function<void()>());
  host_.frame(ctx, live_input);
  if (!panel_open(ui::kScalingTitle)) scaling_->cancel();  // a closed panel's run stops
  renderer_->emit_labels(ImGui::GetBackgroundDrawList());
  imgui_->render();
  cost_.ui_ms = ms_since(t0) + fill_ms;

  // The loop's whole-frame time when it measures one (the window), else this view's share.
  frame_history_.push_back(static_cast<float>(session.frame_ms > 0 ? session.frame_ms : ms_since(frame_start)));
  if (frame_history_.size() > kFrameHistory) frame_history_.erase(frame_history_.begin());
  if (requests.camera_home) {
    fit_camera(loop);
  } else {
    framing_.settle(camera_, host_.insets(state_));  // the focus kept, or Home again in the space the panels leave
  }
  return requests;
}

}  // namespace nbscope

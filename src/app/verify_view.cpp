// The verify view: one GL frame of a `verify --arrays` run (scene, red marks, panels), shared by the
// screenshot and the window; the window's input (pan, zoom, select, keys) and its tooltip.
//
// Index: VerifyView (set-up, camera, problems, frame, input) | write_verify_screenshot.
// The window loop and `gui --arrays` are in verify_window.cpp.
#include "app/verify_view_impl.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "core/cells.hpp"
#include "app/clock.hpp"
#include "app/view_spec.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/plural.hpp"
#include "render/shader.hpp"
#include "ui/window_input.hpp"

namespace nbscope {

namespace {
// Caption lines: as wide as the free view allows (ImGui's font: 7 px a character), within these.
constexpr std::size_t kMinCaptionChars = 40, kMaxCaptionChars = 110;

render::Vec2 v2(double x, double y) { return {static_cast<float>(x), static_cast<float>(y)}; }
}  // namespace

// ---- set-up -----------------------------------------------------------------------------------

VerifyView::VerifyView(render::GlContext& context, GLFWwindow* window, const VerifyArraysRun& run, const ViewOptions& options)
    : run_(run), context_(context), book_(run.user.base == 1), framing_(0.0, render::FocusZoom{4, 1.5}) {
  // The arrays are given whole (nothing to step), and numbered as their file counts.
  if (options.step) throw Error("--step: does not apply to a verify run (the arrays are given whole, no operations to step)");
  if (options.book_numbering && !book_)
    throw Error("--book-numbering: the arrays are drawn numbered as their file counts, from 0 here (--base 1, or its \"base\" key, numbers from 1)");
  renderer_ = std::make_unique<render::Renderer>(render::resolve_shader_dir(options.shader_dir));
  imgui_ = std::make_unique<render::ImGuiLayer>(window);
  camera_.set_viewport(context.width(), context.height());
  // The elements as plain discs (no bodies behind them), the grid, the lists and the ids.
  render::OverlayFlags& f = state_.overlays;
  f = render::OverlayFlags{};
  f.bodies = f.grid = f.lists = f.ids = true;
  f.elements = f.mask = f.pairs = f.checks = f.broadphase = f.trails = f.flash = false;
  apply_overlay_spec(options.overlays, f);
  std::vector<std::string> panel_names;
  for (const char* t : ui::kVerifyPanelTitles) panel_names.push_back(lower(t));
  apply_spec(
      "--panels", options.panels, panel_names,
      [&](bool on) {
        for (const char* t : ui::kVerifyPanelTitles) state_.panel_open[t] = on;
      },
      [&](const std::string& name, bool on) {
        for (const char* t : ui::kVerifyPanelTitles)
          if (name == lower(t)) state_.panel_open[t] = on;
      });
  const Elements& e = run.elements;
  if (options.select >= 0) {
    // --select K as shown: from 1 when the file counts from 1.
    const std::int64_t k = book_ ? options.select - 1 : options.select;
    if (k < 0 || k >= e.size())
      throw Error("--select: element " + std::to_string(options.select) + " does not exist (the elements are numbered " +
                  std::to_string(book_ ? 1 : 0) + ".." + std::to_string(e.size() - (book_ ? 0 : 1)) + ")");
    state_.selected_element = static_cast<ElementId>(k);
  }
  // --layer K of a 3D run, checked as the window checks a 3D frame's (GlView::check_layer); auto: the view's choice.
  if (!options.layer.empty() && options.layer != "auto") {
    const auto k = static_cast<std::int32_t>(std::stol(options.layer));
    if (e.dim != 3 || run.grid.dim != 3) throw Error("--layer: the elements are 2D (layers are those of a 3D grid)");
    const std::int64_t count = run.grid.n[2];
    if (k >= count)
      throw Error("--layer: " + std::to_string(k) + " is past the top layer " + std::to_string(count - 1) + " (the grid has " +
                  std::to_string(count) + (count == 1 ? " layer)" : " layers)"));
    layer_option_ = k;
  }
  for (std::size_t i = 0; i < std::size(render::kListFilterNames); ++i)
    if (options.lists == render::kListFilterNames[i]) list_filter_ = static_cast<render::ListFilter>(i);
  // Home: the elements and half a cell around them (neighbour cells and the heads stay in view), or --camera's view.
  framing_.set_home_box(render::elements_box(e, run.grid));
  if (options.camera) framing_.set_home_view(*options.camera);

  lists_ = render::user_lists(run.user, run.verdict, run.user.base);
  for (std::size_t i = 0; i < lists_.size(); ++i)
    for (const ElementId k : lists_[i].chain) on_lists_.emplace_back(k, static_cast<int>(i));
  std::sort(on_lists_.begin(), on_lists_.end());
  shapes_.reserve(static_cast<std::size_t>(e.size()));
  for (ElementId k = 0; k < static_cast<ElementId>(e.size()); ++k) {
    render::ShapeDraw d;
    d.centre = v2(e.x[k], e.y[k]);
    d.radius = static_cast<float>(e.r[k]);
    d.element = k;
    d.spoke = false;
    shapes_.push_back(d);
  }
  model_.user = &run.user;
  model_.verdict = &run.verdict;
  model_.lists = &lists_;
  model_.base = run.user.base;
  model_.source = run.user.algorithm + " arrays, " + plural(e.size(), "element") + (book_ ? ", numbered from 1" : "");
  select_problem(run.verdict.problems.empty() ? -1 : 0);
  fit();
}

VerifyView::~VerifyView() {
  // ImGui's GL objects go before the renderer's, both while the context is still current.
  imgui_.reset();
  renderer_.reset();
}

// ---- camera -----------------------------------------------------------------------------------

render::ScreenInsets VerifyView::panel_insets() const {
  return panels_seen_ ? layout_.insets : ui::verify_panel_insets(state_);
}

render::ScreenInsets VerifyView::fit_insets() const {
  render::ScreenInsets in = panel_insets();
  // Room under the scene for the legend: its lines (the cell shading, the list kinds, the red's key
  // and the caption) 15 px each.
  in.bottom += 15.0 * static_cast<double>(marks_.caption.size() + 3) + 16.0;
  return in;
}

void VerifyView::fit() {
  camera_.set_viewport(context_.width(), context_.height());
  framing_.go_home(camera_, fit_insets());
}

void VerifyView::focus_on(std::vector<ElementId> ks) {
  const Elements& e = run_.elements;
  ks.erase(std::remove_if(ks.begin(), ks.end(), [&](ElementId k) { return k < 0 || k >= e.size(); }), ks.end());
  if (ks.empty()) return;
  Eigen::Vector2d lo(e.x[ks[0]], e.y[ks[0]]), hi = lo;
  double r = 0;
  for (const ElementId k : ks) {
    lo = lo.cwiseMin(Eigen::Vector2d(e.x[k], e.y[k]));
    hi = hi.cwiseMax(Eigen::Vector2d(e.x[k], e.y[k]));
    r = std::max(r, e.r[k]);
  }
  // Its cells and their neighbours in view: at least two cells across.
  const double cell = run_.grid.dim == 2 ? run_.grid.cell_size : 0.0;
  // Zoomed so that it spans a quarter to two thirds of the free view.
  camera_.set_viewport(context_.width(), context_.height());
  framing_.focus(camera_, 0.5 * (lo + hi), std::max((hi - lo).norm() + 2 * r, 2 * cell), fit_insets());
}

// ---- problems ---------------------------------------------------------------------------------

void VerifyView::select_problem(int index) {
  const auto& problems = run_.verdict.problems;
  state_.selected_problem = index >= 0 && static_cast<std::size_t>(index) < problems.size() ? index : -1;
  const double free_px = context_.width() - panel_insets().left - panel_insets().right - 80.0;
  const auto chars = static_cast<std::size_t>(std::max(0.0, free_px / render::kCharPx));
  marks_ = render::verify_marks(run_.verdict, state_.selected_problem, std::clamp(chars, kMinCaptionChars, kMaxCaptionChars));
  update_layer();
}

void VerifyView::update_layer() {
  const Elements& e = run_.elements;
  if (e.dim != 3 || run_.grid.dim != 3) return;
  if (!layer_) layer_ = slice_layer(e, run_.grid, 0);
  const auto top = static_cast<std::int32_t>(run_.grid.n[2] - 1);
  const auto layer_of = [&](ElementId k) { return layer_->element_layer[static_cast<std::size_t>(k)]; };
  std::int32_t iz = busiest_layer(*layer_);
  if (layer_option_) {
    iz = std::clamp(*layer_option_, 0, top);
  } else if (state_.selected_problem >= 0) {
    for (const ElementId k : problem_elements(state_.selected_problem))
      if (k >= 0 && k < e.size()) {
        iz = layer_of(k);
        break;
      }
  } else if (state_.selected_element >= 0 && state_.selected_element < e.size()) {
    iz = layer_of(state_.selected_element);
  }
  if (iz != layer_->layer) layer_ = slice_layer(e, run_.grid, iz);
}

std::vector<ElementId> VerifyView::problem_elements(int index) const {
  const verify::Problem& p = run_.verdict.problems[static_cast<std::size_t>(index)];
  std::vector<ElementId> ks = p.elements;
  if (p.link) {
    ks.push_back(p.link->first);
    ks.push_back(p.link->second);
    // A link from a head: the list's first element stands for it.
    const int l = marks_.problems[static_cast<std::size_t>(index)].list;
    if (p.link->first < 0 && l >= 0 && !lists_[static_cast<std::size_t>(l)].chain.empty())
      ks.push_back(lists_[static_cast<std::size_t>(l)].chain.front());
  }
  return ks;
}

void VerifyView::go_to_problem(int index) {
  select_problem(index);
  state_.scroll_to_problem = true;
  if (state_.selected_problem >= 0) focus_on(problem_elements(state_.selected_problem));
}

void VerifyView::step_problem(int delta) {
  const int n = static_cast<int>(run_.verdict.problems.size());
  if (n == 0) return;
  const int at = state_.selected_problem < 0 ? (delta > 0 ? -1 : n) : state_.selected_problem;
  go_to_problem(std::clamp(at + delta, 0, n - 1));
}

// ---- frame ------------------------------------------------------------------------------------

void VerifyView::frame(bool live_input, float dt) {
  const auto t0 = Clock::now();
  camera_.set_viewport(context_.width(), context_.height());
  const Elements& e = run_.elements;
  render::OverlayScene scene;
  scene.elements = &e;
  scene.grid = &run_.grid;
  scene.shapes = shapes_;
  scene.lists = &lists_;
  scene.selected = state_.selected_element;
  scene.hovered_cell = hovered_cell_;
  scene.list_filter = list_filter_.value_or(e.size() > render::kRowFilterAbove ? render::ListFilter::Row : render::ListFilter::All);
  // The row the Row filter keeps: hovered, else the selected problem's, else the selected element's.
  if (hovered_cell_) scene.focus_row = (*hovered_cell_)[1];
  else if (state_.selected_problem >= 0) {
    for (const ElementId k : problem_elements(state_.selected_problem))
      if (k >= 0 && k < e.size()) {
        scene.focus_row = run_.grid.cell(e.y[k], 1);
        break;
      }
  } else if (state_.selected_element >= 0) {
    scene.focus_row = run_.grid.cell(e.y[state_.selected_element], 1);
  }
  scene.insets = panel_insets();
  scene.covered = layout_.covered;
  scene.book_numbering = book_;
  scene.verify = &marks_;
  scene.layer = layer();
  renderer_->begin_frame(camera_);
  render::draw_scene(scene, state_.overlays, camera_, *renderer_);
  renderer_->draw(render::palette::kBackground);

  imgui_->new_frame(live_input, context_.width(), context_.height(), dt);
  ui::VerifyUiRequests requests;
  layout_ = ui::draw_verify_panels(model_, state_, requests, static_cast<float>(context_.width()),
                                   static_cast<float>(context_.height()));
  panels_seen_ = true;
  if (live_input) handle_input(requests);
  renderer_->emit_labels(ImGui::GetBackgroundDrawList());
  imgui_->render();
  frame_ms_ = ms_since(t0);

  if (requests.go_to_problem) go_to_problem(*requests.go_to_problem);
  if (requests.go_to_list && static_cast<std::size_t>(*requests.go_to_list) < lists_.size())
    focus_on(lists_[static_cast<std::size_t>(*requests.go_to_list)].chain);
  if (requests.camera_home) {
    fit();
  } else {
    framing_.settle(camera_, fit_insets());  // the focus kept, or Home again in the space the panels leave
  }
}

// ---- input ------------------------------------------------------------------------------------

void VerifyView::handle_input(ui::VerifyUiRequests& requests) {
  const ImGuiIO& io = ImGui::GetIO();
  if (ui::keys_reach_scene()) {
    const auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
    ui::toggle_overlays_by_key(state_.overlays, "BGLIE");
    if (ImGui::IsKeyPressed('[', true)) step_problem(-1);
    if (ImGui::IsKeyPressed(']', true)) step_problem(+1);
    if (pressed(ImGui::GetKeyIndex(ImGuiKey_Home))) requests.camera_home = true;
    if (pressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
      state_.selected_element = -1;
      update_layer();
    }
    // A 3D run: Up/Down the layer above/below, as in the main window.
    for (const auto& [key, step] : {std::pair{ImGuiKey_UpArrow, 1}, std::pair{ImGuiKey_DownArrow, -1}})
      if (layer_ && ImGui::IsKeyPressed(ImGui::GetKeyIndex(key), true)) {
        layer_option_ = layer_->layer + step;
        update_layer();
      }
  }
  const std::optional<Eigen::Vector2d> mouse = ui::mouse_over_scene();
  if (!mouse) {
    hovered_cell_.reset();
    return;
  }
  const Eigen::Vector2d world = camera_.to_world(*mouse);
  hovered_cell_ = run_.grid.dim == 2 ? cell_at(run_.grid, world) : std::nullopt;
  // Either button drags the view; a left click that did not drag selects the element under it.
  ui::move_camera_by_mouse(camera_, *mouse, true);
  if (ImGui::IsMouseReleased(0) && io.MouseDragMaxDistanceSqr[0] <= ui::kClickSlopPx * ui::kClickSlopPx) {
    state_.selected_element = render::element_at(run_.elements, world, layer());
    update_layer();
    // An element at fault selects its (first) problem too.
    if (state_.selected_element >= 0)
      for (std::size_t i = 0; i < run_.verdict.problems.size(); ++i) {
        const auto ks = problem_elements(static_cast<int>(i));
        if (std::find(ks.begin(), ks.end(), state_.selected_element) != ks.end()) {
          select_problem(static_cast<int>(i));
          state_.scroll_to_problem = true;
          break;
        }
      }
  }
  draw_tooltip(render::element_at(run_.elements, world, layer()));
}

void VerifyView::draw_tooltip(ElementId k) const {
  if (k < 0) return;
  const Elements& e = run_.elements;
  const int base = run_.user.base;
  ImGui::BeginTooltip();
  const std::array<std::int32_t, 3> cell{static_cast<std::int32_t>(run_.grid.cell(e.x[k], 0)),
                                         static_cast<std::int32_t>(run_.grid.cell(e.y[k], 1)), -1};
  ImGui::Text("element %lld at (%.4g, %.4g), r %.3g, in cell %s", static_cast<long long>(k + base), e.x[k], e.y[k], e.r[k],
              verify::cell_name(cell, 2, base).c_str());
  const auto range = std::equal_range(on_lists_.begin(), on_lists_.end(), std::make_pair(k, -1),
                                      [](const auto& a, const auto& b) { return a.first < b.first; });
  if (range.first == range.second) ImGui::TextColored(ImVec4(1.0f, 0.47f, 0.45f, 1.0f), "on no list");
  for (auto it = range.first; it != range.second; ++it) {
    const auto l = static_cast<std::size_t>(it->second);
    ImGui::TextUnformatted(ui::list_line(run_.user, run_.verdict.lists[l], lists_[l], base, 16).c_str());
  }
  int shown = 0;
  for (std::size_t i = 0; i < run_.verdict.problems.size() && shown < 4; ++i) {
    const auto ks = problem_elements(static_cast<int>(i));
    if (std::find(ks.begin(), ks.end(), k) == ks.end()) continue;
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 36.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.47f, 0.45f, 1.0f), "%zu. %s", i + 1, run_.verdict.problems[i].text.c_str());
    ImGui::PopTextWrapPos();
    ++shown;
  }
  ImGui::EndTooltip();
}

// ---- write_verify_screenshot ------------------------------------------------------------------

std::string write_verify_screenshot(const VerifyArraysRun& run, const ViewOptions& view) {
  if (!view.screenshot) throw Error("internal: write_verify_screenshot without a screenshot path");
  check_output_path(*view.screenshot);
  const auto context = render::make_offscreen_context(view.width, view.height, view.gl);
  VerifyView v(*context, nullptr, run, view);
  // The settled layout (panels sized, the camera refitted to the space they leave), as the window's.
  double ms = 0;
  for (int i = 0; i < VerifyView::kSettleFrames; ++i) {
    v.frame(false, 1.0f / 60.0f);
    ms += v.frame_ms();
  }
  const Image image = context->read_pixels();
  write_png(*view.screenshot, image);
  const auto problems = run.verdict.problem_count;
  char line[512];
  std::snprintf(line, sizeof line, "screenshot %s (%dx%d, %s): %s on %s, %s%s", view.screenshot->c_str(), image.width,
                image.height, context->kind(), plural(static_cast<long long>(run.verdict.lists.size()), "list").c_str(),
                plural(run.elements.size(), "element").c_str(), plural(problems, "problem").c_str(),
                problems > 0 ? " (the first selected)" : "");
  std::string out = line;
  if (const LayerSlice* layer = v.layer())
    out += "; layer " + std::to_string(layer->layer) + " of " + std::to_string(layer->count) + " shown";
  if (!view.no_timings) {
    std::snprintf(line, sizeof line, "; %.1f ms a frame", ms / VerifyView::kSettleFrames);
    out += line;
  }
  return out;
}

}  // namespace nbscope

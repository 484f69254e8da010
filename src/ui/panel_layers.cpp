// The Layers panel of a 3D frame (book p.123: NBS works through the layers one at a time): which
// layer the view shows (a slider, Up/Down buttons and keys, "auto" to let the view choose), a side
// view of the whole frame (x-z, or y-z) with the layer lines, the layer shown as a band and the
// layer below (which the contact mask reaches) marked faintly — a click or a drag picks the layer —
// and the z-lists (heads C[iz], the chain through Z) beside it. Hidden for a 2D frame.
//
// Index: side view (geometry, elements or their density, bands, the click) | z-lists | LayersPanel.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "ui/layer_lists.hpp"
#include "ui/panels.hpp"
#include "ui/stepper_panels.hpp"

namespace nbscope::ui {

namespace {

// Past this many elements the side view bins them into a density image (a few thousand cells of
// kBinPx pixels) instead of drawing each: 10,000 circles would cost the window its frame rate.
constexpr std::int64_t kMaxDrawnElements = 2000;
constexpr float kBinPx = 3.0f;
constexpr int kZListLines = 5;  // layers listed around the one shown (the column stays short)

const ImU32 kHereColour = IM_COL32(250, 190, 90, 230);
const ImU32 kBelowColour = IM_COL32(150, 170, 220, 190);
const ImU32 kOtherColour = IM_COL32(120, 125, 135, 120);
const ImU32 kBandColour = IM_COL32(250, 190, 90, 55);
const ImU32 kBandEdge = IM_COL32(250, 190, 90, 200);
const ImU32 kBelowBand = IM_COL32(150, 170, 220, 28);
const ImU32 kLayerLine = IM_COL32(200, 205, 220, 120);
const ImU32 kSelectedRing = IM_COL32(255, 255, 255, 235);  // the selected element, whichever layer it is in
const ImVec4 kCurrentText(0.98f, 0.75f, 0.35f, 1.0f);

// Where the side view lies on screen and how world (h, z) maps into it (z up).
struct SideGeometry {
  ImVec2 lo, hi;        // pixel rectangle
  double h0 = 0, z0 = 0;  // world at its lower left corner
  double sx = 1, sz = 1;  // pixels per metre, horizontally and vertically
  ImVec2 to_screen(double h, double z) const {
    return ImVec2(lo.x + static_cast<float>((h - h0) * sx), hi.y - static_cast<float>((z - z0) * sz));
  }
  double z_at(float y) const { return z0 + static_cast<double>(hi.y - y) / sz; }
};

// The layer at pixel row `y` of the side view, clamped into the grid's.
std::int32_t layer_at(const SideGeometry& g, const Grid& grid, float y) {
  const double c = std::floor((g.z_at(y) - grid.origin[2]) / grid.cell_size);
  if (!(c >= 0)) return 0;
  return static_cast<std::int32_t>(std::min(c, static_cast<double>(grid.n[2] - 1)));
}

// Bin `at` (in bins from the first) clamped into [0, count) before it becomes an int: a centre far
// outside the grid (or NaN) must not overflow the conversion.
int bin_of(float at, int count) {
  if (!(at >= 0.0f)) return 0;
  return at >= static_cast<float>(count - 1) ? count - 1 : static_cast<int>(at);
}

ImU32 place_colour(LayerPlace p) {
  return p == LayerPlace::Here ? kHereColour : p == LayerPlace::Below ? kBelowColour : kOtherColour;
}

}  // namespace

class LayersPanel final : public Panel {
 public:
  explicit LayersPanel(std::shared_ptr<StepperSession> session) : session_(std::move(session)) {}
  [[nodiscard]] const char* title() const override { return kLayersTitle; }
  [[nodiscard]] PanelPlace place() const override { return PanelPlace::Right; }
  [[nodiscard]] float width() const override { return 300.0f; }
  [[nodiscard]] int priority() const override { return 15; }
  [[nodiscard]] int column_order() const override { return 50; }
  [[nodiscard]] bool visible(const UiContext& c) const override { return c.sim.layer != nullptr && c.sim.elements != nullptr; }

  void draw(UiContext& c) override {
    const LayerSlice& slice = *c.sim.layer;
    const bool book = c.state.book_numbering;
    const Grid* grid = c.sim.grid();
    const bool grid_3d = grid != nullptr && grid->dim == 3 && grid->n[2] == slice.count;
    draw_choice(c, slice, book);
    if (grid_3d) {
      const double z_lo = grid->origin[2] + slice.layer * grid->cell_size;
      ImGui::TextWrapped("layer %lld of %d, z from %.4g to %.4g m, %lld elements", static_cast<long long>(shown(slice.layer, book)),
                  slice.count, z_lo, z_lo + grid->cell_size, static_cast<long long>(layer_count(slice, slice.layer)));
      ImGui::Checkbox("y-z (else x-z)", &c.state.side_view_yz);
      draw_side_view(c, slice, *grid);
    }
    draw_zlists(c, slice, book);
  }

  bool handle_keys(UiContext& c) override {
    if (c.sim.layer == nullptr) return false;
    for (const int direction : {+1, -1}) {
      if (!ImGui::IsKeyPressed(ImGui::GetKeyIndex(direction > 0 ? ImGuiKey_UpArrow : ImGuiKey_DownArrow), true)) continue;
      move(c, direction);
      return true;
    }
    return false;
  }

 private:
  static std::int64_t layer_count(const LayerSlice& s, std::int32_t iz) {
    return iz >= 0 && static_cast<std::size_t>(iz) < s.per_layer.size() ? s.per_layer[static_cast<std::size_t>(iz)] : 0;
  }
  // One layer up (+1) or down (-1) from the layer shown, within the grid's.
  static void move(UiContext& c, int direction) {
    const LayerSlice& s = *c.sim.layer;
    c.state.layer = std::clamp<std::int32_t>(s.layer + direction, 0, s.count - 1);
  }

  // The slider, Down/Up and auto (the view chooses: the selected element's or pair's layer, else the busiest).
  static void draw_choice(UiContext& c, const LayerSlice& s, bool book) {
    int value = static_cast<int>(shown(s.layer, book));
    const int lo = static_cast<int>(shown(0, book)), hi = static_cast<int>(shown(s.count - 1, book));
    ImGui::SetNextItemWidth(std::max(80.0f, ImGui::GetContentRegionAvail().x - button_width("Down") - button_width("Up") -
                                                button_width("auto") - 3 * ImGui::GetStyle().ItemSpacing.x));
    if (ImGui::SliderInt("##layer", &value, lo, std::max(lo, hi), "layer %d")) c.state.layer = std::clamp(value - lo, 0, s.count - 1);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the layer shown (keys: Up / Down)");
    ImGui::SameLine();
    if (ImGui::Button("Down")) move(c, -1);
    ImGui::SameLine();
    if (ImGui::Button("Up")) move(c, +1);
    ImGui::SameLine();
    const bool automatic = !c.state.layer.has_value();
    if (automatic) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyle().Colors[ImGuiCol_ButtonActive]);
    if (ImGui::Button("auto")) c.state.layer.reset();
    if (automatic) ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the view chooses: the selected element's or pair's layer, else the busiest");
  }

  // The whole frame from the side, the layer shown as a band; a click or a drag picks a layer.
  void draw_side_view(UiContext& c, const LayerSlice& s, const Grid& grid) {
    const Elements& e = *c.sim.elements;
    const int h_axis = c.state.side_view_yz ? 1 : 0;
    const double d = grid.cell_size;
    const double h_span = static_cast<double>(grid.n[h_axis]) * d, z_span = static_cast<double>(grid.n[2]) * d;
    const float w = std::max(60.0f, ImGui::GetContentRegionAvail().x);
    const float h = std::clamp(static_cast<float>(w * z_span / std::max(h_span, 1e-300)), 60.0f, 120.0f);
    SideGeometry g;
    g.lo = ImGui::GetCursorScreenPos();
    g.hi = ImVec2(g.lo.x + w, g.lo.y + h);
    g.h0 = grid.origin[h_axis];
    g.z0 = grid.origin[2];
    g.sx = w / h_span;
    g.sz = h / z_span;
    ImGui::InvisibleButton("##side view", ImVec2(w, h));
    if (ImGui::IsItemActive() && ImGui::GetIO().MouseDown[0]) c.state.layer = layer_at(g, grid, ImGui::GetIO().MousePos.y);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("layer %lld: click or drag to show it", static_cast<long long>(shown(layer_at(g, grid, ImGui::GetIO().MousePos.y), c.state.book_numbering)));
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(g.lo, g.hi, true);
    draw->AddRectFilled(g.lo, g.hi, IM_COL32(24, 26, 31, 255));
    const auto band = [&](std::int32_t iz, ImU32 fill) {
      if (iz < 0) return;
      draw->AddRectFilled(g.to_screen(g.h0, g.z0 + (iz + 1) * d), g.to_screen(g.h0 + h_span, g.z0 + iz * d), fill);
    };
    band(s.below, kBelowBand);
    band(s.layer, kBandColour);
    if (e.size() <= kMaxDrawnElements) {
      draw_elements(draw, g, e, s, h_axis);
    } else {
      draw_density(draw, g, e, s, h_axis);
    }
    // The layer lines over the elements: a settled pack hides any line drawn under it.
    const float spacing = static_cast<float>(d * g.sz);
    for (std::int64_t iz = 0; iz <= grid.n[2]; ++iz) {
      if (spacing < 3.0f && iz % 5 != 0) continue;  // dense layers: every fifth line
      const float y = g.to_screen(0, g.z0 + static_cast<double>(iz) * d).y;
      draw->AddLine(ImVec2(g.lo.x, y), ImVec2(g.hi.x, y), kLayerLine);
    }
    if (const ElementId k = c.state.selected; k >= 0 && k < e.size()) {  // where the selection lies, in any layer
      const float r = std::max(3.0f, static_cast<float>(e.r[k] * g.sx)) + 2.0f;
      draw->AddCircle(g.to_screen(e.axis(h_axis)[k], e.z[k]), r, kSelectedRing, 12, 1.5f);
    }
    for (const std::int32_t edge : {s.layer, s.layer + 1}) {
      const float y = g.to_screen(0, g.z0 + edge * d).y;
      draw->AddLine(ImVec2(g.lo.x, y), ImVec2(g.hi.x, y), kBandEdge, 1.5f);
    }
    draw->PopClipRect();
    draw->AddRect(g.lo, g.hi, kLayerLine);
  }

  // Each element as a small disc of its radius (at least a pixel and a half), coloured by its layer's place.
  static void draw_elements(ImDrawList* draw, const SideGeometry& g, const Elements& e, const LayerSlice& s, int h_axis) {
    const auto& hv = e.axis(h_axis);
    for (ElementId k = 0; k < e.size(); ++k) {
      const float r = std::max(1.5f, static_cast<float>(e.r[k] * g.sx));
      draw->AddCircleFilled(g.to_screen(hv[k], e.z[k]), r, place_colour(s.place(k)), 8);
    }
  }

  // The elements counted into kBinPx-pixel bins, each drawn once, brighter the more it holds.
  void draw_density(ImDrawList* draw, const SideGeometry& g, const Elements& e, const LayerSlice& s, int h_axis) {
    const int cols = std::max(1, static_cast<int>((g.hi.x - g.lo.x) / kBinPx));
    const int rows = std::max(1, static_cast<int>((g.hi.y - g.lo.y) / kBinPx));
    bins_.assign(static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows), 0);
    places_.assign(bins_.size(), static_cast<std::uint8_t>(LayerPlace::Other));
    const auto& hv = e.axis(h_axis);
    int fullest = 1;
    for (ElementId k = 0; k < e.size(); ++k) {
      const ImVec2 p = g.to_screen(hv[k], e.z[k]);
      const int bx = bin_of((p.x - g.lo.x) / kBinPx, cols);
      const int by = bin_of((p.y - g.lo.y) / kBinPx, rows);
      const std::size_t b = static_cast<std::size_t>(by) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(bx);
      fullest = std::max(fullest, ++bins_[b]);
      places_[b] = std::min(places_[b], static_cast<std::uint8_t>(s.place(k)));  // Here < Below < Above < Other
    }
    for (int by = 0; by < rows; ++by) {
      for (int bx = 0; bx < cols; ++bx) {
        const std::size_t b = static_cast<std::size_t>(by) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(bx);
        if (bins_[b] == 0) continue;
        const float t = 0.35f + 0.65f * std::sqrt(static_cast<float>(bins_[b]) / static_cast<float>(fullest));
        ImVec4 colour = ImGui::ColorConvertU32ToFloat4(place_colour(static_cast<LayerPlace>(places_[b])));
        colour.w *= t;
        const ImVec2 a(g.lo.x + static_cast<float>(bx) * kBinPx, g.lo.y + static_cast<float>(by) * kBinPx);
        draw->AddRectFilled(a, ImVec2(a.x + kBinPx, a.y + kBinPx), ImGui::ColorConvertFloat4ToU32(colour));
      }
    }
  }

  // The z-lists: from the stepper's arrays mid-trace, else the frame's NBS 3D trace, else built from the layers.
  ZLists zlists(const SimView& sim, const LayerSlice& s) {
    const StepperSession* session = session_.get();
    if (session != nullptr && session->has_capture() && session->current_for(sim)) {
      const Stepper& st = session->stepper();
      if (st.position() > 0 && st.position() < st.size()) {
        if (auto z = zlists_from_state(st.trace(), st.state())) {
          z->position = st.position();
          z->events = st.size();
          return *z;
        }
      }
    }
    const std::shared_ptr<const FrameTrace>& trace =
        session != nullptr && session->has_capture() && session->current_for(sim) ? session->frame_trace() : sim.trace;
    if (trace && trace->refusal.empty() && trace->elements.dim == 3) {
      if (trace->serial != trace_serial_ || !trace_zlists_) {
        trace_zlists_ = zlists_from_trace(trace->log);
        trace_serial_ = trace->serial;
      }
      if (trace_zlists_) return *trace_zlists_;
    }
    return zlists_from_layers(s);
  }

  void draw_zlists(UiContext& c, const LayerSlice& s, bool book) {
    const ZLists z = zlists(c.sim, s);
    switch (z.source) {
      case ZLists::Source::Stepper:
        ImGui::TextWrapped("z-lists at operation %zu of %zu (as in Arrays):", z.position, z.events);
        break;
      case ZLists::Source::Trace:
        ImGui::TextWrapped("z-lists of the nbs trace, finished:");
        break;
      case ZLists::Source::Layers:
        ImGui::TextWrapped("z-lists (no nbs trace): as the book's first loop builds them:");
        break;
    }
    // A dump's atoms are named by id elsewhere; the lists hold rows, as the arrays and the stepper say.
    if (c.sim.ids() != nullptr) ImGui::TextDisabled("rows, as in Arrays (atom ids: Selection)");
    const auto [from, to] = window_range(static_cast<std::int64_t>(z.heads.size()), s.layer, kZListLines);
    if (to < static_cast<std::int64_t>(z.heads.size())) ImGui::TextDisabled("  ... %lld above", static_cast<long long>(static_cast<std::int64_t>(z.heads.size()) - to));
    for (std::int64_t iz = to; iz-- > from;) {  // the top layer first, as in the side view
      const auto layer = static_cast<std::int32_t>(iz);
      const auto at = static_cast<std::size_t>(iz);
      const std::string head = "C[" + std::to_string(shown(layer, book)) + "] = " + std::to_string(shown(z.heads[at], book)) +
                               "   (" + std::to_string(z.chains[at].size()) + ")##" + std::to_string(layer);
      if (layer == s.layer) ImGui::PushStyleColor(ImGuiCol_Text, kCurrentText);
      if (ImGui::Selectable(head.c_str(), layer == s.layer)) c.state.layer = layer;
      if (layer == s.layer) {
        const std::string chain = zlist_text(z, layer, book);
        ImGui::TextWrapped("  %s", chain.substr(chain.find(": ") + 2).c_str());
        ImGui::PopStyleColor();
      }
    }
    if (from > 0) ImGui::TextDisabled("  ... %lld below", static_cast<long long>(from));
  }

  std::shared_ptr<StepperSession> session_;
  std::vector<int> bins_;                 // the density image's counts, reused frame to frame
  std::vector<std::uint8_t> places_;      // the nearest place (LayerPlace) of each bin's elements
  std::optional<ZLists> trace_zlists_;    // the finished z-lists of the trace last read
  std::uint64_t trace_serial_ = 0;
};

std::unique_ptr<Panel> make_layers_panel(std::shared_ptr<StepperSession> session) {
  return std::make_unique<LayersPanel>(std::move(session));
}

}  // namespace nbscope::ui

// The stepper's scene overlay: the current operation drawn over the bodies — the element it is
// about ringed (magenta: the selected element keeps its white ring), the list being built (or walked) as an arrow chain growing arrow by arrow, the cell
// (or row) it works on outlined, and the pair being tested as a segment coloured by its result. On
// a 3D frame's layer view, what lies in the layer below is drawn fainter and what lies further
// away not at all (core/layers.hpp).
#include <algorithm>
#include <string>

#include "core/layers.hpp"
#include "core/traced_lists.hpp"
#include "render/overlays.hpp"
#include "ui/stepper_panels.hpp"

namespace nbscope::ui {

namespace {

using render::Layer;
using render::Rgba;
using render::Vec2;
namespace palette = render::palette;

const Rgba kNoContact{200, 200, 210, 230};

class SceneWriter {
 public:
  SceneWriter(const StepperSession& s, render::DrawSink& sink, bool ids_drawn, const LayerSlice* layer)
      : s_(s), sink_(sink), e_(s.elements()), ids_drawn_(ids_drawn),
        layer_(layer != nullptr && static_cast<std::int64_t>(layer->element_layer.size()) == e_.size() ? layer : nullptr) {}

  Vec2 centre(std::int32_t k) const { return {static_cast<float>(e_.x[k]), static_cast<float>(e_.y[k])}; }
  // An element of this frame that the view shows (every one in 2D; in 3D its layer's and the layer below's).
  bool valid(std::int32_t k) const { return k >= 0 && k < e_.size() && (layer_ == nullptr || layer_->visible(k)); }
  // Colours of what lies in the layer below fade: the mask reaches it, the view looks through it.
  Rgba faded(Rgba c, std::int32_t k) const {
    return layer_ != nullptr && layer_->place(k) == LayerPlace::Below ? c.with_alpha(static_cast<std::uint8_t>(c.a / 2)) : c;
  }

  // A ring around element k and its id beside it (unless the scene already numbers every element).
  void ring(std::int32_t k, Rgba colour, float width_px) {
    if (!valid(k)) return;
    colour = faded(colour, k);
    sink_.circle(Layer::Top, centre(k), static_cast<float>(e_.r[k]) * 1.15f, colour.with_alpha(40), colour, width_px, 7.0f);
    if (ids_drawn_) return;
    const float r = static_cast<float>(e_.r[k]);
    sink_.text(centre(k) + Vec2(0, r * 1.6f), std::to_string(shown(k, s_.book_numbering)), colour);
  }

  // Outlines a cell; an axis given as -1 spans the whole grid (a row, a layer).
  void cell(const std::int32_t c[3], Rgba fill, Rgba edge) {
    const Grid* g = s_.grid();
    if (g == nullptr || (c[0] < 0 && c[1] < 0)) return;
    if (layer_ != nullptr && c[2] >= 0) {
      const LayerPlace place = layer_->place_of_layer(c[2]);
      if (place != LayerPlace::Here && place != LayerPlace::Below) return;  // a cell of a hidden layer
      if (place == LayerPlace::Below) {
        fill = fill.with_alpha(static_cast<std::uint8_t>(fill.a / 2));
        edge = edge.with_alpha(static_cast<std::uint8_t>(edge.a / 2));
      }
    }
    const double d = g->cell_size;
    const auto lo = [&](int a) { return c[a] >= 0 ? g->origin[a] + c[a] * d : g->origin[a]; };
    const auto hi = [&](int a) { return c[a] >= 0 ? g->origin[a] + (c[a] + 1) * d : g->origin[a] + static_cast<double>(g->n[a]) * d; };
    const Vec2 a(static_cast<float>(lo(0)), static_cast<float>(lo(1)));
    const Vec2 b(static_cast<float>(hi(0)), static_cast<float>(hi(1)));
    sink_.rect(Layer::Overlay, a, b, fill);
    const Vec2 corners[4] = {a, {b.x(), a.y()}, b, {a.x(), b.y()}};
    for (int i = 0; i < 4; ++i) sink_.line(Layer::Top, corners[i], corners[(i + 1) % 4], edge, 2.0f);
  }

  // The list's chain as it stands now: head ringed, one arrow per next link, "-1" after the end.
  void list(int heads, std::int64_t slot, Rgba colour) {
    const std::vector<std::int32_t> members = s_.stepper().list_members(heads, slot);
    if (members.empty()) return;
    for (std::size_t i = 0; i + 1 < members.size(); ++i)
      if (valid(members[i]) && valid(members[i + 1])) sink_.arrow(Layer::Top, centre(members[i]), centre(members[i + 1]), colour, 2.5f);
    const std::int32_t head = members.front(), last = members.back();
    if (valid(head)) sink_.circle(Layer::Top, centre(head), static_cast<float>(e_.r[head]) * 0.35f, colour, colour, 1.0f, 4.0f);
    if (valid(last)) {
      const float r = static_cast<float>(e_.r[last]);
      sink_.text(centre(last) + Vec2(r * 1.9f, 0), "-1", colour);
    }
  }

  // The lists overlay's colour of the list headed by slot `slot` of array `heads`.
  static Rgba list_colour(const char* kind, int heads, std::int64_t slot, const StepperSession& s) {
    const auto& arrays = s.stepper().trace().arrays();
    const bool below = heads >= 0 && static_cast<std::size_t>(heads) < arrays.size() && is_row_below(arrays[heads], slot);
    return render::list_colour(kind, below);
  }

 private:
  const StepperSession& s_;
  render::DrawSink& sink_;
  const Elements& e_;
  bool ids_drawn_;
  const LayerSlice* layer_;  // null: a 2D frame (or a slice of other elements): everything is shown
};

}  // namespace

void draw_stepper_scene(const StepperSession& s, render::DrawSink& sink, bool lists_drawn, const LayerSlice* layer, bool ids_drawn) {
  const Stepper& st = s.stepper();
  const TraceEvent* e = st.current();
  if (e == nullptr) return;
  SceneWriter w(s, sink, ids_drawn, layer);
  const LoopVars v = st.loop_vars();
  const std::int32_t cell[3] = {v.ix, v.iy, v.iz};
  switch (e->op) {
    case TraceOp::Push:
    case TraceOp::Clear: {
      const Rgba colour = SceneWriter::list_colour(e->label, v.heads_array, v.list, s);
      w.cell(cell, colour.with_alpha(35), colour);
      if (!lists_drawn) w.list(v.heads_array, v.list, colour);
      w.ring(e->element, palette::kOperation, 3.0f);
      break;
    }
    case TraceOp::VisitCell:
    case TraceOp::TestPair: {
      w.cell(cell, palette::kMaskCell, palette::kMaskCentre.with_alpha(255));
      if (const auto l = s.list_of_cell(cell); l && !lists_drawn) w.list(l->heads, l->list, SceneWriter::list_colour(l->kind, l->heads, l->list, s));
      w.ring(e->element, palette::kOperation, 3.0f);
      if (e->op == TraceOp::TestPair && w.valid(e->other) && w.valid(e->element)) {
        const Rgba colour = e->contact ? palette::kConfirmedPair : kNoContact;
        sink.line(Layer::Top, w.centre(e->element), w.centre(e->other), colour, e->contact ? 4.0f : 2.0f);
        w.ring(e->other, colour, 3.0f);
        // The verdict below the pair, clear of the ids above the elements.
        const float below = 2.5f * static_cast<float>(std::max(s.elements().r[e->element], s.elements().r[e->other]));
        const Vec2 low = w.centre(e->element).y() < w.centre(e->other).y() ? w.centre(e->element) : w.centre(e->other);
        sink.text(Vec2((w.centre(e->element).x() + w.centre(e->other).x()) * 0.5f, low.y() - below),
                  e->contact ? "contact" : "no contact", colour);
      }
      break;
    }
    case TraceOp::Phase:
      w.cell(e->cell, palette::kSelectionCell, palette::kTextDim);
      break;
    default:
      w.ring(e->element, palette::kOperation, 3.0f);
      break;
  }
}

}  // namespace nbscope::ui

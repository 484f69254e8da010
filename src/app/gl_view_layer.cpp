// The layer part of GlView: a 3D frame is shown one layer of cells at a time, as NBS 3D works
// through it (core/layers.hpp, book p.123). Which layer: the stepper's while it is mid-way through
// this frame's trace (the view follows the loop it shows), else the one the user chose (slider,
// keys, --layer K; clamped, as another frame may have fewer layers), else "auto": the layer whose
// pass finds the focus pair (a violation gone to), else the selected element's, else the busiest.
#include <algorithm>
#include <string>

#include "app/gl_view.hpp"
#include "core/error.hpp"

namespace nbscope {

namespace {

// --layer's value as a layer number; nullopt for "" and "auto" (parse_view_options checked it).
std::optional<std::int32_t> layer_number(const std::string& text) {
  if (text.empty() || text == "auto") return std::nullopt;
  return static_cast<std::int32_t>(std::stol(text));
}

}  // namespace

void GlView::set_layer_option(const std::string& text) {
  choices_.layer = layer_number(text);
  state_.layer = choices_.layer;
}

void GlView::check_layer(const FrameLoop& loop) const {
  if (!choices_.layer) return;
  const Grid& grid = loop.result().selected().grid;
  if (loop.source().elements().dim != 3 || grid.dim != 3)
    throw Error("--layer: the frame is 2D (layers are those of a 3D frame's grid)");
  const std::int64_t count = grid.n[2];
  if (*choices_.layer >= count)
    throw Error("--layer: " + std::to_string(*choices_.layer) + " is past the top layer " + std::to_string(count - 1) +
                " (the frame has " + std::to_string(count) + (count == 1 ? " layer)" : " layers)"));
}

const Stepper* GlView::stepping_through(const std::shared_ptr<const FrameTrace>& trace) const {
  const Stepper& st = stepper_->stepper();
  const bool stepping = trace && stepper_panels_open() && stepper_->has_capture() && stepper_->frame_trace() == trace &&
                        st.position() > 0 && st.position() < st.size();
  return stepping ? &st : nullptr;
}

std::int32_t GlView::choose_layer(const FrameLoop& loop, const std::shared_ptr<const FrameTrace>& trace, const LayerSlice& slice) {
  const std::int32_t top = slice.count - 1;
  // The stepper mid-way: the layer of the phase it is in (a row's phase names its layer), else of
  // the latest operation's cell (the z-lists' pushes): StepperSession::current_layer.
  if (stepping_through(trace) != nullptr)
    if (const auto iz = stepper_->current_layer(); iz && *iz >= 0 && *iz <= top) return *iz;
  if (state_.layer) {
    state_.layer = std::clamp(*state_.layer, 0, top);  // the slider and the keys move from what is shown
    return *state_.layer;
  }
  const ElementId n = loop.source().elements().size();
  const Grid& grid = loop.result().selected().grid;
  if (const auto& p = state_.selected_pair; p && p->i >= 0 && p->j >= 0 && p->i < n && p->j < n) return pair_layer(slice, grid, *p);
  if (state_.selected >= 0 && state_.selected < n) return slice.element_layer[static_cast<std::size_t>(state_.selected)];
  return busiest_layer(slice);
}

void GlView::update_layer(const FrameLoop& loop, const std::shared_ptr<const FrameTrace>& trace) {
  const Elements& e = loop.source().elements();
  const Grid& grid = loop.result().selected().grid;
  if (e.dim != 3 || grid.dim != 3 || grid.n[2] < 1) {
    layer_.reset();
    return;
  }
  // Sliced again only when the frame (or its detection) changed, or another layer is chosen.
  const std::uint64_t generation = loop.change().generation;
  if (!layer_ || layer_generation_ != generation || layer_->element_layer.size() != static_cast<std::size_t>(e.size())) {
    layer_ = slice_layer(e, grid, std::clamp(layer_ ? layer_->layer : 0, 0, static_cast<std::int32_t>(grid.n[2] - 1)));
    layer_generation_ = generation;
  }
  const std::int32_t iz = choose_layer(loop, trace, *layer_);
  if (iz != layer_->layer) layer_ = slice_layer(e, grid, iz);
}

}  // namespace nbscope

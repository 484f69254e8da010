// nbscope core: a 3D frame as NBS sees it, one layer of cells at a time (book p.123). NBS 3D maps
// the elements onto layers iz = Int((z - z_min)/d) (the z-lists, heads C[nz], next Z), then works
// through each layer with its rows and the layer below, which the contact mask reaches. The window
// shows the same: one layer from above, the layer below ghosted, the layers above hidden.
//
// Index: LayerPlace | LayerSlice (one layer's view of the elements) | slice_layer | pair_layer |
// list_layer_place | busiest_layer.
#pragma once
#include <cstdint>
#include <vector>

#include "core/elements.hpp"
#include "core/grid.hpp"
#include "core/pairs.hpp"
#include "core/traced_lists.hpp"

namespace nbscope {

// Where an element (or a list) lies relative to the layer shown.
enum class LayerPlace : std::uint8_t {
  Here,   // in the layer shown: drawn as in 2D
  Below,  // in the layer below, which the contact mask reaches: drawn ghosted
  Above,  // in the layer above: hidden (its pairs with this layer are marked)
  Other,  // further away: hidden
};

// One layer of a 3D frame's grid and where every element lies relative to it.
struct LayerSlice {
  std::int32_t layer = 0;   // iz shown, in [0, count)
  std::int32_t below = -1;  // the layer the mask reaches (iz-1; a periodic z wraps; -1: none)
  std::int32_t above = -1;  // iz+1 (wrapped on a periodic z; -1: none)
  std::int32_t count = 1;   // nz, the grid's layers
  std::vector<std::int32_t> element_layer;  // iz of each element, as NBS integerises it (eq. 3.76's twin on z)
  std::vector<std::int64_t> per_layer;      // elements in each layer (size count)

  // Where element k lies relative to the layer shown.
  [[nodiscard]] LayerPlace place(ElementId k) const { return place_of_layer(element_layer[static_cast<std::size_t>(k)]); }
  // Where layer iz lies relative to the layer shown.
  [[nodiscard]] LayerPlace place_of_layer(std::int32_t iz) const {
    if (iz == layer) return LayerPlace::Here;
    if (iz == below) return LayerPlace::Below;
    if (iz == above) return LayerPlace::Above;
    return LayerPlace::Other;
  }
  // True for an element drawn in this layer's view (its own layer or the layer below).
  [[nodiscard]] bool visible(ElementId k) const {
    const LayerPlace p = place(k);
    return p == LayerPlace::Here || p == LayerPlace::Below;
  }
};

// The view of layer `layer` of 3D `elements` on `grid` (a 3D grid fitted to them). Error when the
// frame or the grid is not 3D, or `layer` is outside [0, grid.n[2]).
[[nodiscard]] LayerSlice slice_layer(const Elements& elements, const Grid& grid, std::int32_t layer);

// The layer in whose pass NBS 3D finds pair p: the upper of its two elements' layers (the mask
// reaches down one layer; on a periodic z, layer 0 finds its pairs with layer nz-1).
[[nodiscard]] std::int32_t pair_layer(const Grid& grid, std::int32_t layer_i, std::int32_t layer_j);
// As above, from the slice's element layers.
[[nodiscard]] std::int32_t pair_layer(const LayerSlice& slice, const Grid& grid, const Pair& p);

// Where a traced list lies relative to the layer shown: by the layer of its cells (cell[2]); a list
// that fixes no layer (2D, a tree's leaf, a z-list's own column) is Here.
[[nodiscard]] LayerPlace list_layer_place(const TracedList& list, const LayerSlice& slice);

// The layer with the most elements (the lowest on a tie): where a view opens when nothing chooses one.
[[nodiscard]] std::int32_t busiest_layer(const LayerSlice& slice);

}  // namespace nbscope

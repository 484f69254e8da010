#include "core/layers.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace nbscope {

LayerSlice slice_layer(const Elements& elements, const Grid& grid, std::int32_t layer) {
  if (elements.dim != 3 || grid.dim != 3) throw Error("layer view: the frame is not 3D");
  if (layer < 0 || layer >= grid.n[2])
    throw Error("layer " + std::to_string(layer) + " is past the grid's layers 0.." + std::to_string(grid.n[2] - 1));
  LayerSlice s;
  s.layer = layer;
  s.count = static_cast<std::int32_t>(grid.n[2]);
  s.below = grid.neighbour(layer, -1, 2);
  s.above = grid.neighbour(layer, 1, 2);
  if (s.count <= 2 && s.above == s.below) s.above = -1;  // two periodic layers: the one other layer is below
  const auto n = static_cast<std::size_t>(elements.size());
  s.element_layer.resize(n);
  s.per_layer.assign(static_cast<std::size_t>(s.count), 0);
  for (std::size_t k = 0; k < n; ++k) {
    const std::int32_t iz = grid.cell(elements.z[static_cast<Eigen::Index>(k)], 2);
    s.element_layer[k] = iz;
    ++s.per_layer[static_cast<std::size_t>(iz)];
  }
  return s;
}

std::int32_t pair_layer(const Grid& grid, std::int32_t layer_i, std::int32_t layer_j) {
  if (layer_i == layer_j) return layer_i;
  // The mask of layer iz reaches iz-1 (wrapped on a periodic z): the pair is found in the pass of
  // the layer whose below is the other one.
  if (grid.neighbour(layer_i, -1, 2) == layer_j) return layer_i;
  if (grid.neighbour(layer_j, -1, 2) == layer_i) return layer_j;
  return std::max(layer_i, layer_j);  // not neighbours (a wrong pair): the upper one
}

std::int32_t pair_layer(const LayerSlice& slice, const Grid& grid, const Pair& p) {
  return pair_layer(grid, slice.element_layer[static_cast<std::size_t>(p.i)],
                    slice.element_layer[static_cast<std::size_t>(p.j)]);
}

LayerPlace list_layer_place(const TracedList& list, const LayerSlice& slice) {
  if (list.cell[2] < 0) return LayerPlace::Here;
  return slice.place_of_layer(list.cell[2]);
}

std::int32_t busiest_layer(const LayerSlice& slice) {
  const auto it = std::max_element(slice.per_layer.begin(), slice.per_layer.end());
  return it == slice.per_layer.end() ? 0 : static_cast<std::int32_t>(it - slice.per_layer.begin());
}

}  // namespace nbscope

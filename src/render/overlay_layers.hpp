// nbscope render: the layer view of a 3D frame (book p.123: NBS works one layer of cells at a time,
// its mask reaching the layer below). What the overlays keep of a 3D frame shown at one layer: the
// lists of that layer's pass, the 3D contact mask of a cell, and picking that sees only the layer.
// The drawing itself is in overlays.cpp, overlay_grid.cpp and overlay_lists.cpp (overlay_layers.cpp
// holds the 3D parts they share).
//
// Index: ListLayerStyle, LayerList | lists_in_layer | mask_cells_3d | element_at (a layer's).
#pragma once
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "core/elements.hpp"
#include "core/grid.hpp"
#include "core/layers.hpp"
#include "core/traced_lists.hpp"

namespace nbscope::render {

// How the layer view draws a list it keeps.
enum class ListLayerStyle : std::uint8_t {
  Here,   // a list of the layer shown: as in 2D
  Below,  // a list of the layer below (NBS's B[1] y-lists, the x-lists of rows of iz-1): ghosted
};

// One list the layer view keeps: its index in the traced lists and its style.
struct LayerList {
  std::size_t index = 0;
  ListLayerStyle style = ListLayerStyle::Here;
  friend bool operator==(const LayerList&, const LayerList&) = default;
};

// The lists of `lists` (traced_lists()) the view of layer `slice.layer` draws, in order: lists built
// in that layer's pass (TracedList::phase_layer, NBS 3D) when they were built in a layer's pass, else
// (screen, tree, sort) every list whose cells lie in the layer or the layer below; Here or Below by
// the list's own layer (cell[2]). z-lists (the heads C) are never kept: the Layers panel shows them.
[[nodiscard]] std::vector<LayerList> lists_in_layer(const std::vector<TracedList>& lists, const LayerSlice& slice);

// The cells (ix, iy, iz) of the 3D contact mask of cell (ix, iy, iz): the cell itself first, then
// its half mask (core/cells.hpp kMask3d: (ix-1,iy,iz), (ix-1..ix+1,iy-1,iz), then the nine cells
// ix-1..ix+1, iy-1..iy+1 of layer iz-1), wrapped on the grid's periodic axes as NBS wraps them,
// fewer at an open edge.
[[nodiscard]] std::vector<std::array<std::int32_t, 3>> mask_cells_3d(const Grid& grid, std::int32_t ix, std::int32_t iy,
                                                                     std::int32_t iz);

// The element of the layer shown (`layer`; null: any, as the 2D overload) whose circle contains
// `world` (the smallest such; ties: lowest id), or -1: ghosts of the layer below and hidden
// elements are never picked.
[[nodiscard]] ElementId element_at(const Elements& elements, const Eigen::Vector2d& world, const LayerSlice* layer);

}  // namespace nbscope::render

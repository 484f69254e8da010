// nbscope render: --color-by's colours (docs/export.md): a value per element made a fill, by a
// categorical palette (type, rank) or a continuous map over the frame's range (vx, overlap, any
// numeric column), and the key the legend draws from. Plain data in, no GL.
#pragma once
#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "render/palette.hpp"

namespace nbscope::render {

// Most categories the legend lists one by one (the rest are counted).
inline constexpr std::size_t kMaxLegendCategories = 12;

// What the colours mean: the legend's swatches or colour bar.
struct ColourKey {
  std::string title;                                     // "type", "vx", "overlap", "rank (proc)"
  std::vector<std::pair<std::string, Rgba>> categories;  // categorical: each value shown, lowest first
  std::size_t more = 0;                                  // categorical values past kMaxLegendCategories
  bool continuous = false;                               // a colour bar from `low` to `high`
  double low = 0, high = 0;
};

// The continuous map's colour at t in [0, 1] (palette::kColourMap).
[[nodiscard]] Rgba colour_map(float t);
// The categorical colour of the k-th distinct value (palette::kCategory, repeating).
[[nodiscard]] Rgba category_colour(std::size_t k);

// One fill per value into `fills`: with `categorical`, each distinct value (ascending) its own colour,
// else the map over [min, max] of the values (a constant column: all the middle colour); the key
// titled `title`. Values that are not finite get the map's low end.
ColourKey colour_values(std::span<const double> values, bool categorical, std::string title, std::vector<Rgba>& fills);

}  // namespace nbscope::render

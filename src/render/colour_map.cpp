// --color-by's colours (colour_map.hpp).
#include "render/colour_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <map>

namespace nbscope::render {

Rgba colour_map(float t) {
  constexpr int kStops = static_cast<int>(std::size(palette::kColourMap));
  const float x = std::clamp(t, 0.0f, 1.0f) * float(kStops - 1);
  const int i = std::min(kStops - 2, static_cast<int>(x));
  return mix(palette::kColourMap[i], palette::kColourMap[i + 1], x - float(i));
}

Rgba category_colour(std::size_t k) { return palette::kCategory[k % std::size(palette::kCategory)]; }

namespace {

// A category's label: integers as integers (types, ranks), else %g.
std::string value_label(double v) {
  char buf[32];
  if (v == std::floor(v) && std::abs(v) < 1e15) std::snprintf(buf, sizeof buf, "%.0f", v);
  else std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

ColourKey colour_values(std::span<const double> values, bool categorical, std::string title, std::vector<Rgba>& fills) {
  ColourKey key;
  key.title = std::move(title);
  fills.resize(values.size());
  if (categorical) {
    std::map<double, std::size_t> index;  // value -> its place among the distinct values
    for (double v : values) index.emplace(v, 0);
    std::size_t k = 0;
    for (auto& [v, i] : index) {
      i = k++;
      if (key.categories.size() < kMaxLegendCategories) key.categories.emplace_back(value_label(v), category_colour(i));
    }
    key.more = index.size() - key.categories.size();
    for (std::size_t r = 0; r < values.size(); ++r) fills[r] = category_colour(index[values[r]]);
    return key;
  }
  key.continuous = true;
  bool any = false;
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    key.low = any ? std::min(key.low, v) : v;
    key.high = any ? std::max(key.high, v) : v;
    any = true;
  }
  const double span = key.high - key.low;
  for (std::size_t r = 0; r < values.size(); ++r) {
    const double v = values[r];
    fills[r] = !std::isfinite(v) ? colour_map(0) : span > 0 ? colour_map(static_cast<float>((v - key.low) / span)) : colour_map(0.5f);
  }
  return key;
}

}  // namespace nbscope::render

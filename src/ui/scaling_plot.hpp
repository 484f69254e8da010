// nbscope ui: a log-log plot drawn with ImDrawList for the Scaling panel: decade ticks (1e3 ..
// 1e6), one colour per series (a detector at a thread count: "nbs", "nbs x2"), a marker per layout, dashed O(N) and O(N log N) references
// anchored at the first point, a tooltip on the point under the mouse.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/scaling.hpp"

namespace nbscope::ui {

// Which value of a row a plot shows.
enum class ScalingQuantity { NsPerElement, BytesPerElement };

// The colour (ImU32, RGBA) of detector `algorithm`: fixed by its place in the registry.
std::uint32_t detector_colour(const std::string& algorithm);
// The colour of `algorithm` on `threads` threads: its own on one, lighter on more.
std::uint32_t series_colour(const std::string& algorithm, int threads);
// Draws `marker` (the layout's place in scaling_layouts(): circle, square, triangle, diamond, ...)
// centred at (x, y) into the current window's draw list.
void draw_layout_marker(float x, float y, float size, int marker, std::uint32_t colour);
// The marker of a layout name: its place in scaling_layouts() (0 when it is not one).
int layout_marker(const std::string& layout);

// Draws one plot of `quantity` over `rows` as an ImGui item `height` pixels tall and as wide as the
// window's content; `title` above it. Rows with a value <= 0 cannot be on a log axis and are left
// out (their detectors are named under the plot).
void draw_scaling_plot(const char* title, ScalingQuantity quantity, const std::vector<ScalingRow>& rows, float height);
// One series of the legend: a detector and its thread count.
struct SeriesKey {
  std::string algorithm;
  int threads = 1;
  friend bool operator==(const SeriesKey&, const SeriesKey&) = default;
};
// The legend: a swatch per series (named "nbs", "nbs x2"), a marker per layout, the dashed references.
void draw_scaling_legend(const std::vector<SeriesKey>& series, const std::vector<std::string>& layouts);

}  // namespace nbscope::ui

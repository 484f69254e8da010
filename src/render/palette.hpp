// nbscope render: every colour the renderer and the overlays use, in one place.
#pragma once
#include <cstdint>

namespace nbscope::render {

// An 8-bit RGBA colour.
struct Rgba {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  // The same colour with alpha `alpha`.
  [[nodiscard]] constexpr Rgba with_alpha(std::uint8_t alpha) const { return {r, g, b, alpha}; }
  friend constexpr bool operator==(const Rgba&, const Rgba&) = default;
};

// The palette: a dark background, bodies in muted tones, overlays in distinct saturated hues,
// and red reserved for check violations.
namespace palette {
inline constexpr Rgba kBackground{24, 26, 31};
inline constexpr Rgba kDynamicFill{86, 120, 160};
inline constexpr Rgba kDynamicOutline{170, 200, 235};
inline constexpr Rgba kStaticFill{70, 74, 82};
inline constexpr Rgba kStaticOutline{140, 146, 156};
inline constexpr Rgba kKinematicFill{96, 140, 110};
inline constexpr Rgba kKinematicOutline{170, 220, 180};
inline constexpr Rgba kBoundingCircle{220, 220, 220, 70};
inline constexpr Rgba kGridLine{120, 130, 150, 90};
inline constexpr Rgba kGridBorder{160, 170, 190, 200};
inline constexpr Rgba kCellShadeLow{70, 100, 150, 55};   // occupancy 1
inline constexpr Rgba kCellShadeHigh{235, 175, 70, 95};   // occupancy >= kCellShadeSaturation
inline constexpr int kCellShadeSaturation = 6;
inline constexpr Rgba kGridMajor{140, 150, 175, 120};   // every few cells, in the overview
// The overview's heat map, elements per cell from 1 (first) to the fullest cell in view (last).
inline constexpr Rgba kHeat[5] = {{50, 30, 110, 215}, {130, 40, 130, 220}, {210, 80, 70, 225}, {245, 170, 40, 230}, {252, 245, 160, 235}};
inline constexpr Rgba kRowBar{250, 170, 60, 200};       // elements per row (= its y-list's length)
inline constexpr Rgba kLabelBack{24, 26, 31, 215};      // behind the grid's title and the legend
inline constexpr Rgba kActiveList{255, 255, 255, 110};  // under the list the stepper is writing
inline constexpr Rgba kMaskCell{80, 220, 200, 70};
inline constexpr Rgba kMaskCentre{80, 220, 200, 130};
inline constexpr Rgba kYList{250, 170, 60};   // y-lists (rows) / first list kind
inline constexpr Rgba kXList{120, 200, 255};  // x-lists (cells) / second list kind
inline constexpr Rgba kXListBelow{190, 150, 255};  // NBS x-lists of the row below (B[1])
inline constexpr Rgba kListHead{255, 255, 255};
inline constexpr Rgba kListEnd{200, 200, 200};
inline constexpr Rgba kPair{250, 230, 90, 220};
inline constexpr Rgba kConfirmedPair{90, 220, 120, 230};
inline constexpr Rgba kBroadphaseOnly{150, 150, 160, 110};
inline constexpr Rgba kViolation{255, 50, 50};
inline constexpr Rgba kViolationText{255, 120, 115};  // red text on the dark background (a problem's words)
inline constexpr Rgba kSelection{255, 255, 255};
inline constexpr Rgba kSelectionCell{255, 255, 255, 45};
inline constexpr Rgba kOperation{255, 80, 230};  // the stepper's current element: never the selection's white
inline constexpr Rgba kTrail{255, 140, 200, 200};
inline constexpr Rgba kFlash{255, 255, 120, 200};
inline constexpr Rgba kDragLine{255, 255, 255, 200};
inline constexpr Rgba kText{235, 235, 240};
inline constexpr Rgba kTextDim{170, 175, 185};
// --color-by: a categorical value's colour (type, rank; the 11th value takes the first again), and
// the continuous map's stops from the frame's lowest value (first) to its highest (viridis).
// (Tableau's 10, its blue moved second: the first is never taken for the bodies' own blue.)
inline constexpr Rgba kCategory[10] = {{242, 142, 43},  {78, 121, 167}, {89, 161, 79},  {225, 87, 89},  {118, 183, 178},
                                       {237, 201, 72},  {176, 122, 161}, {255, 157, 167}, {156, 117, 95}, {186, 176, 172}};
inline constexpr Rgba kColourMap[5] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
}  // namespace palette

// Linear blend of a and b (t in [0, 1]), channel by channel, alpha included.
constexpr Rgba mix(Rgba a, Rgba b, float t) {
  auto m = [t](std::uint8_t x, std::uint8_t y) { return static_cast<std::uint8_t>(x + (y - x) * t + 0.5f); };
  return {m(a.r, b.r), m(a.g, b.g), m(a.b, b.b), m(a.a, b.a)};
}

}  // namespace nbscope::render

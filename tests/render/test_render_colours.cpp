// --color-by's colours without GL (render/colour_map.hpp): a colour per category or a map over the
// frame's range, the bodies drawn in them, and the legend's swatches or colour bar with min and max.
#include <gtest/gtest.h>

#include <vector>

#include "render/colour_map.hpp"
#include "render/overlays.hpp"
#include "support/draw_recorder.hpp"

namespace nbscope::render {
namespace {

using testdraw::Recorder;

TEST(ColourBy, EachCategoryItsColourLowestFirst) {
  std::vector<Rgba> fills;
  const ColourKey key = colour_values(std::vector<double>{2, 1, 1, 7}, true, "type", fills);
  ASSERT_EQ(fills.size(), 4u);
  EXPECT_EQ(fills[1], category_colour(0));
  EXPECT_EQ(fills[2], category_colour(0));
  EXPECT_EQ(fills[0], category_colour(1));
  EXPECT_EQ(fills[3], category_colour(2));
  ASSERT_EQ(key.categories.size(), 3u);
  EXPECT_EQ(key.categories[2].first, "7");
  EXPECT_FALSE(key.continuous);
  EXPECT_NE(category_colour(0), palette::kDynamicFill);
}

TEST(ColourBy, AMapOverTheFramesRange) {
  std::vector<Rgba> fills;
  const ColourKey key = colour_values(std::vector<double>{-1, 0.5, 2}, false, "vx", fills);
  EXPECT_TRUE(key.continuous);
  EXPECT_EQ(key.low, -1);
  EXPECT_EQ(key.high, 2);
  EXPECT_EQ(fills[0], palette::kColourMap[0]);
  EXPECT_EQ(fills[1], colour_map(0.5f));
  EXPECT_EQ(fills[2], palette::kColourMap[4]);
  colour_values(std::vector<double>{3, 3}, false, "vx", fills);  // one value: the middle, no division by 0
  EXPECT_EQ(fills[0], colour_map(0.5f));
}

TEST(ColourBy, BodiesInTheirFillsAndTheLegendSaysWhatTheyMean) {
  Elements e;
  for (int k = 0; k < 3; ++k) e.push_back(1.0 + 2.0 * k, 1.0, 0, 0.9);
  std::vector<ShapeDraw> shapes(3);
  for (int k = 0; k < 3; ++k) {
    shapes[static_cast<std::size_t>(k)].centre = Vec2(float(e.x[k]), 1.0f);
    shapes[static_cast<std::size_t>(k)].radius = 0.9f;
    shapes[static_cast<std::size_t>(k)].element = k;
  }
  Camera camera;
  camera.set_viewport(800, 600);
  camera.fit({{0, 0}, {6, 2}});
  OverlayScene s;
  s.elements = &e;
  s.shapes = shapes;
  OverlayFlags flags;
  flags.grid = false;
  Recorder plain;
  draw_scene(s, flags, camera, plain);
  for (const auto& c : plain.circles) EXPECT_EQ(c.fill, palette::kDynamicFill);

  std::vector<Rgba> fills;
  const ColourKey key = colour_values(std::vector<double>{-0.25, 0, 1.5}, false, "vx", fills);
  s.element_fills = fills;
  s.colour_key = &key;
  Recorder rec;
  draw_scene(s, flags, camera, rec);
  std::vector<Rgba> drawn;
  for (const auto& c : rec.circles)
    if (c.layer == Layer::Bodies) drawn.push_back(c.fill);
  EXPECT_EQ(drawn, fills);
  EXPECT_TRUE(rec.has_text("vx -0.25 .. 1.5"));
  EXPECT_EQ(Recorder::count(rec.rects, palette::kColourMap[0]), 1);  // the bar's low end
  EXPECT_EQ(Recorder::count(rec.rects, palette::kColourMap[4]), 1);  // and its high end

  std::vector<Rgba> types;
  const ColourKey by_type = colour_values(std::vector<double>{1, 2, 1}, true, "type", types);
  s.element_fills = types;
  s.colour_key = &by_type;
  Recorder swatches;
  draw_scene(s, flags, camera, swatches);
  EXPECT_TRUE(swatches.has_text("type"));
  EXPECT_TRUE(swatches.has_text("1"));
  EXPECT_TRUE(swatches.has_text("2"));
  EXPECT_EQ(Recorder::count(swatches.rects, category_colour(1)), 1);
}

}  // namespace
}  // namespace nbscope::render

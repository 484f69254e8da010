// Every bundled scene's labels as the window draws them at 1280x720 and 1024x640, panels docked,
// fitted and zoomed in on the grid's lower left corner:
// no label (element id, axis number, the grid's title, the legend) overlaps another, and no element
// id sits in the band of the column numbers or of the row numbers, where it would read as one of them.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <span>

#include "app/frame_loop.hpp"
#include "physics/box2d_detector.hpp"
#include "core/traced_lists.hpp"
#include "render/overlays.hpp"
#include "support/paths.hpp"

namespace nbscope {
namespace {

using render::Vec2;

struct Text {
  Vec2 at;
  std::string text;
  render::Rgba colour;
};

struct TextRecorder final : render::DrawSink {
  std::vector<Text> texts;
  void circle(render::Layer, Vec2, float, render::Rgba, render::Rgba, float, float) override {}
  void polygon(render::Layer, std::span<const Vec2>, render::Rgba, render::Rgba) override {}
  void line(render::Layer, Vec2, Vec2, render::Rgba, float) override {}
  void arrow(render::Layer, Vec2, Vec2, render::Rgba, float) override {}
  void rect(render::Layer, Vec2, Vec2, render::Rgba) override {}
  void text(Vec2 at, std::string_view t, render::Rgba c) override { texts.push_back({at, std::string(t), c}); }
};

struct Box {
  double x0, y0, x1, y1;
};
Box box_of(const render::Camera& c, const Text& t) {
  const Eigen::Vector2d s = c.to_screen(t.at.cast<double>());
  const double w = render::label_width(t.text.size());
  return {s.x() - 0.5 * w, s.y() - 0.5 * render::kLinePx, s.x() + 0.5 * w, s.y() + 0.5 * render::kLinePx};
}
bool overlap(const Box& a, const Box& b) { return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1; }
bool digits(const std::string& s) { return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }); }

// Draws every overlay of `loop`'s frame through `camera` and holds the labels to the rules above.
void check_view(const FrameLoop& loop, const std::vector<TracedList>& lists, const render::Camera& camera,
                const render::ScreenInsets& insets, std::span<const render::PixelRect> panels, const std::string& where) {
  const Elements& e = loop.source().elements();
  render::OverlayScene s;
  s.elements = &e;
  s.grid = &loop.result().selected().grid;
  s.pairs = &loop.result().selected().pairs;
  s.lists = &lists;
  s.insets = insets;
  s.covered = panels;
  s.selected = 0;
  s.list_filter = render::ListFilter::All;
  render::OverlayFlags all;
  for (const auto& o : render::overlay_infos()) all.*o.flag = true;
  TextRecorder rec;
  render::draw_scene(s, all, camera, rec);
  ASSERT_FALSE(rec.texts.empty()) << where;
  EXPECT_TRUE(std::any_of(rec.texts.begin(), rec.texts.end(), [](const Text& t) { return t.text.find(" cells, d = ") != std::string::npos; }))
      << where << ": the grid's title is missing";
  for (std::size_t i = 0; i < rec.texts.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_FALSE(overlap(box_of(camera, rec.texts[i]), box_of(camera, rec.texts[j])))
          << where << ": '" << rec.texts[i].text << "' over '" << rec.texts[j].text << "'";
  // The axis numbers: dim digits along one line (columns share a y, rows an x).
  std::map<long, std::vector<Box>> by_y, by_x;
  for (const Text& t : rec.texts)
    if (t.colour == render::palette::kTextDim && digits(t.text)) {
      const Box b = box_of(camera, t);
      by_y[std::lround(0.5 * (b.y0 + b.y1))].push_back(b);
      by_x[std::lround(b.x1)].push_back(b);
    }
  const auto band = [](const std::vector<Box>& boxes) {
    Box out = boxes.front();
    for (const Box& b : boxes) out = {std::min(out.x0, b.x0), std::min(out.y0, b.y0), std::max(out.x1, b.x1), std::max(out.y1, b.y1)};
    return out;
  };
  // A band reaches a three-digit number past its ends along its line: an id there reads as one more
  // axis number ("41 0 1 2 3" along the columns).
  const double reach = render::label_width(3) + 4.0;
  std::vector<Box> bands;
  for (const auto& [y, boxes] : by_y)
    if (boxes.size() >= 3) {
      const Box b = band(boxes);
      bands.push_back({b.x0 - reach, b.y0, b.x1 + reach, b.y1});
    }
  for (const auto& [x, boxes] : by_x)
    if (boxes.size() >= 3) {
      const Box b = band(boxes);
      bands.push_back({b.x0, b.y0 - render::kLinePx - 2.0, b.x1, b.y1 + render::kLinePx + 2.0});
    }
  for (const Text& t : rec.texts) {
    if (!(t.colour == render::palette::kText) || !digits(t.text)) continue;  // element ids
    for (const Box& b : bands)
      EXPECT_FALSE(overlap(box_of(camera, t), b)) << where << ": element id " << t.text << " among the axis numbers";
  }
  // No other number (a row's, an id) within a line above or below the column numbers, nor just past
  // their ends: "41 0 1 2 3" reads as one row of numbers (mixed-sizes.json zoomed in).
  for (const auto& [y, boxes] : by_y) {
    if (boxes.size() < 3) continue;
    const Box b = band(boxes);
    const Box near{b.x0 - reach, b.y0 - render::kLinePx - 2.0, b.x1 + reach, b.y1 + render::kLinePx + 2.0};
    for (const Text& t : rec.texts) {
      const Box tb = box_of(camera, t);
      if (!digits(t.text) || std::lround(0.5 * (tb.y0 + tb.y1)) == y) continue;
      EXPECT_FALSE(overlap(tb, near)) << where << ": '" << t.text << "' reads as one of the column numbers";
    }
  }
}

TEST(SceneLabels, NoLabelTouchesAnotherAndNoIdSitsAmongTheAxisNumbers) {
  register_physics_detectors();
  std::vector<std::string> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes"))
    if (entry.path().extension() == ".json") scenes.push_back(entry.path().string());
  std::sort(scenes.begin(), scenes.end());
  ASSERT_GE(scenes.size(), 7u);
  for (const auto& path : scenes) {
    FrameLoop loop;
    load_scene_file(loop, path);
    for (int k = 0; k < 10; ++k) loop.step();
    const Elements& e = loop.source().elements();
    const auto trace = loop.pipeline().frame_trace();
    const std::vector<TracedList> lists =
        trace ? traced_lists(trace->log, static_cast<std::size_t>(e.size())) : std::vector<TracedList>{};
    for (const auto& [w, h] : {std::pair{1280, 720}, std::pair{1024, 640}}) {
      // The window's docked columns, menu bar and Timeline.
      const render::ScreenInsets insets{256, 290, 20, 100};
      const render::PixelRect panels[] = {{0, 0, float(w), 19},
                                          {0, 19, 256, float(h)},
                                          {float(w - 290), 19, float(w), float(h)},
                                          {256, float(h - 100), float(w - 290), float(h)}};
      render::Camera camera;
      camera.set_viewport(w, h);
      const double d = loop.result().selected().grid.cell_size;
      render::WorldRect box;
      box.min = Eigen::Vector2d((e.x - e.r).minCoeff(), (e.y - e.r).minCoeff()).array() - 0.5 * d;
      box.max = Eigen::Vector2d((e.x + e.r).maxCoeff(), (e.y + e.r).maxCoeff()).array() + 0.5 * d;
      render::ScreenInsets fit = insets;
      fit.bottom += 44;
      camera.fit(box, 0.06, fit);
      const std::string name = std::filesystem::path(path).filename().string() + " at " + std::to_string(w) + "x" + std::to_string(h);
      check_view(loop, lists, camera, insets, panels, name);
      // Zoomed in on the grid's lower left corner (the axis numbers then run along the free view's
      // edges, beside cells and ids): mixed-sizes.json put "41" just left of the column numbers.
      const Grid& g = loop.result().selected().grid;
      const Eigen::Vector2d corner = camera.to_screen(Eigen::Vector2d(g.origin[0], g.origin[1]));
      for (const double zoom : {3.0, 6.0}) {
        render::Camera zoomed = camera;
        zoomed.zoom_at(Eigen::Vector2d(std::max(corner.x(), 300.0), std::min(corner.y(), h - 130.0)), zoom);
        check_view(loop, lists, zoomed, insets, panels, name + " zoomed in " + std::to_string(int(zoom)) + "x");
      }
    }
  }
}

}  // namespace
}  // namespace nbscope

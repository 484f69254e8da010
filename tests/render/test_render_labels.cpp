// The scene's labels without GL: the grid's title and axis numbers are placed first and stay in the
// part of the view the panels leave free, also zoomed in; element ids never cover another label,
// ids too long for their circle go beside it, and book numbering counts ids and cells from 1.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/detector.hpp"
#include "render/overlays.hpp"

namespace nbscope::render {
namespace {

// Keeps every text with its position.
struct TextRecorder final : DrawSink {
  struct Text {
    Vec2 at;
    std::string text;
  };
  std::vector<Text> texts;
  void circle(Layer, Vec2, float, Rgba, Rgba, float, float) override {}
  void polygon(Layer, std::span<const Vec2>, Rgba, Rgba) override {}
  void line(Layer, Vec2, Vec2, Rgba, float) override {}
  void arrow(Layer, Vec2, Vec2, Rgba, float) override {}
  void rect(Layer, Vec2, Vec2, Rgba) override {}
  void text(Vec2 at, std::string_view t, Rgba) override { texts.push_back({at, std::string(t)}); }
  [[nodiscard]] bool has(const std::string& t) const {
    return std::any_of(texts.begin(), texts.end(), [&](const Text& x) { return x.text == t; });
  }
};

// A label's screen rectangle as the renderer draws it: 7 px a character, 13 px high, centred.
struct Box {
  double x0, y0, x1, y1;
};
Box box_of(const Camera& c, const TextRecorder::Text& t) {
  const Eigen::Vector2d s = c.to_screen(t.at.cast<double>());
  const double w = 7.0 * static_cast<double>(t.text.size()) + 2.0;
  return {s.x() - 0.5 * w, s.y() - 6.5, s.x() + 0.5 * w, s.y() + 6.5};
}
bool overlap(const Box& a, const Box& b) { return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1; }

// A 20 x 20 grid of 1 m cells with one element at every cell centre.
struct Field {
  Elements e;
  Grid grid;
  PairList pairs;
  Camera camera;
  explicit Field(double r = 0.3) {
    Eigen::ArrayXd x(400), y(400);
    for (int k = 0; k < 400; ++k) {
      x[k] = 0.5 + k % 20;
      y[k] = 0.5 + k / 20;
    }
    e = make_elements_2d(x, y, Eigen::ArrayXd::Constant(400, r));
    DetectOptions o;
    o.grid.cell_size = 1.0;
    o.grid.origin = std::array<double, 3>{0, 0, 0};
    auto d = make_detector("nbs");
    d->detect(e, o, pairs);
    grid = *d->last_grid();
    camera.set_viewport(800, 600);
  }
  OverlayScene scene(const ScreenInsets& insets) const {
    OverlayScene s;
    s.elements = &e;
    s.grid = &grid;
    s.pairs = &pairs;
    s.insets = insets;
    return s;
  }
};

OverlayFlags grid_and_ids() {
  OverlayFlags f;
  f.ids = true;
  f.grid = true;
  return f;
}

TEST(Labels, ZoomedInTheAxisNumbersRunAlongTheEdgesOfTheFreeView) {
  Field f;
  f.camera.set({10, 10}, 60.0);  // cells of 60 px: the grid's own edges are far outside the view
  const ScreenInsets insets{120, 80, 20, 150};
  TextRecorder rec;
  draw_scene(f.scene(insets), grid_and_ids(), f.camera, rec);
  int columns = 0, rows = 0;
  for (const auto& t : rec.texts) {
    const Eigen::Vector2d s = f.camera.to_screen(t.at.cast<double>());
    // Column numbers: just above the bottom panel; row numbers: just right of the left one.
    if (s.y() > 600 - 150 - 14 && s.y() < 600 - 150) ++columns;
    if (s.x() > 120 && s.x() < 120 + 20 && s.y() < 600 - 150 - 14) ++rows;
  }
  EXPECT_GE(columns, 8) << "the column (ix) numbers vanished when zoomed in";
  EXPECT_GE(rows, 5) << "the row (iy) numbers vanished when zoomed in";
  EXPECT_TRUE(rec.has("10"));
}

TEST(Labels, NoLabelCoversAnotherOrGoesUnderAPanel) {
  // The menu bar, the left and right columns, the bottom dock and a floating window.
  const PixelRect panels[] = {{0, 0, 800, 19}, {0, 19, 100, 600}, {740, 19, 800, 600}, {100, 480, 740, 600}, {300, 200, 450, 300}};
  for (const double ppm : {25.0, 40.0, 60.0, 120.0}) {
    Field f(0.45);
    f.camera.set({8, 9}, ppm);
    OverlayScene scene = f.scene(ScreenInsets{100, 60, 19, 120});
    scene.covered = panels;
    TextRecorder rec;
    draw_scene(scene, grid_and_ids(), f.camera, rec);
    ASSERT_GT(rec.texts.size(), 10u);
    EXPECT_TRUE(std::any_of(rec.texts.begin(), rec.texts.end(), [](const auto& t) { return t.text.find("20 x 20 cells") == 0; }))
        << "the grid's title is always placed";
    for (std::size_t i = 0; i < rec.texts.size(); ++i) {
      const Box a = box_of(f.camera, rec.texts[i]);
      for (const PixelRect& p : panels)
        EXPECT_FALSE(overlap(a, Box{p.x0 + 0.5, p.y0 + 0.5, p.x1 - 0.5, p.y1 - 0.5}))
            << "'" << rec.texts[i].text << "' under a panel at " << ppm << " px/m";
      for (std::size_t j = 0; j < i; ++j)
        EXPECT_FALSE(overlap(a, box_of(f.camera, rec.texts[j])))
            << "'" << rec.texts[i].text << "' over '" << rec.texts[j].text << "' at " << ppm << " px/m";
    }
  }
}

// gas.json: 4-digit ids do not fit inside circles where 3-digit ones do; they go just above them.
TEST(Labels, IdsTooLongForTheirCircleAreDrawnBesideIt) {
  const int n = 1002;
  Eigen::ArrayXd x = Eigen::ArrayXd::Constant(n, 500.0), y = Eigen::ArrayXd::Constant(n, 500.0);
  x[999] = 2;  // "999": 23 px, fits a 26 px circle
  x[1001] = 6;  // "1001": 30 px, does not
  y[999] = y[1001] = 2;
  const Elements e = make_elements_2d(x, y, Eigen::ArrayXd::Constant(n, 0.5));
  Camera camera;
  camera.set_viewport(400, 300);
  camera.set({4, 2}, 26.0);
  OverlayScene s;
  s.elements = &e;
  OverlayFlags f;
  f.ids = true;
  TextRecorder rec;
  draw_scene(s, f, camera, rec);
  ASSERT_TRUE(rec.has("999"));
  ASSERT_TRUE(rec.has("1001"));
  for (const auto& t : rec.texts) {
    if (t.text == "999") {
      EXPECT_NEAR(t.at.y(), 2.0f, 1e-4f) << "inside its circle";
    }
    if (t.text == "1001") {
      EXPECT_GT(t.at.y(), 2.5f) << "above its circle";
    }
  }
}

TEST(Labels, BookNumberingCountsIdsAndCellsFromOne) {
  Field f;
  f.camera.set({2.5, 2.5}, 60.0);
  OverlayScene zero = f.scene({});
  OverlayScene book = zero;
  book.book_numbering = true;
  TextRecorder r0, r1;
  draw_scene(zero, grid_and_ids(), f.camera, r0);
  draw_scene(book, grid_and_ids(), f.camera, r1);
  // Element 0 sits in cell (0, 0): "0" in 0-based numbering (its id and both axes), never in book numbering.
  EXPECT_TRUE(r0.has("0"));
  EXPECT_FALSE(r1.has("0"));
  EXPECT_TRUE(r1.has("1"));
  // Element 21 is drawn as 22, at the same place.
  const auto at = [](const TextRecorder& r, const std::string& t) {
    for (const auto& x : r.texts)
      if (x.text == t) return x.at;
    return Vec2(-1, -1);
  };
  EXPECT_TRUE(at(r0, "21").isApprox(at(r1, "22")));
}

// A run in named units (--units lj) gives the grid's cell size in them; a scene's metres stay unsaid.
TEST(Labels, TheGridsTitleGivesTheCellSizeInTheRunsUnit) {
  Field f;
  f.camera.set({10, 10}, 30.0);
  OverlayScene metres = f.scene({});
  OverlayScene sigma = metres;
  sigma.length_unit = "sigma";
  TextRecorder r0, r1;
  draw_scene(metres, grid_and_ids(), f.camera, r0);
  draw_scene(sigma, grid_and_ids(), f.camera, r1);
  const auto title = [](const TextRecorder& r) {
    for (const auto& x : r.texts)
      if (x.text.find(" cells, d = ") != std::string::npos) return x.text;
    return std::string();
  };
  EXPECT_EQ(title(r0), "20 x 20 cells, d = 1");
  EXPECT_EQ(title(r1), "20 x 20 cells, d = 1 sigma");
}

}  // namespace
}  // namespace nbscope::render

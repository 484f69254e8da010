// The renderer under OSMesa (and EGL): primitives land on the pixels the camera maths says they should,
// the camera keeps its promises, bad shader directories are refused, PNG files round-trip.
#include <gtest/gtest.h>
#include <imgui.h>

#include <cmath>
#include <filesystem>

#include "core/error.hpp"
#include "io/png.hpp"
#include "render/camera.hpp"
#include "render/gl_context.hpp"
#include "render/imgui_layer.hpp"
#include "render/renderer.hpp"
#include "render/shader.hpp"

namespace nbscope::render {
namespace {

constexpr int kW = 320, kH = 200;

// One OSMesa context and renderer for all tests of this file (creating them costs ~50 ms).
struct Gl {
  std::unique_ptr<GlContext> context = make_offscreen_context(kW, kH, "osmesa");
  Renderer renderer{resolve_shader_dir(NBSCOPE_SHADER_DIR)};
};
Gl& gl() {
  static Gl instance;
  return instance;
}

// A camera 10 px per metre with the world origin at the centre of the viewport.
Camera test_camera() {
  Camera c;
  c.set_viewport(kW, kH);
  c.set({0, 0}, 10.0);
  return c;
}

bool same_rgb(const std::uint8_t* px, Rgba c) { return px[0] == c.r && px[1] == c.g && px[2] == c.b; }
std::string rgb(const std::uint8_t* px) {
  return std::to_string(px[0]) + "," + std::to_string(px[1]) + "," + std::to_string(px[2]);
}

void save_for_inspection(const Image& img, const std::string& name) {
  std::filesystem::create_directories(std::string(NBSCOPE_TEST_OUT) + "/render");
  write_png(std::string(NBSCOPE_TEST_OUT) + "/render/" + name + ".png", img);
}

TEST(Camera, ScreenAndWorldRoundTripAndYPointsUp) {
  Camera c = test_camera();
  const Eigen::Vector2d p(3.25, -1.5);
  EXPECT_TRUE(c.to_world(c.to_screen(p)).isApprox(p, 1e-12));
  // 10 px per metre, origin at (160, 100), y up in the world and down on screen.
  EXPECT_TRUE(c.to_screen({1, 1}).isApprox(Eigen::Vector2d(170, 90), 1e-12));
}

TEST(Camera, ZoomKeepsThePointUnderTheCursorFixed) {
  Camera c = test_camera();
  const Eigen::Vector2d cursor(40, 170);
  const Eigen::Vector2d before = c.to_world(cursor);
  c.zoom_at(cursor, 3.7);
  EXPECT_NEAR(c.pixels_per_metre(), 37.0, 1e-9);
  EXPECT_TRUE(c.to_world(cursor).isApprox(before, 1e-12));
}

TEST(Camera, PanMovesTheWorldWithTheMouseAndHomeRestoresTheFit) {
  Camera c = test_camera();
  c.fit({{-5, -2}, {15, 8}}, 0.0);
  // The whole rectangle is visible and touches the viewport on the tighter axis.
  const WorldRect v = c.view();
  EXPECT_LE(v.min.x(), -5 + 1e-9);
  EXPECT_GE(v.max.x(), 15 - 1e-9);
  EXPECT_LE(v.min.y(), -2 + 1e-9);
  EXPECT_GE(v.max.y(), 8 - 1e-9);
  EXPECT_NEAR(c.pixels_per_metre(), 16.0, 1e-9);  // min(320/20, 200/10)
  const Eigen::Vector2d grabbed = c.to_world({100, 100});
  c.pan_pixels({25, -10});
  EXPECT_TRUE(c.to_world({125, 90}).isApprox(grabbed, 1e-12));
  c.zoom_at({0, 0}, 2.0);
  c.home();
  EXPECT_NEAR(c.pixels_per_metre(), 16.0, 1e-9);
  EXPECT_TRUE(c.centre().isApprox(Eigen::Vector2d(5, 3), 1e-12));
}

// Draws a rect, circles and a line through `r` into `context` and checks their pixels.
void expect_primitives_where_the_camera_puts_them(GlContext& context, Renderer& r, const std::string& name) {
  const Camera cam = test_camera();
  const Rgba fill{200, 40, 40}, outline{40, 200, 40}, line{30, 60, 250}, cell{250, 250, 0};
  r.begin_frame(cam);
  r.rect(Layer::Cells, {-15, 5}, {-10, 9}, cell);                    // pixels x 10..60, y 10..50
  r.circle(Layer::Bodies, {0, 0}, 4.0f, fill, outline, 3.0f);          // radius 40 px at (160, 100)
  r.line(Layer::Overlay, {6, -8}, {14, -8}, line, 3.0f);             // y = 180, x 220..300
  r.circle(Layer::Top, {-14, -8}, 0.01f, fill, Rgba{0, 0, 0, 0}, 0.0f, 6.0f);  // tiny, but 6 px on screen
  r.draw(palette::kBackground);
  const Image img = context.read_pixels();
  save_for_inspection(img, name);

  EXPECT_TRUE(same_rgb(img.at(160, 100), fill)) << rgb(img.at(160, 100));
  EXPECT_TRUE(same_rgb(img.at(160 + 38, 100), outline)) << rgb(img.at(198, 100));  // inside the 3 px band
  EXPECT_TRUE(same_rgb(img.at(160 + 30, 100), fill)) << rgb(img.at(190, 100));
  EXPECT_TRUE(same_rgb(img.at(160 + 44, 100), palette::kBackground)) << rgb(img.at(204, 100));
  EXPECT_TRUE(same_rgb(img.at(160 + 29, 100 + 29), palette::kBackground));  // corner of the quad: cut away
  EXPECT_TRUE(same_rgb(img.at(35, 30), cell)) << rgb(img.at(35, 30));
  EXPECT_TRUE(same_rgb(img.at(65, 30), palette::kBackground));
  EXPECT_TRUE(same_rgb(img.at(260, 180), line)) << rgb(img.at(260, 180));
  EXPECT_TRUE(same_rgb(img.at(260, 185), palette::kBackground));
  EXPECT_TRUE(same_rgb(img.at(20, 180), fill)) << rgb(img.at(20, 180));  // the 6 px marker
  EXPECT_TRUE(same_rgb(img.at(20 + 9, 180), palette::kBackground));

  // One draw call per non-empty kind and layer: rects, circles (2 layers), lines.
  EXPECT_EQ(r.stats().draw_calls, 4);
}

TEST(Renderer, PrimitivesLandWhereTheCameraPutsThem) {
  Gl& g = gl();
  expect_primitives_where_the_camera_puts_them(*g.context, g.renderer, "primitives");
}

// The same pixels through EGL, whose surfaceless context draws into an FBO of its own: its
// viewport, colour format and row order must match OSMesa's buffer.
TEST(Renderer, PrimitivesLandWhereTheCameraPutsThemUnderEgl) {
  {
    const std::unique_ptr<GlContext> context = make_offscreen_context(kW, kH, "egl");
    EXPECT_STREQ(context->kind(), "egl");
    EXPECT_EQ(context->width(), kW);
    EXPECT_EQ(context->height(), kH);
    Renderer renderer{resolve_shader_dir(NBSCOPE_SHADER_DIR)};
    expect_primitives_where_the_camera_puts_them(*context, renderer, "primitives_egl");
  }
  // Back to this file's OSMesa context (and its GL functions) for the tests that follow.
  gl().context->make_current();
}

TEST(Renderer, ArrowsAndPolygonsFillTheirInsides) {
  Gl& g = gl();
  Renderer& r = g.renderer;
  const Rgba poly{220, 120, 20}, arrow{240, 240, 240};
  r.begin_frame(test_camera());
  const Vec2 tri[] = {{-10, -5}, {-2, -5}, {-6, 3}};  // pixels (60,150) (140,150) (100,70)
  r.polygon(Layer::Bodies, tri, poly, Rgba{0, 0, 0, 0});
  r.arrow(Layer::Overlay, {2, 0}, {12, 0}, arrow, 2.0f);  // pixels (180,100) -> (280,100)
  r.draw(palette::kBackground);
  const Image img = g.context->read_pixels();
  save_for_inspection(img, "arrow_polygon");
  EXPECT_TRUE(same_rgb(img.at(100, 130), poly)) << rgb(img.at(100, 130));
  EXPECT_TRUE(same_rgb(img.at(60, 80), palette::kBackground));
  EXPECT_TRUE(same_rgb(img.at(200, 100), arrow)) << rgb(img.at(200, 100));
  // The head (10 px long, 5 px wide on each side at its base) is filled around the shaft.
  EXPECT_TRUE(same_rgb(img.at(274, 102), arrow)) << rgb(img.at(274, 102));
  EXPECT_TRUE(same_rgb(img.at(230, 104), palette::kBackground)) << rgb(img.at(230, 104));
}

TEST(Renderer, ImGuiPanelsAndLabelsDrawOverTheScene) {
  Gl& g = gl();
  ImGuiLayer imgui(nullptr);
  Renderer& r = g.renderer;
  for (int frame = 0; frame < 3; ++frame) {  // windows take two frames to size themselves
    r.begin_frame(test_camera());
    r.text({-10, 0}, "1234", palette::kText);
    r.draw(palette::kBackground);
    imgui.new_frame(false, kW, kH, 1.0f / 60.0f);
    ImGui::SetNextWindowPos(ImVec2(200, 10));
    ImGui::Begin("Panel", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::TextUnformatted("hello");
    ImGui::End();
    r.emit_labels(ImGui::GetBackgroundDrawList());
    imgui.render();
  }
  const Image img = g.context->read_pixels();
  save_for_inspection(img, "imgui");
  EXPECT_GT(imgui.last_vertices(), 0);
  // The label around pixel (60, 100) has text-coloured pixels; the panel at (200, 10) is not background.
  int text_pixels = 0;
  for (int y = 90; y < 110; ++y)
    for (int x = 40; x < 80; ++x) text_pixels += same_rgb(img.at(x, y), palette::kText) ? 1 : 0;
  EXPECT_GT(text_pixels, 10);
  EXPECT_FALSE(same_rgb(img.at(205, 15), palette::kBackground));
}

TEST(Renderer, MissingShaderDirectoryIsRefusedWithItsName) {
  try {
    (void)resolve_shader_dir("/nonexistent/shaders");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/shaders"), std::string::npos) << e.what();
  }
  gl();  // a context must be current for Program
  const std::string dir = std::string(NBSCOPE_TEST_OUT) + "/render/bad_shaders";
  std::filesystem::create_directories(dir);
  testing::internal::CaptureStderr();
  EXPECT_THROW(Program(dir, "circle"), Error);
  testing::internal::GetCapturedStderr();
}

TEST(Offscreen, UnknownBackendsAndSizesAreRefused) {
  EXPECT_THROW(make_offscreen_context(64, 64, "vulkan"), Error);
  EXPECT_THROW(make_offscreen_context(0, 64, "egl"), Error);
  EXPECT_THROW(make_offscreen_context(64, 9000, "osmesa"), Error);
}

TEST(Png, RoundTripCompareAndAtomicFailure) {
  const std::string dir = std::string(NBSCOPE_TEST_OUT) + "/render";
  std::filesystem::create_directories(dir);
  Image a = Image::filled(40, 30, 10, 20, 30);
  a.at(5, 7)[1] = 200;
  write_png(dir + "/roundtrip.png", a);
  const Image b = read_png(dir + "/roundtrip.png");
  ASSERT_EQ(b.width, 40);
  ASSERT_EQ(b.height, 30);
  EXPECT_EQ(b.rgba, a.rgba);

  Image c = b;
  c.at(1, 1)[0] = static_cast<std::uint8_t>(c.at(1, 1)[0] + 3);   // within tolerance 3
  c.at(2, 2)[2] = static_cast<std::uint8_t>(c.at(2, 2)[2] + 40);  // beyond it
  const ImageDiff d = compare_images(c, b, 3);
  EXPECT_EQ(d.differing, 1);
  EXPECT_EQ(d.max_channel_delta, 40);
  EXPECT_EQ(d.diff.at(2, 2)[0], 255);
  EXPECT_FALSE(compare_images(Image::filled(4, 4, 0, 0, 0), b, 3).same_size);
  EXPECT_TRUE(is_uniform(Image::filled(4, 4, 9, 9, 9)));
  EXPECT_FALSE(is_uniform(b));

  EXPECT_THROW(write_png("/nonexistent-dir/x.png", a), Error);
  EXPECT_THROW(read_png(dir + "/missing.png"), Error);
  EXPECT_FALSE(std::filesystem::exists("/nonexistent-dir/x.png"));
}

}  // namespace
}  // namespace nbscope::render

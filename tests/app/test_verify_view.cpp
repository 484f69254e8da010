// The verify view under OSMesa on a hand-made run (the book's nine elements, screen arrays with a
// planted bug): the screenshot is written and shows the wrong link in red where it lies on screen,
// the first problem is selected, and choosing another problem puts the camera on it. And the
// window's panels read the frame loop's own FrameResult (the SimView points at it, copies nothing).
#include <gtest/gtest.h>

#include <filesystem>

#include "app/gl_view.hpp"
#include "app/verify_view_impl.hpp"
#include "core/error.hpp"
#include "io/png.hpp"
#include "physics/box2d_detector.hpp"
#include "render/gl_context.hpp"
#include "support/verify_fixture.hpp"

namespace nbscope {
namespace {

const std::string kOut = std::string(NBSCOPE_TEST_OUT) + "/verify_view";

ViewOptions options() {
  ViewOptions o;
  o.width = 1000;
  o.height = 600;
  o.shader_dir = NBSCOPE_SHADER_DIR;
  o.gl = "osmesa";
  return o;
}

// True when some pixel within `radius` of (x, y) is the marks' red (kViolation, not the panels' tints).
bool red_near(const Image& image, const Eigen::Vector2d& at, int radius) {
  for (int y = static_cast<int>(at.y()) - radius; y <= static_cast<int>(at.y()) + radius; ++y)
    for (int x = static_cast<int>(at.x()) - radius; x <= static_cast<int>(at.x()) + radius; ++x) {
      if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
      const std::uint8_t* p = image.at(x, y);
      if (p[0] > 220 && p[1] < 90 && p[2] < 90) return true;
    }
  return false;
}

TEST(VerifyView, TheScreenshotIsWrittenWithTheFirstProblemSelected) {
  const testdata::PlantedBug bug(1);
  std::filesystem::create_directories(kOut);
  ViewOptions o = options();
  o.screenshot = kOut + "/planted_bug.png";
  std::filesystem::remove(*o.screenshot);
  const std::string summary = write_verify_screenshot(bug.run, o);
  EXPECT_NE(summary.find("4 lists on 9 elements, 3 problems (the first selected)"), std::string::npos) << summary;
  const Image image = read_png(*o.screenshot);
  EXPECT_EQ(image.width, 1000);
  EXPECT_FALSE(is_uniform(image));
}

TEST(VerifyView, TheWrongLinkIsRedOnScreenAndAProblemChosenGetsTheCamera) {
  const testdata::PlantedBug bug(1);
  const auto context = render::make_offscreen_context(1000, 600, "osmesa");
  VerifyView view(*context, nullptr, bug.run, options());
  for (int i = 0; i < VerifyView::kSettleFrames; ++i) view.frame(false, 1.0f / 60.0f);
  EXPECT_EQ(view.selected_problem(), 0);
  const Image image = context->read_pixels();
  const Elements& e = bug.run.elements;
  const auto screen = [&](ElementId k) { return view.camera().to_screen({e.x[k], e.y[k]}); };
  // Along the link 1 -> 6 (0-based; E[2] = 7 in the file's numbering), a third of the way and half-way.
  for (const double t : {0.35, 0.5, 0.65}) EXPECT_TRUE(red_near(image, screen(1) + t * (screen(6) - screen(1)), 4)) << "t " << t;
  // Not along a right link (3 -> 1, same list).
  EXPECT_FALSE(red_near(image, 0.5 * (screen(3) + screen(1)), 2));

  // Problem 3 (8 -> 6 meets 6 again) chosen: the camera puts the pair in the middle of the free view.
  view.go_to_problem(2);
  view.frame(false, 1.0f / 60.0f);
  EXPECT_EQ(view.selected_problem(), 2);
  const Eigen::Vector2d mid = 0.5 * (screen(8) + screen(6));
  const double free_w = 1000 - ui::kVerifyColumnWidth;
  EXPECT_NEAR(mid.x(), 0.5 * free_w, 0.1 * free_w);
  EXPECT_GT(mid.y(), 0.0);
  EXPECT_LT(mid.y(), 600.0);
  EXPECT_NE(view.marks().caption.front().find("3 of 3 problems"), std::string::npos) << view.marks().caption.front();
}

TEST(VerifyView, UnknownPanelsAndElementsAreRefused) {
  const testdata::PlantedBug bug(1);
  const auto context = render::make_offscreen_context(400, 300, "osmesa");
  const auto make = [&](const ViewOptions& o) { VerifyView v(*context, nullptr, bug.run, o); };
  ViewOptions o = options();
  o.panels = "problems,+nonsense";
  EXPECT_THROW(make(o), Error);
  o = options();
  o.select = 0;  // counted from 1 in this file's numbering
  EXPECT_THROW(make(o), Error);
  o.select = 9;
  EXPECT_NO_THROW(make(o));
}

// A floating panel that keeps what the SimView it is handed says about the frame.
struct FrameProbe final : ui::Panel {
  const FrameResult** frame;
  std::int64_t* number;
  FrameProbe(const FrameResult** f, std::int64_t* n) : frame(f), number(n) {}
  [[nodiscard]] const char* title() const override { return "Frame probe"; }
  [[nodiscard]] ui::PanelPlace place() const override { return ui::PanelPlace::Floating; }
  void draw(ui::UiContext& c) override {
    *frame = c.sim.frame;
    *number = c.sim.frame_number();
  }
};

TEST(PanelsView, TheSimViewPointsAtTheFrameLoopsOwnResult) {
  register_physics_detectors();
  const auto context = render::make_offscreen_context(800, 500, "osmesa");
  FrameLoop loop;
  load_scene_file(loop, std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/book-fig-3-15.json");
  ViewOptions o = options();
  o.width = 800;
  o.height = 500;
  GlView view(*context, nullptr, o, loop);
  const FrameResult* seen = nullptr;
  std::int64_t number = -1;
  view.host().add_panel(std::make_unique<FrameProbe>(&seen, &number));
  Session session;
  session.paused = true;
  view.frame(loop, session, false, 1.0f / 60.0f);
  EXPECT_EQ(seen, &loop.result());
  EXPECT_EQ(number, 0);
  loop.step();
  view.frame(loop, session, false, 1.0f / 60.0f);
  EXPECT_EQ(seen, &loop.result());
  EXPECT_EQ(number, 1);
  EXPECT_EQ(number, loop.source().frame());
}

}  // namespace
}  // namespace nbscope

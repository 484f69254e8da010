// The window's view under OSMesa, driven as the window drives it: the stepper and the lists overlay
// hold the same trace of a frame, the overlay shows the lists as they stand at the stepper's
// operation (and the finished lists at the end), and a selection survives a restart but not a
// change of scene.
#include <gtest/gtest.h>

#include "app/gl_view.hpp"
#include "physics/box2d_detector.hpp"
#include "render/gl_context.hpp"
#include "core/traced_lists.hpp"
#include "ui/stepper_panels.hpp"

namespace nbscope {
namespace {

std::string scene(const char* name) { return std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/" + name; }

struct ViewRig {
  std::unique_ptr<render::GlContext> context = render::make_offscreen_context(800, 500, "osmesa");
  FrameLoop loop;
  Session session;
  std::unique_ptr<GlView> view;
  explicit ViewRig(ViewOptions options, const char* file) {
    register_physics_detectors();
    options.width = 800;
    options.height = 500;
    options.shader_dir = NBSCOPE_SHADER_DIR;
    load_scene_file(loop, scene(file));
    session.scene_path = loop.source().scene().path;
    session.paused = true;
    view = std::make_unique<GlView>(*context, nullptr, options);
    view->on_scene_loaded(loop);
  }
  void frames(int n) {
    for (int k = 0; k < n; ++k) view->frame(loop, session, false, 1.0f / 60.0f);
  }
};

TEST(GlView, TheStepperAndTheListsOverlayShareOneTraceAndAgreeAtEveryOperation) {
  ViewOptions o;
  o.overlays = "+lists";
  o.step = 3;
  ViewRig rig(o, "book-fig-3-15.json");
  rig.frames(3);
  ui::StepperSession& s = rig.view->stepper();
  ASSERT_TRUE(s.has_capture()) << s.message();
  const auto trace = rig.loop.pipeline().frame_trace();
  EXPECT_EQ(s.frame_trace(), trace) << "the stepper ran a detection of its own";
  const std::size_t n = static_cast<std::size_t>(rig.loop.source().elements().size());
  for (const std::size_t p : {std::size_t{3}, std::size_t{56}, s.stepper().size()}) {
    s.stepper().seek(p);
    rig.frames(1);
    const auto expected = traced_lists(trace->log, n, p);
    ASSERT_EQ(rig.view->lists().size(), expected.size()) << "at operation " << p;
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(rig.view->lists()[i].chain, expected[i].chain) << "at operation " << p;
  }
  // At the end: the finished lists.
  const auto finished = traced_lists(trace->log, n);
  ASSERT_EQ(rig.view->lists().size(), finished.size());
  // Operation 3 differs from the end (the scene does not show finished lists mid-trace).
  EXPECT_NE(traced_lists(trace->log, n, 3).size(), finished.size());
}

// Box2D keeps no book arrays: paused, with the stepper open, the panels say so (not "pause").
TEST(GlView, ADetectorWithoutATraceSaysSoInTheStepperPanels) {
  ViewOptions o;
  o.overlays = "+lists";
  o.panels = "+stepper,+arrays,+pseudocode";
  ViewRig rig(o, "book-fig-3-15.json");
  rig.loop.pipeline().set_algorithm("box2d");
  rig.frames(2);
  const ui::StepperSession& s = rig.view->stepper();
  EXPECT_FALSE(s.has_capture());
  EXPECT_NE(s.message().find("box2d records no operations"), std::string::npos) << s.message();
  EXPECT_EQ(ui::idle_message(s), s.message());
  EXPECT_TRUE(rig.view->lists().empty());
}

// The Arrays panel alone (the Stepper closed) still gets the frame's trace.
TEST(GlView, TheArraysPanelAloneHoldsTheTrace) {
  ViewOptions o;
  o.step = 5;
  o.panels = "-stepper,-pseudocode,+arrays";
  ViewRig rig(o, "book-fig-3-15.json");
  rig.frames(2);
  EXPECT_NO_THROW(rig.view->check_step());
  EXPECT_TRUE(rig.view->stepper().has_capture()) << rig.view->stepper().message();
  EXPECT_EQ(rig.view->stepper().frame_trace(), rig.loop.pipeline().frame_trace());
}

TEST(GlView, ASelectionSurvivesARestartButNotAnotherScene) {
  ViewOptions o;
  o.select = 5;
  ViewRig rig(o, "book-fig-3-15.json");
  rig.frames(1);
  EXPECT_EQ(rig.view->state().selected, 5) << "--select chose it for the first scene";
  rig.loop.step();
  rig.loop.restart();
  rig.view->on_scene_loaded(rig.loop, false);
  EXPECT_EQ(rig.view->state().selected, 5) << "a restart shows the same bodies";
  load_scene_file(rig.loop, scene("pile.json"));
  rig.view->on_scene_loaded(rig.loop);
  EXPECT_EQ(rig.view->state().selected, -1) << "element 5 of another scene is another body";
}

}  // namespace
}  // namespace nbscope

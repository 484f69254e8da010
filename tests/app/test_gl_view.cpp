// The window's view under OSMesa, driven as the window drives it: the stepper and the lists overlay
// hold the same trace of a frame, the overlay shows the lists as they stand at the stepper's
// operation (and the finished lists at the end), a selection survives a restart but not a change
// of scene, and the view follows the loop's changes (GlView::follow) without being told of each.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "app/gl_view.hpp"
#include "app/gui_requests.hpp"
#include "physics/box2d_detector.hpp"
#include "render/gl_context.hpp"
#include "render/gl_window.hpp"
#include "core/traced_lists.hpp"
#include "support/x_display.hpp"
#include "ui/stepper_panels.hpp"

namespace nbscope {
namespace {

std::string scene(const char* name) { return std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/" + name; }

struct ViewRig {
  std::unique_ptr<render::GlContext> context;
  FrameLoop loop;
  Session session;
  std::unique_ptr<GlView> view;
  explicit ViewRig(ViewOptions options, const char* file, const FrameLoopOptions& loop_options = {}, int width = 800, int height = 500)
      : context(render::make_offscreen_context(width, height, "osmesa")), loop(loop_options) {
    register_physics_detectors();
    options.width = width;
    options.height = height;
    options.shader_dir = NBSCOPE_SHADER_DIR;
    load_scene_file(loop, scene(file));
    session.scene_path = loop.source().scene().path;
    session.paused = true;
    view = std::make_unique<GlView>(*context, nullptr, options, loop);
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
  rig.loop.redetect_with_algorithm("box2d");
  rig.frames(2);
  const ui::StepperSession& s = rig.view->stepper();
  EXPECT_FALSE(s.has_capture());
  EXPECT_NE(s.message().find("box2d records no operations"), std::string::npos) << s.message();
  EXPECT_EQ(ui::idle_message(s), s.message());
  EXPECT_TRUE(rig.view->lists().empty());
}

// A violation chosen with the Stepper closed (a click in Violations or Stats, or ]): opening the
// Stepper afterwards goes to the operation that decided the pair, as if it had been open.
TEST(GlView, AStepperOpenedAfterAViolationWasChosenGoesToItsOperation) {
  FrameLoopOptions faulty;
  faulty.fault = Fault::DropPair;
  ViewRig rig(ViewOptions{}, "book-fig-3-15.json", faulty);
  rig.frames(1);
  ASSERT_FALSE(rig.loop.history().violation_log().listed().empty()) << "drop-pair loses a pair on frame 0";
  ui::UiRequests choose;
  choose.go_to_violation = 0;
  apply_requests(choose, rig.loop, *rig.view, rig.session);
  rig.frames(2);
  const ui::StepperSession& s = rig.view->stepper();
  EXPECT_FALSE(s.target_location().has_value()) << "the Stepper is closed";
  rig.view->state().panel_open[ui::kStepperTitle] = true;
  rig.frames(3);
  ASSERT_TRUE(s.has_capture()) << s.message();
  ASSERT_TRUE(s.target_location().has_value()) << "the Stepper opened at operation " << s.stepper().position();
  ASSERT_TRUE(s.target_location()->event.has_value());
  EXPECT_EQ(s.stepper().position(), *s.target_location()->event + 1);
  EXPECT_GT(s.stepper().position(), 0u);
}

// A key tap the window queued (press and release between two frames) acts on the next live frame.
TEST(GlView, ATapQueuedBetweenTwoFramesActs) {
  ViewRig rig(ViewOptions{}, "book-fig-3-15.json");
  rig.frames(1);
  const render::InputEvent tap[] = {{render::InputEvent::Kind::Key, render::InputEvent::Action::Press, 'P'},
                                    {render::InputEvent::Kind::Key, render::InputEvent::Action::Release, 'P'}};
  rig.view->queue_input(tap);
  EXPECT_TRUE(rig.view->frame(rig.loop, rig.session, true, 1.0f / 60.0f).toggle_pause);
  EXPECT_FALSE(rig.view->frame(rig.loop, rig.session, true, 1.0f / 60.0f).toggle_pause);
}

// Through GLFW's own callbacks in a real window (without a display the test runs itself again on its
// own Xvfb): ImGui's backend, which chains to the window's callback, still sees the key, and
// the window queues it, so a press and release before the next frame still act on it.
TEST(GlViewWindow, ATapThroughGlfwsCallbacksActs) {
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') {
    NBSCOPE_SKIP_WITHOUT_XVFB();
    const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
    const std::string cmd = testcli::on_display() + " '" + self +
                            "' --gtest_filter=GlViewWindow.ATapThroughGlfwsCallbacksActs >/dev/null 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    return;
  }
  register_physics_detectors();
  render::GlfwWindow window(800, 500, "nbscope test");
  FrameLoop loop;
  load_scene_file(loop, scene("book-fig-3-15.json"));
  Session session;
  session.paused = true;
  ViewOptions o;
  o.width = 800;
  o.height = 500;
  o.shader_dir = NBSCOPE_SHADER_DIR;
  GlView view(window, window.handle(), o, loop);
  view.frame(loop, session, true, 1.0f / 60.0f);
  // The key callback GLFW calls now: ImGui's, installed after the window's.
  const GLFWkeyfun key = glfwSetKeyCallback(window.handle(), nullptr);
  glfwSetKeyCallback(window.handle(), key);
  ASSERT_NE(key, nullptr);
  key(window.handle(), GLFW_KEY_P, 0, GLFW_PRESS, 0);
  EXPECT_TRUE(ImGui::GetIO().KeysDown[GLFW_KEY_P]) << "ImGui's backend no longer gets the keys";
  key(window.handle(), GLFW_KEY_P, 0, GLFW_RELEASE, 0);
  view.queue_input(window.take_input());
  EXPECT_TRUE(view.frame(loop, session, true, 1.0f / 60.0f).toggle_pause) << "the tap between two frames was lost";
  view.queue_input(window.take_input());
  EXPECT_FALSE(view.frame(loop, session, true, 1.0f / 60.0f).toggle_pause);
}

// Choosing a violation in the window (1280x720, the default scene with a fault) collapses no panel
// and moves none that was already shown: the Selection panel comes below the others.
TEST(GlView, ChoosingAViolationLeavesThePanelsWhereTheyAre) {
  FrameLoopOptions faulty;
  faulty.fault = Fault::DropMaskCell;
  ViewRig rig(ViewOptions{}, "default.json", faulty, 1280, 720);
  for (int k = 0; k < 40 && rig.loop.history().violation_log().listed().size() < 3; ++k) {
    rig.loop.step();
    rig.frames(1);
  }
  ASSERT_GE(rig.loop.history().violation_log().listed().size(), 3u);
  rig.frames(GlView::kSettleFrames);
  struct Shown {
    const ImGuiWindow* window;
    ImVec2 pos;
    bool collapsed;
  };
  std::vector<Shown> before;
  for (const auto& p : rig.view->host().panels())
    if (const ImGuiWindow* w = ImGui::FindWindowByName(p->title()); w != nullptr && w->Active)
      before.push_back({w, w->Pos, w->Collapsed});
  ASSERT_GE(before.size(), 5u);
  ui::UiRequests choose;
  choose.go_to_violation = 1;
  apply_requests(choose, rig.loop, *rig.view, rig.session);
  rig.frames(GlView::kSettleFrames);
  ASSERT_GE(rig.view->state().selected, 0);
  for (const Shown& s : before) {
    EXPECT_EQ(s.window->Collapsed, s.collapsed) << s.window->Name;
    EXPECT_EQ(s.window->Pos.x, s.pos.x) << s.window->Name;
    EXPECT_EQ(s.window->Pos.y, s.pos.y) << s.window->Name;
  }
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
  rig.frames(1);
  EXPECT_EQ(rig.view->state().selected, 5) << "a restart shows the same bodies";
  load_scene_file(rig.loop, scene("pile.json"));
  rig.frames(1);
  EXPECT_EQ(rig.view->state().selected, -1) << "element 5 of another scene is another body";
}

// Element k's position in the frame shown, as the trail keeps it.
render::Vec2 position(const FrameLoop& loop, ElementId k) {
  const Elements& e = loop.source().elements();
  return {static_cast<float>(e.x[k]), static_cast<float>(e.y[k])};
}

bool any_flash(const GlView& view) {
  return std::any_of(view.flashes().begin(), view.flashes().end(), [](float f) { return f > 0; });
}

// Drawn after every step: the trail grows one point a step from the first frame, and the elements
// whose cell changed flash.
TEST(GlViewFollow, EachStepDrawnAddsItsTrailPointAndFlashes) {
  ViewOptions o;
  o.select = 12;
  ViewRig rig(o, "default.json");
  ASSERT_EQ(rig.view->trails().size(), 1u);
  EXPECT_EQ(rig.view->trails().front(), std::vector<render::Vec2>{position(rig.loop, 12)}) << "a new scene: its first frame only";
  bool flashed = false;
  for (int k = 1; k <= 20; ++k) {
    rig.loop.step();
    rig.frames(1);
    ASSERT_EQ(rig.view->trails().size(), 1u);
    ASSERT_EQ(rig.view->trails().front().size(), static_cast<std::size_t>(k + 1)) << "one point a step";
    EXPECT_EQ(rig.view->trails().front().back(), position(rig.loop, 12));
    flashed = flashed || any_flash(*rig.view);
  }
  EXPECT_TRUE(flashed) << "20 frames of the default scene move some element to another cell";
}

// Nobody tells a view about steps: one that draws only after N steps shows the very trail and
// flashes of one that drew after each (the trail from the history, the flashes from the loop's
// cell changes). (One view at a time holds the ImGui context: the first rig's figures are kept.)
TEST(GlViewFollow, StepsDrawnOnlyAtTheEndShowWhatEachStepDrawnShows) {
  ViewOptions o;
  o.select = 12;
  std::vector<std::vector<render::Vec2>> trails;
  std::vector<float> flashes;
  {
    ViewRig each(o, "default.json");
    for (int k = 1; k <= 20; ++k) {
      each.loop.step();
      each.frames(1);
    }
    trails = each.view->trails();
    flashes = each.view->flashes();
  }
  ASSERT_TRUE(std::any_of(flashes.begin(), flashes.end(), [](float f) { return f > 0; })) << "nothing to compare";
  ViewRig rig(o, "default.json");
  std::vector<render::Vec2> path{position(rig.loop, 12)};
  for (int k = 1; k <= 20; ++k) {
    rig.loop.step();
    path.push_back(position(rig.loop, 12));
  }
  rig.frames(1);
  ASSERT_EQ(rig.view->trails().size(), 1u);
  EXPECT_EQ(rig.view->trails().front(), path) << "frames 0..20 from the history";
  EXPECT_EQ(rig.view->trails(), trails);
  ASSERT_EQ(rig.view->flashes().size(), flashes.size());
  for (std::size_t k = 0; k < flashes.size(); ++k) EXPECT_FLOAT_EQ(rig.view->flashes()[k], flashes[k]) << "element " << k;
  // A restart then steps, unseen alike: the new run's trail only, flashes from its own steps.
  rig.loop.restart();
  rig.loop.step();
  rig.loop.step();
  rig.frames(1);
  ASSERT_EQ(rig.view->trails().size(), 1u);
  EXPECT_EQ(rig.view->trails().front(), std::vector<render::Vec2>(path.begin(), path.begin() + 3));
  EXPECT_EQ(rig.loop.cell_changes().steps(), 2u);
}

// Nothing changed since the last frame drawn: nothing moves, not even the flashes' fading; a redetect
// (same frame) changes nothing seen either.
TEST(GlViewFollow, NoChangeAndARedetectLeaveTrailsAndFlashesAlone) {
  ViewOptions o;
  o.select = 12;
  ViewRig rig(o, "default.json");
  for (int k = 0; k < 60 && !any_flash(*rig.view); ++k) {
    rig.loop.step();
    rig.frames(1);
  }
  ASSERT_TRUE(any_flash(*rig.view));
  const std::vector<float> flashes = rig.view->flashes();
  const auto trails = rig.view->trails();
  rig.frames(3);
  EXPECT_EQ(rig.view->flashes(), flashes) << "no change: the flashes did not fade";
  EXPECT_EQ(rig.view->trails(), trails);
  rig.loop.redetect();
  rig.loop.redetect_with_algorithm("sort");
  rig.frames(1);
  EXPECT_EQ(rig.view->flashes(), flashes) << "the same frame detected again";
  EXPECT_EQ(rig.view->trails(), trails);
  // The next step fades them once.
  rig.loop.step();
  rig.frames(1);
  for (std::size_t k = 0; k < flashes.size(); ++k) {
    const float now = rig.view->flashes()[k];
    if (flashes[k] > 0) {
      EXPECT_TRUE(now == 1.0f || now < flashes[k]) << "element " << k << ": faded, or its cell changed again";
    }
  }
  EXPECT_EQ(rig.view->trails().front().size(), trails.front().size() + 1);
}

// A selection made mid-run shows where the element came from at once: its trail over the kept frames.
TEST(GlViewFollow, ANewSelectionShowsItsPastTrail) {
  ViewRig rig(ViewOptions{}, "default.json");
  std::vector<render::Vec2> path{position(rig.loop, 7)};
  for (int k = 1; k <= 12; ++k) {
    rig.loop.step();
    path.push_back(position(rig.loop, 7));
  }
  rig.frames(1);
  EXPECT_TRUE(rig.view->trails().empty()) << "nothing selected";
  rig.view->state().selected = 7;
  rig.frames(1);
  ASSERT_EQ(rig.view->trails().size(), 1u);
  EXPECT_EQ(rig.view->trails().front(), path);
}

// Going back one kept frame flashes from the neighbour; a jump starts the flashes again; either way
// the trail is the history's up to the frame shown.
TEST(GlViewFollow, AFrameShownRebuildsTheTrailFromTheHistory) {
  ViewOptions o;
  o.select = 12;
  ViewRig rig(o, "default.json");
  std::vector<render::Vec2> path{position(rig.loop, 12)};
  for (int k = 1; k <= 30; ++k) {
    rig.loop.step();
    rig.frames(1);
    path.push_back(position(rig.loop, 12));
  }
  rig.loop.show_frame(10);
  rig.frames(1);
  EXPECT_EQ(rig.view->trails().front(), std::vector<render::Vec2>(path.begin(), path.begin() + 11));
  EXPECT_FALSE(any_flash(*rig.view)) << "a jump";
  ASSERT_TRUE(rig.loop.step_back());
  rig.frames(1);
  EXPECT_EQ(rig.view->trails().front(), std::vector<render::Vec2>(path.begin(), path.begin() + 10));
}

// The camera is the view's to fit: a new scene is fitted, a restart (the same scene) keeps where
// the user looked.
TEST(GlViewFollow, ANewSceneFitsTheCameraARestartKeepsIt) {
  ViewRig rig(ViewOptions{}, "default.json");
  rig.frames(GlView::kSettleFrames);
  const Eigen::Vector2d looked(3.25, -1.5);
  rig.view->camera().set(looked, 7.0);
  rig.loop.step();
  rig.loop.restart();
  rig.frames(1);
  EXPECT_EQ(rig.view->camera().centre(), looked) << "a restart keeps the camera";
  EXPECT_EQ(rig.view->camera().pixels_per_metre(), 7.0);
  load_scene_file(rig.loop, scene("pile.json"));
  rig.frames(1);
  EXPECT_NE(rig.view->camera().pixels_per_metre(), 7.0) << "another scene is fitted";
}

// (One view at a time: each holds the ImGui context.)
TEST(GlViewFollow, TheCameraOptionWinsOverTheFit) {
  ViewOptions fixed;
  fixed.camera = std::array<double, 3>{1.0, 2.0, 50.0};
  ViewRig pinned(fixed, "default.json");
  EXPECT_EQ(pinned.view->camera().pixels_per_metre(), 50.0) << "--camera over the fit";
  load_scene_file(pinned.loop, scene("pile.json"));
  pinned.frames(1);
  EXPECT_EQ(pinned.view->camera().pixels_per_metre(), 50.0) << "--camera over the fit of a new scene too";
}

}  // namespace
}  // namespace nbscope

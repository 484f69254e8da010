// The input both windows share (ui/window_input, render::CameraFraming): the same wheel and drag
// move the main window's camera and the verify window's alike (the verify window's left drag pans
// too; the main window's drags a body instead), and Home, a focus and the refit behave the same
// for both, each with its own zoom for a focus.
#include <imgui.h>

#include <gtest/gtest.h>

#include "render/camera_framing.hpp"
#include "support/ui_fixture.hpp"
#include "ui/window_input.hpp"

namespace nbscope {
namespace {

// A bare ImGui context whose frames are fed by hand: the mouse at `pos`, the buttons, the wheel.
class FakeMouse {
 public:
  FakeMouse() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini left in the working directory
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    io.DisplaySize = ImVec2(800, 600);
    io.DeltaTime = 1.0f / 60.0f;
  }
  ~FakeMouse() {
    if (started_) ImGui::EndFrame();
    ImGui::DestroyContext();
  }
  FakeMouse(const FakeMouse&) = delete;
  FakeMouse& operator=(const FakeMouse&) = delete;

  // One frame with the mouse at (x, y), `button` down (-1: none) and `wheel` notches.
  void frame(float x, float y, int button = -1, float wheel = 0) {
    if (started_) ImGui::EndFrame();  // the previous frame
    started_ = true;
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(x, y);
    for (int b = 0; b < 5; ++b) io.MouseDown[b] = b == button;
    io.MouseWheel = wheel;
    ImGui::NewFrame();
  }

 private:
  bool started_ = false;
};

render::Camera camera_at(double x, double y, double ppm) {
  render::Camera c;
  c.set_viewport(800, 600);
  c.set({x, y}, ppm);
  return c;
}

TEST(WindowInput, TheSameWheelAndRightDragMoveBothWindowsCamerasAlike) {
  FakeMouse mouse;
  render::Camera main_window = camera_at(1, 2, 40), verify_window = camera_at(1, 2, 40);
  mouse.frame(300, 200);
  mouse.frame(310, 195, 1, 1.0f);  // right button down, moved (10, -5), one notch in
  ASSERT_EQ(ui::mouse_over_scene(), Eigen::Vector2d(310, 195));
  ui::move_camera_by_mouse(main_window, {310, 195}, false);
  ui::move_camera_by_mouse(verify_window, {310, 195}, true);
  render::Camera expected = camera_at(1, 2, 40);
  expected.zoom_at({310, 195}, 1.2);
  expected.pan_pixels({10, -5});
  for (const render::Camera* c : {&main_window, &verify_window}) {
    EXPECT_EQ(c->centre(), expected.centre());
    EXPECT_EQ(c->pixels_per_metre(), expected.pixels_per_metre());
  }
}

TEST(WindowInput, ALeftDragPansTheVerifyWindowOnlyPastTheClickSlop) {
  FakeMouse mouse;
  render::Camera main_window = camera_at(0, 0, 20), verify_window = camera_at(0, 0, 20);
  mouse.frame(100, 100);
  mouse.frame(102, 100, 0);  // 2 px: still a click
  ui::move_camera_by_mouse(main_window, {102, 100}, false);
  ui::move_camera_by_mouse(verify_window, {102, 100}, true);
  EXPECT_EQ(verify_window.centre(), main_window.centre());
  mouse.frame(120, 100, 0);  // 20 px: a drag
  ui::move_camera_by_mouse(main_window, {120, 100}, false);
  ui::move_camera_by_mouse(verify_window, {120, 100}, true);
  EXPECT_EQ(main_window.centre(), Eigen::Vector2d(0, 0)) << "the main window's left drag moves a body, not the view";
  EXPECT_DOUBLE_EQ(verify_window.centre().x(), -18.0 / 20.0);
}

TEST(CameraFraming, AFocusHoldsWhileThePanelsMoveAndEndsWhenTheUserMovesTheCamera) {
  render::Camera camera = camera_at(0, 0, 20);
  render::CameraFraming framing(0, render::FocusZoom{4, 1.5});
  framing.set_home_box({{-10, -10}, {10, 10}});
  framing.go_home(camera, {});
  framing.focus(camera, {3, 4}, 1.0, {});
  // The subject is zoomed to a quarter of the free view's shorter side (600 px), centred.
  EXPECT_DOUBLE_EQ(camera.pixels_per_metre(), 150.0);
  EXPECT_EQ(camera.to_screen({3, 4}), Eigen::Vector2d(400, 300));
  // A panel opens on the left: the focus follows into the space left free.
  framing.settle(camera, render::ScreenInsets{200, 0, 0, 0});
  EXPECT_NEAR(camera.to_screen({3, 4}).x(), 500, 1e-9);
  EXPECT_NEAR(camera.to_screen({3, 4}).y(), 300, 1e-9);
  // The user pans: the camera is theirs, settle no longer moves it, nor refits (not at Home).
  camera.pan_pixels({30, 0});
  const Eigen::Vector2d moved = camera.centre();
  framing.settle(camera, {});
  framing.settle(camera, render::ScreenInsets{0, 300, 0, 0});
  EXPECT_EQ(camera.centre(), moved);
}

TEST(CameraFraming, AtHomeTheCameraRefitsToThePanelsAndAFixedViewIsHomeUntilABoxReplacesIt) {
  render::Camera camera = camera_at(0, 0, 20);
  render::CameraFraming framing(44);  // the main window's legend below a fitted box
  framing.set_home_box({{0, 0}, {10, 10}});
  framing.go_home(camera, {});
  render::Camera fitted = camera_at(0, 0, 20);
  fitted.fit({{0, 0}, {10, 10}}, 0.06, render::ScreenInsets{0, 0, 0, 44});
  EXPECT_EQ(camera.centre(), fitted.centre());
  EXPECT_EQ(camera.pixels_per_metre(), fitted.pixels_per_metre());
  framing.settle(camera, render::ScreenInsets{0, 250, 0, 0});  // a column of panels on the right
  fitted.fit({{0, 0}, {10, 10}}, 0.06, render::ScreenInsets{0, 250, 0, 44});
  EXPECT_EQ(camera.centre(), fitted.centre());
  // --camera: its view is Home (no legend room), until Home is asked for on the scene's box.
  framing.set_home_view({5, 5, 30});
  framing.go_home(camera, {});
  EXPECT_EQ(camera.centre(), Eigen::Vector2d(5, 5));
  EXPECT_EQ(camera.pixels_per_metre(), 30);
  framing.set_home_box({{0, 0}, {10, 10}});
  framing.go_home(camera, {});
  EXPECT_NE(camera.pixels_per_metre(), 30);
}

// Key taps shorter than a frame (press and release between two frames: at 9 FPS, most taps) reach
// the panels: each change of a key is given to ImGui on a frame of its own, in order.
using Event = render::InputEvent;
constexpr Event tap_down(int key) { return Event{Event::Kind::Key, Event::Action::Press, key}; }
constexpr Event tap_up(int key) { return Event{Event::Kind::Key, Event::Action::Release, key}; }
constexpr int kLeftShift = 340;  // GLFW_KEY_LEFT_SHIFT

TEST(InputReplay, ATapWithinOneFrameIsSeenAndTwoAreSeenTwice) {
  ui::testui::ImGuiScope scope;
  ui::UiHost host;
  ui::testui::BookFrame f;
  ImGui::GetIO().MousePos = ImVec2(640, 360);
  ui::InputReplay input;
  const auto frame = [&] {
    input.apply();
    ui::testui::run_frame(host, f);
    return f.requests.toggle_pause;
  };
  frame();
  const Event one_tap[] = {tap_down('P'), tap_up('P')};
  input.add(one_tap);
  EXPECT_TRUE(frame()) << "P pressed and released before the frame: the tap is lost";
  EXPECT_FALSE(frame()) << "released on the next frame";
  EXPECT_FALSE(input.pending());
  // Two taps between two frames: two toggles, on frames of their own.
  const Event two_taps[] = {tap_down('P'), tap_up('P'), Event{Event::Kind::Key, Event::Action::Repeat, 'P'}, tap_down('P'), tap_up('P')};
  input.add(two_taps);
  int toggles = 0;
  for (int k = 0; k < 6; ++k) toggles += frame() ? 1 : 0;
  EXPECT_EQ(toggles, 2);
  EXPECT_FALSE(input.pending());
}

TEST(InputReplay, KeepsTheOrderOfAModifierAndAKey) {
  ui::testui::ImGuiScope scope;
  ui::UiHost host;
  ui::testui::BookFrame f;
  std::vector<Violation> log{Violation{0, Invariant::AEqualsR, Pair{0, 1}, {}, {}, "x"},
                             Violation{0, Invariant::AEqualsR, Pair{2, 3}, {}, {}, "x"}};
  f.sim.violations = &log;
  f.sim.violations_total = 2;
  f.state.current_violation = 1;
  ui::InputReplay input;
  input.apply();
  ui::testui::run_frame(host, f);
  // Shift+[ (the first violation) typed within one frame: Shift is still down when [ goes down.
  const Event shift_bracket[] = {tap_down(kLeftShift), tap_down('['), tap_up('['), tap_up(kLeftShift)};
  input.add(shift_bracket);
  input.apply();
  ui::testui::run_frame(host, f);
  EXPECT_EQ(f.requests.go_to_violation, 0u) << "Shift+[ goes to the first";
  input.apply();
  ui::testui::run_frame(host, f);
  EXPECT_FALSE(ImGui::GetIO().KeyShift);
  // A mouse button's click within one frame is down for a frame too.
  const Event click[] = {Event{Event::Kind::MouseButton, Event::Action::Press, 0}, Event{Event::Kind::MouseButton, Event::Action::Release, 0}};
  input.add(click);
  input.apply();
  EXPECT_TRUE(ImGui::GetIO().MouseDown[0]);
  input.apply();
  EXPECT_FALSE(ImGui::GetIO().MouseDown[0]);
}

}  // namespace
}  // namespace nbscope

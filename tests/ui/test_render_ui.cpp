// The panels' host without GL: keys and mouse reach the right requests and view changes (input is
// fed to ImGui as the GLFW backend would), panels can be added, and the settings file round-trips
// and survives being malformed.
#include <gtest/gtest.h>
#include <imgui.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/cells.hpp"
#include "support/ui_fixture.hpp"
#include "render/overlays.hpp"
#include "ui/host.hpp"
#include "ui/settings.hpp"

namespace nbscope::ui {
namespace {

using ImGuiContextScope = testui::ImGuiScope;

// Three elements in a 3x1 grid of 2 m cells, a camera of 20 px/m centred on them.
struct World {
  Elements elements = make_elements_2d((Eigen::ArrayXd(3) << 1, 3, 5).finished(), (Eigen::ArrayXd(3) << 1, 1, 1).finished(),
                                       (Eigen::ArrayXd(3) << 0.9, 0.9, 0.5).finished());
  FrameResult result;
  Grid& grid = result.lanes.front().grid;
  SimView sim;
  UiState state;
  UiRequests requests;
  render::Camera camera;
  World() {
    grid.cell_size = 2;
    grid.inv_cell_size = 0.5;
    grid.n[0] = 3;
    grid.n[1] = 1;
    sim.elements = &elements;
    sim.frame = &result;
    sim.algorithms = {"brute", "nbs", "screen"};
    sim.algorithm = "nbs";
    camera.set_viewport(1280, 720);
    camera.set({3, 1}, 20.0);
  }
};

// Runs one UI frame with the given input already set in ImGuiIO.
UiRequests run_frame(UiHost& host, World& w) {
  w.requests = {};
  ImGui::NewFrame();
  UiContext ctx{w.sim, w.state, w.requests, w.camera};
  host.frame(ctx, true);
  ImGui::Render();
  return w.requests;
}

void release_all() {
  ImGuiIO& io = ImGui::GetIO();
  for (bool& k : io.KeysDown) k = false;
  for (bool& b : io.MouseDown) b = false;
  io.MouseWheel = 0;
}

TEST(UiHost, KeysTogglePauseStepRestartOverlaysAndAlgorithms) {
  ImGuiContextScope scope;
  UiHost host;
  World w;
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(640, 600);  // over the scene, away from the panels
  run_frame(host, w);
  run_frame(host, w);

  const bool grid_before = w.state.overlays.grid;
  io.KeysDown['P'] = io.KeysDown['G'] = io.KeysDown['3'] = true;
  UiRequests r = run_frame(host, w);
  EXPECT_TRUE(r.toggle_pause);
  EXPECT_EQ(w.state.overlays.grid, !grid_before);
  EXPECT_EQ(r.algorithm, std::optional<std::string>("screen"));
  release_all();
  run_frame(host, w);
  io.KeysDown['O'] = io.KeysDown['R'] = true;
  r = run_frame(host, w);
  EXPECT_TRUE(r.step_once);
  EXPECT_TRUE(r.restart);
  EXPECT_FALSE(r.toggle_pause);
  release_all();
  run_frame(host, w);
  // Held keys do not toggle again.
  io.KeysDown['G'] = true;
  run_frame(host, w);
  run_frame(host, w);
  EXPECT_EQ(w.state.overlays.grid, grid_before);
  release_all();
}

TEST(UiHost, MouseZoomsAboutTheCursorPansSelectsAndDrags) {
  ImGuiContextScope scope;
  UiHost host;
  World w;
  ImGuiIO& io = ImGui::GetIO();
  run_frame(host, w);
  // The wheel zooms keeping the world point under the cursor.
  const ImVec2 cursor(660, 350);  // world (4, 1.5): inside cell (2, 0)
  io.MousePos = cursor;
  run_frame(host, w);
  const Eigen::Vector2d under = w.camera.to_world({cursor.x, cursor.y});
  io.MouseWheel = 2;
  run_frame(host, w);
  io.MouseWheel = 0;
  EXPECT_NEAR(w.camera.pixels_per_metre(), 20.0 * 1.44, 1e-9);
  EXPECT_TRUE(w.camera.to_world({cursor.x, cursor.y}).isApprox(under, 1e-9));
  // Hovering names the cell under the cursor.
  ASSERT_TRUE(w.state.hovered_cell.has_value());
  EXPECT_EQ(*w.state.hovered_cell, cell_at(w.grid, under));

  // Right-drag pans: the world follows the mouse.
  io.MouseDown[1] = true;
  run_frame(host, w);
  const Eigen::Vector2d grabbed = w.camera.to_world({cursor.x, cursor.y});
  io.MousePos = ImVec2(cursor.x + 30, cursor.y - 12);
  run_frame(host, w);
  EXPECT_TRUE(w.camera.to_world({cursor.x + 30, cursor.y - 12}).isApprox(grabbed, 1e-9));
  release_all();
  run_frame(host, w);

  // A left click on element 2 selects it and starts a drag; moving drags; releasing ends it.
  // (ImGui floors the mouse position to whole pixels.)
  const Eigen::Vector2d on_two = w.camera.to_screen({5.1, 1.0}).array().floor();
  const Eigen::Vector2d at_two = w.camera.to_world(on_two);
  io.MousePos = ImVec2(static_cast<float>(on_two.x()), static_cast<float>(on_two.y()));
  run_frame(host, w);
  io.MouseDown[0] = true;
  UiRequests r = run_frame(host, w);
  EXPECT_EQ(w.state.selected, 2);
  ASSERT_TRUE(r.drag_begin.has_value());
  EXPECT_TRUE(r.drag_begin->isApprox(at_two, 1e-9)) << r.drag_begin->transpose() << " vs " << at_two.transpose();
  io.MousePos.x += 40;
  r = run_frame(host, w);
  ASSERT_TRUE(r.drag_to.has_value());
  EXPECT_NEAR(r.drag_to->x(), at_two.x() + 40 / w.camera.pixels_per_metre(), 1e-9);
  io.MouseDown[0] = false;
  r = run_frame(host, w);
  EXPECT_TRUE(r.drag_end);
  // A click on empty space clears the selection.
  io.MousePos = ImVec2(640, 700);
  run_frame(host, w);
  io.MouseDown[0] = true;
  r = run_frame(host, w);
  EXPECT_EQ(w.state.selected, -1);
  EXPECT_FALSE(r.drag_begin.has_value());
  release_all();
}

// A panel added by another part (the stepper does this) gets drawn and offered the keys first.
struct CountingPanel final : Panel {
  int draws = 0, keys = 0;
  [[nodiscard]] const char* title() const override { return "Counting"; }
  void draw(UiContext&) override { ++draws; }
  bool handle_keys(UiContext&) override {
    ++keys;
    return ImGui::IsKeyPressed('P', false);  // takes P for itself
  }
};

TEST(UiHost, AddedPanelsAreDrawnAndTakeKeysFirst) {
  ImGuiContextScope scope;
  UiHost host;
  auto panel = std::make_unique<CountingPanel>();
  CountingPanel* p = panel.get();
  host.add_panel(std::move(panel));
  World w;
  ImGui::GetIO().MousePos = ImVec2(640, 600);
  run_frame(host, w);
  ImGui::GetIO().KeysDown['P'] = true;
  const UiRequests r = run_frame(host, w);
  EXPECT_FALSE(r.toggle_pause);  // the panel took it
  EXPECT_EQ(p->draws, 2);
  EXPECT_EQ(p->keys, 2);
  // Closed panels are neither drawn nor asked.
  w.state.panel_open["Counting"] = false;
  release_all();
  run_frame(host, w);
  EXPECT_EQ(p->draws, 2);
}

TEST(Settings, RoundTripAndMalformedFilesFallBackToDefaults) {
  const std::string dir = std::string(NBSCOPE_TEST_OUT) + "/render_ui_settings";
  std::filesystem::remove_all(dir);
  const std::string path = dir + "/nbscope/settings.json";
  Settings s;
  s.overlays.lists = true;
  s.overlays.grid = false;
  s.panels["Metrics"] = true;
  s.last_scene = "/some/scene.json";
  s.algorithm = "screen";
  s.camera = std::array<double, 3>{1.5, -2.0, 33.0};
  s.speed = 2.5;
  save_settings(path, s);  // creates the directory
  std::vector<std::string> ignored;
  const Settings back = load_settings(path, ignored);
  EXPECT_TRUE(ignored.empty()) << ignored.front();
  EXPECT_TRUE(back.overlays.lists);
  EXPECT_FALSE(back.overlays.grid);
  EXPECT_EQ(back.panels.at("Metrics"), true);
  EXPECT_EQ(back.last_scene, s.last_scene);
  EXPECT_EQ(back.algorithm, s.algorithm);
  EXPECT_EQ(back.camera, s.camera);
  EXPECT_DOUBLE_EQ(back.speed, 2.5);

  std::ofstream(path) << "{ not json";
  const Settings bad = load_settings(path, ignored);
  ASSERT_EQ(ignored.size(), 1u);
  EXPECT_EQ(ignored[0].rfind("the whole file (not JSON: ", 0), 0u) << ignored[0];
  EXPECT_EQ(bad.overlays.grid, render::OverlayFlags{}.grid);
  EXPECT_FALSE(bad.last_scene.has_value());

  EXPECT_TRUE(load_settings(dir + "/missing.json", ignored).panels.empty());
  EXPECT_TRUE(ignored.empty());
}

// A camera left where the fit put it is not frozen into the settings: the next start fits the
// scene again (and keeps refitting as panels open) instead of showing the last run's view until
// Home. A camera the user panned or zoomed comes back as it was.
TEST(Settings, AFittedCameraIsFittedAgainAndAMovedOneRestored) {
  const render::WorldRect box{{0, 0}, {10, 10}};
  render::Camera last;
  last.set_viewport(1280, 720);
  last.fit(box, 0.06, render::ScreenInsets{270, 300, 25, 120});  // the panels of the last run
  Settings s;
  s.last_scene = "/some/scene.json";
  s.camera = camera_to_save(last);
  EXPECT_FALSE(s.camera.has_value());
  render::Camera next;
  next.set_viewport(1280, 720);
  next.fit(box, 0.06, render::ScreenInsets{270, 300, 0, 0});  // the start's fit, before the panels' first frame
  EXPECT_FALSE(restore_camera(s, "/some/scene.json", next));
  EXPECT_TRUE(next.at_home()) << "still fitted: the first frame refits it into the panels' space";

  last.pan_pixels({40, -10});
  s.camera = camera_to_save(last);
  ASSERT_TRUE(s.camera.has_value());
  EXPECT_FALSE(restore_camera(s, "/another/scene.json", next));
  EXPECT_TRUE(restore_camera(s, "/some/scene.json", next));
  EXPECT_EQ(next.centre(), last.centre());
  EXPECT_EQ(next.pixels_per_metre(), last.pixels_per_metre());
}

TEST(Settings, PathFollowsXdgConfigHomeThenHome) {
  const char* old_xdg = std::getenv("XDG_CONFIG_HOME");
  const std::string keep_xdg = old_xdg != nullptr ? old_xdg : "";
  setenv("XDG_CONFIG_HOME", "/cfg", 1);
  EXPECT_EQ(settings_path(), "/cfg/nbscope/settings.json");
  unsetenv("XDG_CONFIG_HOME");
  setenv("HOME", "/home/someone", 1);
  EXPECT_EQ(settings_path(), "/home/someone/.config/nbscope/settings.json");
  if (!keep_xdg.empty()) setenv("XDG_CONFIG_HOME", keep_xdg.c_str(), 1);
}

}  // namespace
}  // namespace nbscope::ui

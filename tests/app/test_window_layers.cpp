// The window's view of a 3D frame, one layer at a time (app/gl_view_layer.cpp), under OSMesa: the
// layer chosen (auto: the focus pair's, the selected element's, the busiest; the user's clamped into
// the frame; the stepper's while it is mid-way), going to a violation of a 3D frame (its layer, the
// stepper at its operation), and through the binary: 3D frames open and render (they were refused),
// gui --input on ELEMENTS.csv, and --layer's bad values (one line, exit 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "app/gl_view.hpp"
#include "support/window_rig.hpp"
#include "app/gui_requests.hpp"
#include "core/layers.hpp"
#include "render/gl_context.hpp"
#include "support/run_cli.hpp"
#include "support/x_display.hpp"
#include "ui/panels.hpp"
#include "ui/stepper_panels.hpp"

namespace nbscope {
namespace {

struct LayerRig : testapp::RecordingWindowRig {
  using RecordingWindowRig::RecordingWindowRig;
  // Each element's layer as NBS integerises z on the frame's grid.
  [[nodiscard]] std::int32_t layer_of(ElementId k) const {
    return loop.result().selected().grid.cell(loop.source().elements().z[k], 2);
  }
};

TEST(WindowLayers, AThreeDFrameIsShownOneLayerAtATimeTheBusiestFirst) {
  LayerRig rig(testapp::scattered_spheres(400, 1));
  rig.frames(1);
  const LayerSlice* s = rig.view->layer();
  ASSERT_NE(s, nullptr) << "a 3D frame is sliced";
  EXPECT_EQ(s->count, rig.loop.result().selected().grid.n[2]);
  EXPECT_GT(s->count, 2);
  // Nothing chosen: the layer with the most elements.
  std::vector<std::int64_t> per(static_cast<std::size_t>(s->count), 0);
  for (ElementId k = 0; k < rig.loop.source().elements().size(); ++k) ++per[static_cast<std::size_t>(rig.layer_of(k))];
  EXPECT_EQ(s->layer, static_cast<std::int32_t>(std::max_element(per.begin(), per.end()) - per.begin()));
}

TEST(WindowLayers, OnlyTheLayerShownAndTheOneBelowReachTheRenderer) {
  LayerRig rig(testapp::scattered_spheres(400, 8));
  rig.view->state().layer = 2;
  rig.frames(1);
  const LayerSlice& s = *rig.view->layer();
  ASSERT_EQ(s.layer, 2);
  std::size_t expected = 0;
  for (ElementId k = 0; k < rig.loop.source().elements().size(); ++k) expected += rig.layer_of(k) == 1 || rig.layer_of(k) == 2;
  EXPECT_EQ(rig.view->shapes().size(), expected);
  for (const render::ShapeDraw& d : rig.view->shapes()) {
    EXPECT_TRUE(rig.layer_of(d.element) == 1 || rig.layer_of(d.element) == 2) << "element " << d.element;
    EXPECT_FALSE(d.spoke) << "a sphere seen from above has no rotation to show";
  }
}

TEST(WindowLayers, AutoIsTheFocusPairsLayerElseTheSelectedElements) {
  LayerRig rig(testapp::scattered_spheres(400, 2));
  rig.frames(1);
  // A pair across two layers: shown in the pass of the upper one (the mask reaches down).
  std::optional<Pair> across;
  for (const Pair& p : rig.loop.result().selected().pairs)
    if (rig.layer_of(p.i) != rig.layer_of(p.j) && std::max(rig.layer_of(p.i), rig.layer_of(p.j)) != rig.view->layer()->layer) {
      across = p;
      break;
    }
  ASSERT_TRUE(across.has_value()) << "the frame has pairs between layers";
  rig.view->state().selected = across->i;
  rig.view->state().selected_pair = *across;
  rig.frames(1);
  EXPECT_EQ(rig.view->layer()->layer, std::max(rig.layer_of(across->i), rig.layer_of(across->j)));
  // The element alone: its own layer.
  rig.view->state().selected_pair.reset();
  rig.view->state().selected = across->i;
  rig.frames(1);
  EXPECT_EQ(rig.view->layer()->layer, rig.layer_of(across->i));
}

TEST(WindowLayers, TheUsersLayerIsClampedIntoTheFrame) {
  LayerRig rig(testapp::scattered_spheres(300, 3));
  rig.frames(1);
  const std::int32_t top = rig.view->layer()->count - 1;
  rig.view->state().layer = top + 50;
  rig.frames(1);
  EXPECT_EQ(rig.view->layer()->layer, top);
  EXPECT_EQ(rig.view->state().layer, top) << "Up/Down move from the layer shown";
  rig.view->state().layer = -3;
  rig.frames(1);
  EXPECT_EQ(rig.view->layer()->layer, 0);
  rig.view->state().layer = 1;
  rig.frames(1);
  EXPECT_EQ(rig.view->layer()->layer, 1);
}

// Going to a violation of a 3D frame shows the layer whose pass decides the pair, over the layer the
// user was on, and the stepper (opened) goes to the operation: the layer is then the stepper's.
void expect_violation_layer(Fault fault) {
  FrameLoopOptions faulty;
  faulty.fault = fault;
  LayerRig rig(testapp::scattered_spheres(400, 4), ViewOptions{}, faulty);
  rig.frames(1);
  const auto& listed = rig.loop.history().violation_log().listed();
  ASSERT_FALSE(listed.empty()) << fault_name(fault) << " breaks the 3D frame";
  // The last violation, so that it is not in the busiest layer by chance alone.
  std::size_t chosen = listed.size() - 1;
  const Pair pair = listed[chosen].pair;
  const std::int32_t want = pair_layer(rig.loop.result().selected().grid, rig.layer_of(pair.i), rig.layer_of(pair.j));
  rig.view->state().layer = want == 0 ? 1 : 0;  // the user elsewhere
  rig.frames(1);
  ui::UiRequests choose;
  choose.go_to_violation = chosen;
  apply_requests(choose, rig.loop, *rig.view, rig.session);
  rig.frames(1);
  EXPECT_EQ(rig.view->layer()->layer, want) << fault_name(fault) << ": the pair's layer (auto), over the user's";
  rig.view->state().panel_open[ui::kStepperTitle] = true;
  rig.frames(3);
  const ui::StepperSession& s = rig.view->stepper();
  ASSERT_TRUE(s.has_capture()) << s.message();
  ASSERT_TRUE(s.target_location() && s.target_location()->event) << s.target_status();
  EXPECT_EQ(s.stepper().position(), *s.target_location()->event + 1) << "the stepper at the operation that decided the pair";
  EXPECT_EQ(rig.view->layer()->layer, want) << fault_name(fault) << ": the stepper's layer at " << s.target_status();
}

TEST(WindowLayers, GoingToADroppedPairOfAThreeDFrameShowsItsLayerAndOperation) { expect_violation_layer(Fault::DropPair); }

TEST(WindowLayers, GoingToADroppedMaskCellOfAThreeDFrameShowsItsLayerAndOperation) { expect_violation_layer(Fault::DropMaskCell); }

TEST(WindowLayers, MidWayTheLayerIsTheStepperTestedPairsUpperLayer) {
  ViewOptions o;
  o.step = 1;
  LayerRig rig(testapp::scattered_spheres(300, 5), o);
  rig.frames(2);
  ui::StepperSession& s = rig.view->stepper();
  ASSERT_TRUE(s.has_capture()) << s.message();
  // Every test between two layers (a sample of them): the view is on the upper one, whatever the user chose.
  rig.view->state().layer = 0;
  const auto& events = s.stepper().events();
  int seen = 0;
  for (std::size_t i = 0; i < events.size() && seen < 8; ++i) {
    const TraceEvent& ev = events[i];
    if (ev.op != TraceOp::TestPair || rig.layer_of(ev.element) == rig.layer_of(ev.other)) continue;
    s.stepper().seek(i + 1);
    rig.frames(1);
    EXPECT_EQ(rig.view->layer()->layer, std::max(rig.layer_of(ev.element), rig.layer_of(ev.other))) << "operation " << i;
    ++seen;
  }
  EXPECT_GT(seen, 0) << "the trace tests pairs between layers";
  // At the end of the trace the user's layer again.
  s.stepper().seek(events.size());
  rig.frames(1);
  EXPECT_EQ(rig.view->layer()->layer, 0);
}

// The lists the scene draws are the Stepper's arrays at every operation of a 3D trace: each list
// whose head is set, walked through its next array in the stepper's state, is the scene's latest
// list of that head (nbs, screen, tree in 3D; a sample of operations through the frame).
void expect_lists_follow_the_arrays(const char* algorithm) {
  ViewOptions o;
  o.overlays = "+lists";
  o.lists = "all";
  o.step = 1;
  FrameLoopOptions lo;
  lo.algorithm = algorithm;
  LayerRig rig(testapp::scattered_spheres(80, 7), o, lo);
  rig.frames(2);
  ui::StepperSession& s = rig.view->stepper();
  ASSERT_TRUE(s.has_capture()) << algorithm << ": " << s.message();
  const auto& arrays = s.stepper().trace().arrays();
  const auto array_named = [&](const std::string& name) {
    for (std::size_t a = 0; a < arrays.size(); ++a)
      if (arrays[a].name == name) return static_cast<int>(a);
    return -1;
  };
  const std::size_t n = s.stepper().size();
  int compared = 0;
  for (std::size_t p = 1; p <= n; p += std::max<std::size_t>(1, n / 37)) {
    s.stepper().seek(p);
    rig.frames(1);
    const ArrayState& state = s.stepper().state();
    const std::vector<TracedList>& lists = rig.view->lists();
    for (std::size_t i = 0; i < lists.size(); ++i) {
      const TracedList& l = lists[i];
      const int next = array_named(l.next_name);
      if (next < 0 || l.heads_array < 0) continue;  // (sort's runs: no next array)
      const std::int32_t head = state[static_cast<std::size_t>(l.heads_array)][static_cast<std::size_t>(l.slot)];
      if (head < 0) continue;
      std::vector<ElementId> walked;
      for (std::int32_t k = head; k >= 0 && walked.size() <= 80; k = state[static_cast<std::size_t>(next)][static_cast<std::size_t>(k)])
        walked.push_back(k);
      // Lists of this head cleared earlier are kept as they were (drawn in their own pass): one of
      // the scene's lists of the head is the arrays' list now.
      bool found = false;
      for (const TracedList& t : lists) found = found || (t.heads_array == l.heads_array && t.slot == l.slot && t.chain == walked);
      EXPECT_TRUE(found) << algorithm << " at operation " << p << ": " << l.heads_name << "[" << l.slot << "] holds " << walked.size()
                         << " elements from " << head;
      ++compared;
    }
  }
  EXPECT_GT(compared, 20) << algorithm;
}

TEST(WindowLayers, TheScenesListsAreTheStepperArraysInNbs3d) { expect_lists_follow_the_arrays("nbs"); }
TEST(WindowLayers, TheScenesListsAreTheStepperArraysInScreen3d) { expect_lists_follow_the_arrays("screen"); }
TEST(WindowLayers, TheScenesListsAreTheStepperArraysInTree3d) { expect_lists_follow_the_arrays("tree"); }

TEST(WindowLayers, ATwoDFrameHasNoLayer) {
  Recording rec = testapp::scattered_spheres(50, 6);
  Elements flat;
  for (ElementId k = 0; k < rec.frames[0].elements.size(); ++k)
    flat.push_back(rec.frames[0].elements.x[k], rec.frames[0].elements.y[k], 0, 0.4);
  rec.frames[0].elements = flat;
  LayerRig rig(std::move(rec));
  rig.frames(1);
  EXPECT_EQ(rig.view->layer(), nullptr);
}

// ---- through the binary ----

const std::string kPour = std::string("--dump '") + NBSCOPE_SOURCE_DIR + "/assets/examples/pour3d/atoms.*.dump'";

TEST(WindowLayersCli, AThreeDReplayRendersAScreenshot) {
  const std::string dir = testcli::scratch_dir("WindowLayersCli.AThreeDReplayRendersAScreenshot");
  const auto r = testcli::run("replay --headless " + kPour + " --screenshot " + dir + "/pour.png --layer 2 --size 640x360");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/pour.png")) << r.err;
}

TEST(WindowLayersCli, AThreeDReplayStopsAtAViolationAndDrawsIt) {
  const std::string dir = testcli::scratch_dir("WindowLayersCli.AThreeDReplayStopsAtAViolationAndDrawsIt");
  const auto r = testcli::run("replay --headless " + kPour + " --inject-fault drop-mask-cell --stop-at-violation --layer auto --screenshot " +
                              dir + "/v.png --size 640x360");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.out.find("stopped at the first violation"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir + "/v.png")) << r.err;
}

TEST(WindowLayersCli, GuiInputOpensAThreeDCsvFrame) {
  const std::string dir = testcli::scratch_dir("WindowLayersCli.GuiInputOpensAThreeDCsvFrame");
  testcli::write_text(dir + "/e.csv", "x,y,z,r\n0,0,0,0.5\n0.8,0,0,0.5\n0,0,2.1,0.5\n0.3,0.2,1.4,0.5\n");
  // Without a display: rendered headless (the window itself: on the test's own Xvfb, below).
  const auto r = testcli::run("gui --input " + dir + "/e.csv --frames 3 --screenshot " + dir + "/e.png --size 640x360");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/e.png")) << r.err;
  NBSCOPE_SKIP_WITHOUT_XVFB();
  const auto w = testcli::run("gui --input " + dir + "/e.csv --frames 3 --screenshot " + dir + "/w.png --size 640x360 --layer 1",
                              testcli::on_display());
  EXPECT_EQ(w.exit_code, 0) << w.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/w.png")) << w.err;
  EXPECT_NE(w.err.find(" FPS; ms a simulated frame"), std::string::npos) << "--frames N redraws a one-frame input: " << w.err;
}

// One line, exit 2.
void expect_refused(const std::string& args, const std::string& what) {
  const auto r = testcli::run(args);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
  EXPECT_EQ(r.err, "nbscope: error: " + what + "\n") << args;
}

TEST(WindowLayersCli, BadLayersAreOneLine) {
  const std::string dir = testcli::scratch_dir("WindowLayersCli.BadLayersAreOneLine");
  const std::string shot = " --screenshot " + dir + "/x.png";
  expect_refused("replay --headless " + kPour + shot + " --layer 12", "--layer: 12 is past the top layer 5 (the frame has 6 layers)");
  expect_refused("replay --headless " + kPour + shot + " --layer two", "--layer: 'two' is not a layer number (0 is the bottom layer) or auto");
  expect_refused("replay --headless " + kPour + shot + " --layer -1", "--layer: '-1' is not a layer number (0 is the bottom layer) or auto");
  expect_refused("headless --scene " + std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/default.json --frames 2" + shot + " --layer 1",
                 "--layer: the frame is 2D (layers are those of a 3D frame's grid)");
  expect_refused("replay --headless " + kPour + " --layer 1", "--layer: needs --screenshot (headless draws nothing without one)");
  const std::string nine = std::string(NBSCOPE_SOURCE_DIR) + "/assets/examples/nine.csv";
  const std::string bug = std::string(NBSCOPE_SOURCE_DIR) + "/assets/examples/nine_screen_bug.json";
  expect_refused("verify --input " + nine + " --arrays " + bug + shot + " --layer 0", "--layer: the elements are 2D (layers are those of a 3D grid)");
  expect_refused("gui --input " + nine + " --arrays " + bug + " --frames 1" + shot + " --layer 0",
                 "--layer: the elements are 2D (layers are those of a 3D grid)");
  expect_refused("gui --input " + std::string(NBSCOPE_SOURCE_DIR) + "/assets/examples/pour3d/atoms.7500.dump --contact-ids 1,2",
                 "--contact-ids: gui --input reads no contacts (replay --dump FILES --contacts FILES reads a dump's contacts)");
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.png"));
}

}  // namespace
}  // namespace nbscope

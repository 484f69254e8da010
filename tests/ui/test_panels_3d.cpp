// The panels other than Layers on a 3D frame without GL (support/ui3d_fixture.hpp): the Selection
// panel names an element's cell (ix, iy, iz), layer and list places; Arrays and Pseudocode show the
// 3D arrays and loops; a cell seek and a violation's pair work in 3D; the stepper's scene overlay
// leaves out the hidden layers; Stats counts the cells of all three sides.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <random>
#include <string>

#include "core/detector.hpp"
#include "core/layers.hpp"
#include "core/lists.hpp"
#include "core/traced_lists.hpp"
#include "support/ui3d_fixture.hpp"
#include "ui/layer_lists.hpp"
#include "ui/settings_json.hpp"
#include "ui/panels.hpp"
#include "ui/stepper_panels.hpp"

namespace nbscope::ui {
namespace {

using testui::Frame3d;
using testui::panel_text;
using testui::Recorder;
using testui::run_frame;
using testui::Scope3d;

// Selection on a 3D element: its cell (ix, iy, iz), row, layer against the one shown, and its place
// in each list of the frame's lists (the z-list C[iz], the y-list B[0][iy], the x-lists A[r][ix]).
TEST(SelectionPanel, NamesA3dElementsCellLayerAndListPlaces) {
  Scope3d scope;
  UiHost host;
  add_stepper_panels(host);
  Frame3d f;
  f.sim.paused = false;
  const std::vector<TracedList> lists = traced_lists(f.traced().trace->log, static_cast<std::size_t>(f.elements.size()));
  f.sim.lists = &lists;
  // An element of the layer below the one shown, at least second on its z-list.
  const ZLists z = zlists_from_layers(f.slice);
  ASSERT_GE(f.slice.below, 0);
  const auto& chain = z.chains[static_cast<std::size_t>(f.slice.below)];
  ASSERT_GE(chain.size(), 3u);
  const ElementId k = chain[1];
  f.state.selected = k;
  const Grid& g = f.grid();
  const std::int32_t ix = g.cell(f.elements.x[k], 0), iy = g.cell(f.elements.y[k], 1), iz = g.cell(f.elements.z[k], 2);
  ASSERT_EQ(iz, f.slice.below);
  run_frame(host, f);
  const std::string text = panel_text(host, f, "Selection");
  const auto has = [&](const std::string& what) { EXPECT_NE(text.find(what), std::string::npos) << what << "\n" << text; };
  has("cell (ix, iy, iz) = (" + std::to_string(ix) + ", " + std::to_string(iy) + ", " + std::to_string(iz) + ")");
  has("row (iy, iz) = (" + std::to_string(iy) + ", " + std::to_string(iz) + ")");
  has("in layer " + std::to_string(iz) + " (layer shown: " + std::to_string(f.slice.layer) + ")");
  has("z-list C[" + std::to_string(iz) + "]: position 2 of " + std::to_string(chain.size()));
  has("y-list B[0][" + std::to_string(iy) + "]: position");
  has("x-list A[0][" + std::to_string(ix) + "]: position");
  // With the lists overlay off, the frame's trace (paused: the stepper's) gives the same places.
  f.sim.lists = nullptr;
  const std::string from_trace = panel_text(host, f, "Selection");
  EXPECT_NE(from_trace.find("z-list C[" + std::to_string(iz) + "]: position 2 of " + std::to_string(chain.size())), std::string::npos)
      << from_trace;
  // Its own layer shown: "(shown)"; book numbering shifts every index.
  f.slice = slice_layer(f.elements, g, iz);
  f.state.book_numbering = true;
  const std::string book = panel_text(host, f, "Selection");
  EXPECT_NE(book.find("in layer " + std::to_string(iz + 1) + " (shown)"), std::string::npos) << book;
  EXPECT_NE(book.find("cell (ix, iy, iz) = (" + std::to_string(ix + 1) + ", " + std::to_string(iy + 1) + ", " + std::to_string(iz + 1) + ")"),
            std::string::npos) << book;
}

// Arrays and Pseudocode on 3D traces: NBS's C, Z, B, Y, A, X with their shapes and row names, the
// 3D loops with the current line; sort, screen and tree 3D show their own.
TEST(StepperPanels3d, ArraysAndPseudocodeShowThe3dArraysAndLoops) {
  Scope3d scope;
  UiHost host;
  auto session = add_stepper_panels(host, StepperConfig{std::size_t{0}, false});
  Frame3d f;
  open_stepper_panels(f.state);
  run_frame(host, f);
  ASSERT_TRUE(session->has_capture()) << session->message();
  const Grid& g = f.grid();
  const std::string n = std::to_string(f.elements.size());
  EXPECT_EQ(array_shapes_text(*session), "C[nz=" + std::to_string(g.n[2]) + "]  Z[N=" + n + "]  B[2][ny=" + std::to_string(g.n[1]) +
                                             "]  Y[N=" + n + "]  A[5][nx=" + std::to_string(g.n[0]) + "]  X[N=" + n + "]");
  // Mid-way through a row's contacts: the 3D lines, the arrays, the rows of A.
  Stepper& st = session->stepper();
  std::size_t contacts = 0;
  for (std::size_t i = 0; i < st.size() && contacts == 0; ++i)
    if (st.events()[i].op == TraceOp::TestPair) contacts = i + 1;
  ASSERT_GT(contacts, 0u);
  st.seek(contacts);
  const std::string text = panel_text(host, f, kPseudocodeTitle) + panel_text(host, f, kArraysTitle);
  for (const char* what : {"nbs, 3D", "add the discrete element k onto the z_iz list", "Loop over all layers iz", "[1] layer iz-1",
                           "[2] (iy-1,iz-1)", "[4] (iy+1,iz-1)", "iz ="})
    EXPECT_NE(text.find(what), std::string::npos) << what << "\n" << text;
  for (const char* algorithm : {"sort", "screen", "tree"}) {
    f.sim.algorithm = algorithm;
    run_frame(host, f);
    ASSERT_TRUE(session->has_capture()) << algorithm << ": " << session->message();
    session->stepper().seek(session->stepper().size() / 2);
    const std::string other = panel_text(host, f, kPseudocodeTitle);
    EXPECT_NE(other.find(std::string(algorithm) + ", 3D"), std::string::npos) << other;
    EXPECT_TRUE(session->current_layer().has_value() || std::string(algorithm) != "screen") << algorithm;
    if (std::string(algorithm) == "screen") {
      EXPECT_NE(other.find("C[ix][iy][iz]"), std::string::npos) << other;
      EXPECT_EQ(array_shapes_text(*session), "C[nx=" + std::to_string(g.n[0]) + "][ny=" + std::to_string(g.n[1]) + "][nz=" +
                                                  std::to_string(g.n[2]) + "]  E[N=" + n + "]");
    }
  }
}

// The stepper's scene overlay on a layer view draws nothing about an element of a hidden layer.
TEST(StepperScene3d, LeavesOutWhatTheLayerViewHides) {
  Frame3d f;
  StepperSession s;
  s.capture(f.traced());
  ASSERT_TRUE(s.has_capture());
  Stepper& st = s.stepper();
  // A push onto the z-list of an element two layers or more from the one shown.
  std::optional<std::size_t> hidden;
  for (std::size_t i = 0; i < st.size() && !hidden; ++i) {
    const TraceEvent& e = st.events()[i];
    if (e.op == TraceOp::Push && e.element >= 0 && !f.slice.visible(e.element)) hidden = i;
  }
  ASSERT_TRUE(hidden.has_value());
  st.seek(*hidden + 1);
  Recorder flat, layered;
  draw_stepper_scene(s, flat, true);
  draw_stepper_scene(s, layered, true, &f.slice);
  EXPECT_GT(flat.circles.size(), 0u) << "without a layer the element is ringed";
  EXPECT_EQ(layered.circles.size(), 0u);
  EXPECT_TRUE(layered.texts.empty());
}


// Shift+PageDown on a cell clicked in the layer view goes to an operation on that cell of that layer
// (in 3D a cell (ix, iy) alone names none); a violation's pair in a 3D frame is found in the trace.
TEST(StepperPanels3d, ACellSeekAndAViolationsPairWorkIn3d) {
  Scope3d scope;
  UiHost host;
  auto session = add_stepper_panels(host, StepperConfig{std::size_t{0}, false});
  Frame3d f;
  open_stepper_panels(f.state);
  run_frame(host, f);
  ASSERT_TRUE(session->has_capture()) << session->message();
  // A cell of the layer shown that holds an element.
  ElementId k = 0;
  while (k < f.elements.size() && f.slice.place(k) != LayerPlace::Here) ++k;
  ASSERT_LT(k, f.elements.size());
  const Grid& g = f.grid();
  const std::array<std::int32_t, 2> cell{g.cell(f.elements.x[k], 0), g.cell(f.elements.y[k], 1)};
  f.state.selected_cell = cell;
  testui::press(267, true);  // Shift+PageDown
  run_frame(host, f);
  testui::release();
  const TraceEvent* e = session->stepper().current();
  ASSERT_NE(e, nullptr) << session->status;
  EXPECT_EQ(e->cell[0], cell[0]);
  EXPECT_EQ(e->cell[1], cell[1]);
  EXPECT_EQ(e->cell[2], f.slice.layer);

  // A contact the trace found, as if A had lost it: the stepper goes to its test, in its layer's pass.
  ASSERT_FALSE(f.sim.trace->pairs.empty());
  const Pair p = f.sim.trace->pairs.front();
  session->set_target(StepperSession::PairTarget{0, p, Invariant::AEqualsR, "missing from A"});
  run_frame(host, f);
  ASSERT_TRUE(session->target_location().has_value());
  EXPECT_NE(session->target_status().find("tested against"), std::string::npos) << session->target_status();
  const TraceEvent* test = session->stepper().current();
  ASSERT_NE(test, nullptr);
  EXPECT_EQ(test->op, TraceOp::TestPair);
  EXPECT_EQ(session->current_layer(), pair_layer(f.slice, g, p));
}

// Stats counts a 3D grid's cells with all three sides (it once wrote "7 x 7 = 294" for 7 x 7 x 6).
TEST(StatsPanel, ThreeDCellsAreCountedWithTheirLayers) {
  Scope3d scope;
  UiHost host;
  Frame3d f;
  const Grid& g = f.grid();
  ASSERT_GT(g.n[2], 1);
  const std::string text = panel_text(host, f, "Stats");
  const std::string want = "cells " + std::to_string(g.n[0]) + " x " + std::to_string(g.n[1]) + " x " + std::to_string(g.n[2]) +
                           " = " + std::to_string(g.n[0] * g.n[1] * g.n[2]);
  EXPECT_NE(text.find(want), std::string::npos) << text;
}

}  // namespace
}  // namespace nbscope::ui

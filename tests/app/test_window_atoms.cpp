// The window's view of a dump's frames (recorded frames with atom ids, some periodic), under OSMesa:
// the selection, a violation's pair and the trail follow the atom's id across frames whose rows
// shift as atoms are lost or inserted (nothing selected once the atom is gone), the panels get the
// ids and the touching convention, and a periodic frame's screenshot is written for a look
// (NBSCOPE_TEST_OUT/window_periodic.png).
#include <gtest/gtest.h>

#include <filesystem>

#include "app/gl_view.hpp"
#include "support/window_rig.hpp"
#include "core/error.hpp"
#include "io/png.hpp"
#include "render/gl_context.hpp"

namespace nbscope {
namespace {

// One atom a frame: x as given, y 0, radius 0.25.
RecordedFrame dump_frame(std::int64_t number, std::vector<std::int64_t> ids, std::vector<double> xs) {
  RecordedFrame f;
  f.number = number;
  f.time = 0.1 * static_cast<double>(number);
  f.ids = std::move(ids);
  for (const double x : xs) f.elements.push_back(x, 0, 0, 0.25);
  return f;
}

using AtomRig = testapp::RecordingWindowRig;

// Atom 30 moves right by 0.1 a frame; atom 20 is lost in frame 1, atom 5 inserted in frame 2, atom
// 30 gone in frame 3.
Recording atoms_come_and_go() {
  Recording rec;
  rec.path = "atoms.dump";
  rec.frames = {dump_frame(0, {10, 20, 30}, {0, 2, 4.0}), dump_frame(1, {10, 30}, {0, 4.1}),
                dump_frame(2, {5, 10, 30}, {-2, 0, 4.2}), dump_frame(3, {5, 10}, {-2, 0})};
  return rec;
}

TEST(WindowAtoms, TheSelectionFollowsTheAtomIdAcrossFramesWhoseRowsShift) {
  AtomRig rig(atoms_come_and_go());
  rig.frames(1);
  rig.view->state().selected = 2;  // atom 30, clicked on frame 0
  rig.frames(1);
  rig.loop.step();  // atom 20 lost: atom 30 is row 1
  rig.frames(1);
  EXPECT_EQ(rig.view->state().selected, 1);
  rig.loop.step();  // atom 5 inserted: row 2 again
  rig.frames(1);
  EXPECT_EQ(rig.view->state().selected, 2);
  // Its trail is the atom's path over the kept frames (frame 0's too, where it was clicked), not a row's.
  ASSERT_EQ(rig.view->trails().size(), 1u);
  std::vector<float> xs;
  for (const render::Vec2& p : rig.view->trails().front()) xs.push_back(p.x());
  EXPECT_EQ(xs, (std::vector<float>{4.0f, 4.1f, 4.2f}));
  // Back to frame 0 (shown from the history): row 2 again, the trail rebuilt by id.
  rig.loop.show_frame(1);
  rig.frames(1);
  EXPECT_EQ(rig.view->state().selected, 1);
  ASSERT_EQ(rig.view->trails().size(), 1u);
  xs.clear();
  for (const render::Vec2& p : rig.view->trails().front()) xs.push_back(p.x());
  EXPECT_EQ(xs, (std::vector<float>{4.0f, 4.1f}));
  // Atom 30 gone in frame 3: nothing selected.
  rig.loop.show_frame(2);
  rig.loop.step();
  rig.frames(1);
  EXPECT_EQ(rig.view->state().selected, -1);
}

TEST(WindowAtoms, AViolationsPairFollowsItsAtomsAndIsDroppedWhenOneIsGone) {
  AtomRig rig(atoms_come_and_go());
  rig.frames(1);
  rig.view->state().selected = 0;
  rig.view->state().selected_pair = Pair{0, 2};  // atoms 10 and 30
  rig.loop.step();
  rig.frames(1);
  ASSERT_TRUE(rig.view->state().selected_pair.has_value());
  EXPECT_EQ(*rig.view->state().selected_pair, (Pair{0, 1}));
  rig.loop.step();
  rig.frames(1);
  EXPECT_EQ(*rig.view->state().selected_pair, (Pair{1, 2}));
  rig.loop.step();
  rig.frames(1);
  EXPECT_FALSE(rig.view->state().selected_pair.has_value());
  EXPECT_EQ(rig.view->state().selected, 1) << "atom 10 is still there";
}

// --select names an atom id on a dump's frames (what the panels show), and refuses one not there.
TEST(WindowAtoms, SelectNamesAnAtomId) {
  ViewOptions o;
  o.select = 30;
  {
    AtomRig rig(atoms_come_and_go(), o);  // (one view, one ImGui context, at a time)
    EXPECT_NO_THROW(rig.view->check_selection(rig.loop));
    EXPECT_EQ(rig.view->state().selected, 2);
  }
  o.select = 2;  // a row, not an atom of frame 0
  AtomRig missing(atoms_come_and_go(), o);
  EXPECT_THROW(missing.view->check_selection(missing.loop), Error);
  EXPECT_EQ(missing.view->state().selected, -1);
}

// Rows are the elements when the frames carry no ids: the selection stays on its row.
TEST(WindowAtoms, WithoutIdsTheSelectionStaysOnItsRow) {
  Recording rec = atoms_come_and_go();
  for (RecordedFrame& f : rec.frames) f.ids.clear();
  AtomRig rig(std::move(rec));
  rig.frames(1);
  rig.view->state().selected = 1;
  rig.loop.step();
  rig.frames(1);
  EXPECT_EQ(rig.view->state().selected, 1);
}

// A periodic frame (x periodic over [0, 10)) with the ids overlay: the picture is written for a look.
TEST(WindowAtoms, APeriodicFramesScreenshotIsWritten) {
  Recording rec;
  rec.path = "periodic.dump";
  RecordedFrame f = dump_frame(0, {2753, 12, 99, 4}, {0.3, 9.75, 5, 9.4});
  f.elements.y << 1, 1.2, 1, 2.4;
  f.elements.r << 0.5, 0.5, 0.5, 0.45;
  f.elements.box.periodic[0] = true;
  f.elements.box.lo[0] = 0;
  f.elements.box.hi[0] = 10;
  f.pairs = {{0, 1}};  // the dump's own contact: across the edge
  rec.frames = {f};
  rec.has_pairs = true;
  ViewOptions o;
  o.overlays = "+ids,+elements";
  o.no_timings = true;
  FrameLoopOptions recorded;
  recorded.algorithm = "recorded";
  AtomRig rig(std::move(rec), o, recorded);
  rig.view->state().selected = 0;
  rig.frames(GlView::kSettleFrames);
  ASSERT_EQ(rig.loop.result().selected().pairs, (PairList{{0, 1}})) << "atoms 2753 and 12 touch across the edge";
  std::filesystem::create_directories(NBSCOPE_TEST_OUT);
  write_png(std::string(NBSCOPE_TEST_OUT) + "/window_periodic.png", rig.view->screenshot());
}

// A violation across x's periodic edge of [0, 100): atoms 7 (x 0.3) and 8 (x 99.75) touch through
// the edge, 0.55 apart. Going to it frames the pair as the check measures it (atom 7 and 8's image
// at -0.25), not the two atoms' positions 99 apart (which put the whole box in view).
TEST(WindowAtoms, AViolationAcrossAPeriodicEdgeFramesTheMinimumImagePair) {
  Recording rec;
  rec.path = "periodic.dump";
  RecordedFrame f = dump_frame(0, {7, 8, 9}, {0.3, 99.75, 50});
  f.elements.r << 0.5, 0.5, 0.5;
  f.elements.box.periodic[0] = true;
  f.elements.box.lo[0] = 0;
  f.elements.box.hi[0] = 100;
  rec.frames = {f};
  AtomRig rig(std::move(rec));
  rig.frames(1);
  Violation v;
  v.frame = rig.loop.source().frame();
  v.pair = Pair{0, 1};
  v.what = "in contact (in R) but missing from the recorded pairs";
  rig.view->focus_violation(rig.loop, v);
  rig.frames(GlView::kSettleFrames);
  const render::WorldRect seen = rig.view->camera().view();
  EXPECT_LT(seen.max.x() - seen.min.x(), 20.0) << "zoomed on the pair, not the box";
  for (const double x : {0.3, -0.25}) {  // atom 7, and atom 8's nearest image
    EXPECT_GT(x, seen.min.x()) << x;
    EXPECT_LT(x, seen.max.x()) << x;
  }
  std::filesystem::create_directories(NBSCOPE_TEST_OUT);
  write_png(std::string(NBSCOPE_TEST_OUT) + "/window_periodic_violation.png", rig.view->screenshot());
}

// A run whose first frame has no atoms (LIGGGHTS's timestep 0, before insertion): Home fits the
// first frame with atoms once it is shown, not the empty frame's placeholder box.
TEST(WindowAtoms, AnEmptyFirstFrameIsNotWhatHomeFits) {
  Recording rec;
  rec.path = "pour.dump";
  rec.frames = {dump_frame(0, {}, {}), dump_frame(1, {1, 2, 3}, {10, 30, 50})};
  AtomRig rig(std::move(rec));
  rig.frames(1);
  rig.loop.step();
  rig.frames(GlView::kSettleFrames);
  const render::WorldRect seen = rig.view->camera().view();
  for (const double x : {9.75, 50.25}) {  // the atoms' extent
    EXPECT_GT(x, seen.min.x()) << x;
    EXPECT_LT(x, seen.max.x()) << x;
  }
  EXPECT_LT(seen.max.x() - seen.min.x(), 160.0) << "fitted, not zoomed out";
}

// (One view at a time: each holds the ImGui context.) A camera the user moved is theirs: the first
// frame with atoms does not fit it again.
TEST(WindowAtoms, AnEmptyFirstFrameLeavesACameraTheUserMoved) {
  Recording again;
  again.path = "pour.dump";
  again.frames = {dump_frame(0, {}, {}), dump_frame(1, {1}, {10}), dump_frame(2, {1, 2}, {10, 500})};
  AtomRig moved(std::move(again));
  moved.frames(1);
  moved.view->camera().set({3, 4}, 17.0);
  moved.loop.step();
  moved.frames(1);
  EXPECT_EQ(moved.view->camera().pixels_per_metre(), 17.0);
}

// A frame read from two ranks' files (io/dump_ranks.hpp): four atoms, one in each quarter of a 10 x
// 10 box split 2 x 2, ranks 0..3 as LAMMPS numbers them (z fastest, then y: rank 1 upper left).
Recording four_ranks() {
  RecordedFrame f = dump_frame(100, {1, 2, 3, 4}, {});
  for (const auto& [x, y] : {std::pair{2.5, 2.5}, {2.5, 7.5}, {7.5, 2.5}, {7.5, 7.5}}) f.elements.push_back(x, y, 0, 1.5);
  f.ranks = {0, 1, 2, 3};
  auto split = std::make_shared<Subdomains>();
  split->grid = {2, 2, 1};
  split->box.max[0] = split->box.max[1] = split->box.max[2] = 10;
  f.subdomains = split;
  Recording rec;
  rec.path = "atoms.%.dump";
  rec.frames = {f};
  return rec;
}

// The colour of the screenshot's pixel over world point (x, y).
render::Rgba pixel_at(AtomRig& rig, const Image& image, double x, double y) {
  const Eigen::Vector2d p = rig.view->camera().to_screen({x, y});
  const std::uint8_t* c = image.at(static_cast<int>(p.x()), static_cast<int>(p.y()));
  return {c[0], c[1], c[2]};
}

TEST(WindowAtoms, PerRankFramesAreColouredByRankAndShowEachRanksSubdomain) {
  ViewOptions options;
  options.colour_by = "rank";  // no proc column: the ranks of the files
  options.panels = "none";
  options.overlays = "-grid";  // nothing over the atoms' fills
  AtomRig rig(four_ranks(), options);
  rig.frames(3);
  const Image image = rig.view->screenshot();
  write_png(std::string(NBSCOPE_TEST_OUT) + "/window_ranks.png", image);
  const double xs[] = {2.5, 2.5, 7.5, 7.5}, ys[] = {2.5, 7.5, 2.5, 7.5};
  for (std::size_t rank = 0; rank < 4; ++rank) {
    // Left of and above the centre: clear of the spoke drawn from it to the right.
    EXPECT_EQ(pixel_at(rig, image, xs[rank] - 0.6, ys[rank] + 0.6), render::category_colour(rank)) << "the atom of rank " << rank;
  }
  EXPECT_TRUE(rig.view->state().overlays.subdomains);
  // Along the cut x = 5 between ranks 0 and 2 (y 2.5): one of the two ranks' outline colours.
  const render::Rgba cut = pixel_at(rig, image, 5.0, 2.5);
  EXPECT_TRUE(cut == render::category_colour(0) || cut == render::category_colour(2)) << int(cut.r) << "," << int(cut.g) << "," << int(cut.b);
  rig.view->state().overlays.subdomains = false;  // D
  rig.frames(1);
  EXPECT_NE(pixel_at(rig, rig.view->screenshot(), 5.0, 2.5), cut);
}

TEST(WindowAtoms, ColourByRankWithoutRanksOrAProcColumnIsOneClearError) {
  Recording rec = four_ranks();
  rec.frames.front().ranks.clear();
  rec.frames.front().subdomains.reset();
  ViewOptions options;
  options.colour_by = "rank";
  try {
    AtomRig rig(std::move(rec), options);
    rig.frames(1);
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("--color-by rank: the frames have no column 'proc'"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }
}

}  // namespace
}  // namespace nbscope

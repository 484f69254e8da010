// The subdomains overlay (render/overlays.hpp, D): a frame read from per-rank dumps shows each rank's
// subdomain outlined in the rank's colour and labelled "rank r"; the overlay's key turns it off; a
// frame without ranks draws none; a 3D frame's layer view shows the subdomains its layer cuts.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "core/layers.hpp"
#include "render/overlays.hpp"
#include "support/draw_recorder.hpp"
#include "support/layer_draw.hpp"

namespace nbscope::render {
namespace {

using testdraw::Recorder;

// A 10 x 10 box split 2 x 2 (LAMMPS's rank order: rank 1 above rank 0, rank 2 right of it), one atom in each.
struct FourRanks {
  Elements e;
  Subdomains split;
  FourRanks() {
    for (const auto& [x, y] : {std::pair{2.0, 2.0}, {2.0, 7.0}, {7.0, 2.0}, {7.0, 7.0}}) e.push_back(x, y, 0, 0.5);
    split.grid = {2, 2, 1};
    split.box.max[0] = split.box.max[1] = 10;
  }
};

Recorder draw(const OverlayScene& s, const OverlayFlags& f) {
  Camera camera;
  camera.set_viewport(800, 800);
  camera.fit({{-1, -1}, {11, 11}});
  Recorder rec;
  draw_scene(s, f, camera, rec);
  return rec;
}

OverlayFlags subdomains_only() {
  OverlayFlags f;
  for (const OverlayInfo& o : overlay_infos()) f.*o.flag = false;
  f.subdomains = true;
  return f;
}

TEST(SubdomainsOverlay, EachRanksSubdomainOutlinedInItsColourAndLabelled) {
  const FourRanks four;
  OverlayScene s;
  s.elements = &four.e;
  s.subdomains = &four.split;
  const Recorder rec = draw(s, subdomains_only());
  for (int rank = 0; rank < 4; ++rank) {
    const auto outline = rec.lines_of(category_colour(static_cast<std::size_t>(rank)));
    ASSERT_EQ(outline.size(), 4u) << "rank " << rank;
    // Rank 1's is the upper left quarter: x 0..5, y 5..10.
    float lo_x = 99, hi_x = -99, lo_y = 99, hi_y = -99;
    for (const auto& l : outline)
      for (const Vec2& p : {l.from, l.to}) {
        lo_x = std::min(lo_x, p.x()), hi_x = std::max(hi_x, p.x());
        lo_y = std::min(lo_y, p.y()), hi_y = std::max(hi_y, p.y());
      }
    const Bounds b = four.split.bounds_of(rank);
    EXPECT_FLOAT_EQ(lo_x, static_cast<float>(b.min[0]));
    EXPECT_FLOAT_EQ(hi_y, static_cast<float>(b.max[1]));
    EXPECT_TRUE(rec.has_text("rank " + std::to_string(rank)));
    // The label inside its own subdomain.
    for (const auto& t : rec.texts)
      if (t.text == "rank " + std::to_string(rank)) {
        EXPECT_GT(t.at.x(), b.min[0]);
        EXPECT_LT(t.at.x(), b.max[0]);
        EXPECT_GT(t.at.y(), b.min[1]);
        EXPECT_LT(t.at.y(), b.max[1]);
      }
  }
  EXPECT_EQ(four.split.bounds_of(1).min[1], 5);
  EXPECT_EQ(four.split.bounds_of(1).max[0], 5);

  OverlayFlags off = subdomains_only();
  off.subdomains = false;  // the D key
  EXPECT_TRUE(draw(s, off).lines.empty());
  s.subdomains = nullptr;  // a frame of one file set: no ranks, nothing to draw
  EXPECT_TRUE(draw(s, subdomains_only()).lines.empty());
}

TEST(SubdomainsOverlay, TheOverlayHasAKeyOfItsOwnAndIsOnByDefault) {
  int with_d = 0;
  for (const OverlayInfo& o : overlay_infos()) with_d += o.key == 'D';
  EXPECT_EQ(with_d, 1);
  EXPECT_TRUE(OverlayFlags{}.subdomains);
}

TEST(SubdomainsOverlay, TheLayerViewShowsTheSubdomainsItsLayerCuts) {
  // 4 x 4 x 4 unit cells; the box split in z (two ranks: z 0..2 and 2..4); layer 3 shown (z 3..4).
  const testlayers::Column col;
  Subdomains split;
  split.grid = {1, 1, 2};
  split.box.max[0] = split.box.max[1] = split.box.max[2] = 4;
  const LayerSlice top = slice_layer(col.e, col.grid, 3), bottom = slice_layer(col.e, col.grid, 0);
  OverlayScene s;
  s.elements = &col.e;
  s.grid = &col.grid;
  s.subdomains = &split;
  s.layer = &top;
  Recorder rec = draw(s, subdomains_only());
  EXPECT_TRUE(rec.has_text("rank 1"));
  EXPECT_FALSE(rec.has_text("rank 0"));
  EXPECT_EQ(rec.lines_of(category_colour(0)).size(), 0u);
  s.layer = &bottom;
  rec = draw(s, subdomains_only());
  EXPECT_TRUE(rec.has_text("rank 0"));
  EXPECT_FALSE(rec.has_text("rank 1"));
}

}  // namespace
}  // namespace nbscope::render

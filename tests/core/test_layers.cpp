// core/layers: a 3D frame seen one layer of cells at a time — where each element lies relative to
// the layer shown (here, below, above, further), the periodic z's wrap, the refusals, the layer whose
// pass finds a pair, the place of a traced list and the busiest layer.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "core/layers.hpp"

namespace nbscope {
namespace {

// Spheres of radius 0.25 at (0.5, 0.5, z) for each z: on a grid of unit cells from the origin,
// element k lies in layer floor(zs[k]).
Elements column(std::initializer_list<double> zs) {
  Elements e;
  e.dim = 3;
  for (const double z : zs) e.push_back(0.5, 0.5, z, 0.25);
  return e;
}

Grid unit_grid(const Elements& e, std::int64_t nz) {
  GridOptions o;
  o.cell_size = 1.0;
  o.origin = {0.0, 0.0, 0.0};
  o.cells = {{2, 2, nz}};
  return make_grid(e, o);
}

TEST(Layers, SlicePlacesEachElementHereBelowAboveOrFurther) {
  const Elements e = column({2.5, 1.5, 3.5, 0.5, 2.1, 4.5});
  const Grid g = unit_grid(e, 5);
  const LayerSlice s = slice_layer(e, g, 2);
  EXPECT_EQ(s.layer, 2);
  EXPECT_EQ(s.below, 1);
  EXPECT_EQ(s.above, 3);
  EXPECT_EQ(s.count, 5);
  EXPECT_EQ(s.element_layer, (std::vector<std::int32_t>{2, 1, 3, 0, 2, 4}));
  EXPECT_EQ(s.per_layer, (std::vector<std::int64_t>{1, 1, 2, 1, 1}));
  EXPECT_EQ(s.place(0), LayerPlace::Here);
  EXPECT_EQ(s.place(1), LayerPlace::Below);
  EXPECT_EQ(s.place(2), LayerPlace::Above);
  EXPECT_EQ(s.place(3), LayerPlace::Other);
  EXPECT_EQ(s.place(4), LayerPlace::Here);
  EXPECT_EQ(s.place(5), LayerPlace::Other);
  EXPECT_TRUE(s.visible(0));
  EXPECT_TRUE(s.visible(1));
  EXPECT_FALSE(s.visible(2));
  EXPECT_FALSE(s.visible(3));
}

TEST(Layers, TheBottomAndTopLayersOfAnOpenZHaveNoBelowOrAbove) {
  const Elements e = column({0.5, 1.5, 2.5});
  const Grid g = unit_grid(e, 3);
  const LayerSlice bottom = slice_layer(e, g, 0);
  EXPECT_EQ(bottom.below, -1);
  EXPECT_EQ(bottom.above, 1);
  EXPECT_EQ(bottom.place(2), LayerPlace::Other);  // two up: hidden, not "below" by a wrap
  const LayerSlice top = slice_layer(e, g, 2);
  EXPECT_EQ(top.below, 1);
  EXPECT_EQ(top.above, -1);
  EXPECT_EQ(top.place(0), LayerPlace::Other);
}

TEST(Layers, APeriodicZWrapsTheBottomLayersBelowToTheTop) {
  Elements e = column({0.5, 1.5, 2.5, 3.5});
  e.box.periodic[2] = true;
  e.box.lo[2] = 0.0;
  e.box.hi[2] = 4.0;
  GridOptions o;
  o.cell_size = 1.0;
  const Grid g = make_grid(e, o);
  ASSERT_EQ(g.n[2], 4);
  const LayerSlice bottom = slice_layer(e, g, 0);
  EXPECT_EQ(bottom.below, 3);
  EXPECT_EQ(bottom.above, 1);
  EXPECT_EQ(bottom.place(3), LayerPlace::Below);
  EXPECT_EQ(bottom.place(1), LayerPlace::Above);
  EXPECT_EQ(bottom.place(2), LayerPlace::Other);
  const LayerSlice top = slice_layer(e, g, 3);
  EXPECT_EQ(top.above, 0);
  EXPECT_EQ(top.place(0), LayerPlace::Above);
  // The pass of layer 0 finds its pairs with layer 3 (its mask's layer below), not the other way round.
  EXPECT_EQ(pair_layer(g, 0, 3), 0);
  EXPECT_EQ(pair_layer(g, 3, 0), 0);
  EXPECT_EQ(pair_layer(g, 3, 2), 3);
}

TEST(Layers, SliceRefusesA2DFrameAndLayersPastTheGrid) {
  const Elements e = column({0.5, 1.5});
  const Grid g = unit_grid(e, 2);
  EXPECT_THROW((void)slice_layer(e, g, -1), Error);
  try {
    (void)slice_layer(e, g, 2);
    ADD_FAILURE() << "layer 2 of 2 accepted";
  } catch (const Error& err) {
    EXPECT_NE(std::string(err.what()).find("0..1"), std::string::npos) << err.what();
  }
  Elements flat;
  flat.push_back(0.5, 0.5, 0.0, 0.25);
  GridOptions o;
  o.cell_size = 1.0;
  const Grid g2 = make_grid(flat, o);
  EXPECT_THROW((void)slice_layer(flat, g2, 0), Error);
  EXPECT_THROW((void)slice_layer(e, g2, 0), Error);  // a 3D frame on a 2D grid
}

TEST(Layers, APairIsFoundInThePassOfItsUpperLayer) {
  const Elements e = column({0.5, 1.5, 1.9, 3.5});
  const Grid g = unit_grid(e, 4);
  EXPECT_EQ(pair_layer(g, 1, 1), 1);
  EXPECT_EQ(pair_layer(g, 0, 1), 1);
  EXPECT_EQ(pair_layer(g, 1, 0), 1);
  EXPECT_EQ(pair_layer(g, 0, 3), 3);  // not neighbours on an open z (a wrong pair): the upper one
  const LayerSlice s = slice_layer(e, g, 0);
  EXPECT_EQ(pair_layer(s, g, Pair{0, 1}), 1);
  EXPECT_EQ(pair_layer(s, g, Pair{1, 2}), 1);
  EXPECT_EQ(pair_layer(s, g, Pair{0, 3}), 3);
}

TEST(Layers, AListLiesWhereItsCellsLayerIs) {
  const Elements e = column({0.5, 1.5, 2.5});
  const Grid g = unit_grid(e, 3);
  const LayerSlice s = slice_layer(e, g, 1);
  TracedList l;
  EXPECT_EQ(list_layer_place(l, s), LayerPlace::Here);  // fixes no layer (2D, a tree's leaf)
  l.cell[2] = 1;
  EXPECT_EQ(list_layer_place(l, s), LayerPlace::Here);
  l.cell[2] = 0;
  EXPECT_EQ(list_layer_place(l, s), LayerPlace::Below);
  l.cell[2] = 2;
  EXPECT_EQ(list_layer_place(l, s), LayerPlace::Above);
}

TEST(Layers, TheBusiestLayerIsTheFullestTheLowestOnATie) {
  const Elements e = column({0.5, 1.5, 1.6, 2.5, 2.6, 3.5});
  const Grid g = unit_grid(e, 4);
  EXPECT_EQ(busiest_layer(slice_layer(e, g, 0)), 1);
  const Elements one_each = column({0.5, 1.5, 2.5});
  EXPECT_EQ(busiest_layer(slice_layer(one_each, unit_grid(one_each, 3), 2)), 0);
}

}  // namespace
}  // namespace nbscope

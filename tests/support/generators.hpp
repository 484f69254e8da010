// nbscope tests and benchmarks: element sets of the families every detector is checked on.
#pragma once
#include "core/elements.hpp"
#include "core/layouts.hpp"
#include "core/grid.hpp"
#include "core/pairs.hpp"

namespace nbscope::testdata {

// The layouts live in core (core/layouts.hpp), shared with `nbscope scaling`; these names keep
// the tests and benchmarks unchanged.
using nbscope::Layout;
using nbscope::all_layouts;
using nbscope::layout_name;
using nbscope::make_layout;

// The book's Fig. 3.15: nine elements of radius 0.1 (assets/examples/nine.csv, 0-based here).
Elements book_nine();
// Its grid as the book pins it: 10 x 10 unit cells from (0, 0).
GridOptions book_grid();
// The reference every detector is checked against: brute force, sorted by (i, j).
PairList brute_pairs(const Elements& elements);

}  // namespace nbscope::testdata

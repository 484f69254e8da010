// A verify run by hand (no arrays file): the book's nine elements of Fig. 3.15 and screen arrays with
// a planted bug, with the verdict the check gives them — for drawing tests that need no reader.
#pragma once
#include <array>
#include <string>

#include "app/verify_run.hpp"
#include "render/camera.hpp"

namespace nbscope::testdata {

// The book's Fig. 3.15 nine elements (assets/examples/nine.csv), 0-based; with 1 m cells from (0,0)
// they lie in C[4][6] {3,1,0}, C[4][5] {5}, C[5][5] {7}, C[1][6] {8,6,4,2} (0-based cells).
inline Elements nine() {
  return make_elements_2d((Eigen::ArrayXd(9) << 4.75, 4.90, 1.85, 4.60, 1.30, 4.50, 1.60, 5.20, 1.20).finished(),
                          (Eigen::ArrayXd(9) << 6.45, 6.50, 6.45, 6.80, 6.85, 5.55, 6.60, 5.40, 6.55).finished(),
                          Eigen::ArrayXd::Constant(9, 0.1));
}

// Screen arrays with a planted bug: E[1] = 6 (was 0), so C[4][6]'s list runs 3 -> 1 -> 6 -> 4 -> 2,
// element 0 is on no list, and C[1][6]'s walk, 8 -> 6, meets 6 a second time and is cut there.
struct PlantedBug {
  VerifyArraysRun run;
  render::Camera camera;
  explicit PlantedBug(int base) {
    Elements& e = run.elements;
    Grid& grid = run.grid;
    verify::UserArrays& user = run.user;
    verify::ArraysVerdict& verdict = run.verdict;
    e = nine();
    GridOptions o;
    o.cell_size = 1.0;
    o.origin = std::array<double, 3>{0, 0, 0};
    o.cells = std::array<std::int64_t, 3>{10, 10, 1};
    grid = make_grid(e, o);
    user.algorithm = "screen";
    user.base = base;
    verify::ListFamily f;
    f.heads_name = "C";
    f.next_name = "E";
    f.heads_shape = {10, 10};
    f.next_path = "$.next";
    const auto list = [](std::int32_t ix, std::int32_t iy, std::int32_t head) {
      verify::UserList l;
      l.slot = ix * 10 + iy;
      l.head = head;
      l.cell = {ix, iy, -1};
      return l;
    };
    f.lists = {list(4, 6, 3), list(4, 5, 5), list(5, 5, 7), list(1, 6, 8)};
    f.next = {-1, 6, -1, 1, 2, -1, 4, -1, 6};
    user.families.push_back(f);
    const auto b = [base](int k) { return std::to_string(k + base); };
    verify::Problem wrong;
    wrong.kind = verify::ProblemKind::WrongList;
    wrong.text = "E[" + b(1) + "] = " + b(6) + ", but element " + b(6) + " lies in cell (" + b(1) + "," + b(6) + ") and element " +
                 b(1) + " in cell (" + b(4) + "," + b(6) + ")";
    wrong.elements = {6};
    wrong.link = std::make_pair(ElementId{1}, ElementId{6});
    wrong.family = 0;
    wrong.list = 0;
    verify::Problem dropped;
    dropped.kind = verify::ProblemKind::NotListed;
    dropped.text = "element " + b(0) + " is on no list: C[" + b(4) + "][" + b(6) + "] should hold it";
    dropped.elements = {0};
    dropped.family = 0;
    verify::Problem twice;
    twice.kind = verify::ProblemKind::TwoLists;
    twice.text = "E[" + b(8) + "] = " + b(6) + ", but element " + b(6) + " is already on C[" + b(4) + "][" + b(6) + "]";
    twice.elements = {6};
    twice.link = std::make_pair(ElementId{8}, ElementId{6});
    twice.family = 0;
    twice.list = 3;
    verdict.problems = {wrong, dropped, twice};
    verdict.problem_count = 3;
    verdict.lists = {{0, 0, {3, 1, 6, 4, 2}, false}, {0, 1, {5}, false}, {0, 2, {7}, false}, {0, 3, {8}, true}};
    camera.set_viewport(1000, 600);
    camera.fit({{0.5, 4.8}, {6.0, 7.5}});
  }
};

}  // namespace nbscope::testdata

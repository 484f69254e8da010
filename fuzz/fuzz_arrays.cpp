// Fuzz target: an ARRAYS.json through the path `verify --arrays` takes (io/arrays_json.hpp, then
// core/verify.hpp) on arbitrary bytes, against fixed elements: the book's nine circles (2D) or
// fourteen spheres (3D, chosen by the file's "dim"). The algorithm is the file's, or each of screen,
// nbs, tree and sort; the grid the file's keys pin, the rest derived from the elements, as verify
// derives it. A file it refuses must say so with nbscope::Error; one it reads must be walked to a
// verdict that keeps its promises: every kept problem counted, no more kept than the cap, every
// problem's family and list and every walked list's elements naming something that exists.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/array_schema.hpp"
#include "core/error.hpp"
#include "core/grid.hpp"
#include "core/verify.hpp"
#include "fuzz_check.hpp"
#include "io/arrays_json.hpp"

namespace {

using nbscope::Elements;

Elements nine() {
  Elements e;
  const double rows[9][2] = {{4.75, 6.45}, {4.90, 6.50}, {1.85, 6.45}, {4.60, 6.80}, {1.30, 6.85},
                             {4.50, 5.55}, {1.60, 6.60}, {5.20, 5.40}, {1.20, 6.55}};
  for (const auto& p : rows) e.push_back(p[0], p[1], 0, 0.1);
  return e;
}

// Fourteen spheres: a 2 x 2 x 2 block of unit cells with two to a cell in places, and one on a boundary.
Elements fourteen() {
  Elements e;
  e.dim = 3;
  for (int k = 0; k < 14; ++k)
    e.push_back(0.3 + (k % 2) * 1.0 + (k >= 8 ? 0.2 : 0), 0.4 + (k / 2 % 2) * 1.0, 0.5 + (k / 4 % 2) * 1.0 + (k == 13 ? 0.5 : 0), 0.25);
  return e;
}

// The verdict's promises.
void check_verdict(const nbscope::verify::UserArrays& user, const nbscope::verify::ArraysVerdict& v, std::int64_t n) {
  using nbscope::verify::kMaxKeptProblems;
  FUZZ_CHECK(v.problem_count >= static_cast<std::int64_t>(v.problems.size()), "arrays: fewer problems counted than kept");
  FUZZ_CHECK(v.problems.size() <= kMaxKeptProblems, "arrays: more problems kept than the cap");
  const auto families = static_cast<int>(user.families.size());
  for (const auto& p : v.problems) {
    FUZZ_CHECK(!p.text.empty(), "arrays: a problem without text");
    FUZZ_CHECK(p.family >= -1 && p.family < families, "arrays: a problem names family " + std::to_string(p.family));
    if (p.family >= 0 && p.list >= 0)
      FUZZ_CHECK(p.list < static_cast<int>(user.families[static_cast<std::size_t>(p.family)].lists.size()),
                 "arrays: a problem names list " + std::to_string(p.list));
    for (const nbscope::ElementId k : p.elements) FUZZ_CHECK(k >= 0 && k < n, "arrays: a problem names element " + std::to_string(k));
  }
  for (const auto& w : v.lists) {
    FUZZ_CHECK(w.family >= 0 && w.family < families, "arrays: a walked list of family " + std::to_string(w.family));
    FUZZ_CHECK(w.list >= 0 && w.list < static_cast<int>(user.families[static_cast<std::size_t>(w.family)].lists.size()),
               "arrays: a walked list " + std::to_string(w.list));
    FUZZ_CHECK(static_cast<std::int64_t>(w.chain.size()) <= n, "arrays: a walked list longer than N");
    for (const nbscope::ElementId k : w.chain) FUZZ_CHECK(k >= 0 && k < n, "arrays: a walked list holds element " + std::to_string(k));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Elements two = nine(), three = fourteen();
  const std::string text(reinterpret_cast<const char*>(data), size);
  nbscope::ArraysJson file;
  try {
    file = nbscope::parse_arrays_json(text, "fuzz.json");
  } catch (const nbscope::Error&) {
    return 0;  // refused: the normal outcome
  }
  const Elements& e = file.dim.value_or(2) == 3 ? three : two;
  if (file.elements && *file.elements != e.size()) return 0;  // verify refuses it before the arrays
  std::vector<std::string> algorithms = nbscope::array_schema::algorithms();
  if (file.algorithm) algorithms = {*file.algorithm};
  for (const std::string& algorithm : algorithms) {
    nbscope::verify::UserArrays user;
    nbscope::verify::ArraysVerdict verdict;
    try {
      nbscope::GridOptions options = file.grid;
      if (options.cells && e.dim == 2) (*options.cells)[2] = 1;
      const nbscope::Grid grid = nbscope::make_grid(e, options);
      user = file.arrays(algorithm, grid, e.size(), file.base.value_or(0));
      if (nbscope::fuzz::planted_fault() == "foreign-exception") throw std::logic_error("planted");
      verdict = nbscope::verify::verify_arrays(e, grid, user, true);
    } catch (const nbscope::Error&) {
      continue;  // a grid or arrays verify refuses
    }
    if (nbscope::fuzz::planted_fault() == "bad-row") verdict.problem_count = -1;
    check_verdict(user, verdict, e.size());
  }
  return 0;
}

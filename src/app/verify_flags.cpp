#include "app/verify_flags.hpp"

#include <algorithm>
#include <iterator>

#include "app/grid_flags.hpp"
#include "core/error.hpp"

namespace nbscope {

VerifyArraysInputs take_verify_flags(Args& args) {
  VerifyArraysInputs in;
  const auto input = args.value("--input");
  const auto arrays = args.value("--arrays");
  if (!input || input->empty())
    throw Error("--input: missing: the elements the arrays were built on (ELEMENTS.csv, x,y,r a line)");
  if (!arrays || arrays->empty())
    throw Error("--arrays: missing: the heads and next arrays to check (ARRAYS.json, in the schema nbscope dump writes)");
  in.elements_path = *input;
  in.arrays_path = *arrays;
  if (auto a = args.value("--algorithm")) {
    if (std::find(std::begin(kVerifiedAlgorithms), std::end(kVerifiedAlgorithms), *a) == std::end(kVerifiedAlgorithms))
      throw Error("--algorithm: '" + *a + "' is not one of screen, nbs, tree, sort (the algorithms whose arrays can be checked)");
    in.algorithm = *a;
  }
  in.grid_flags = take_grid_flags(args);
  if (auto b = args.integer("--base", 0, 1)) in.base = static_cast<int>(*b);
  in.exact = args.flag("--exact");
  return in;
}

}  // namespace nbscope

// nbscope app: one `nbscope verify --arrays` run as data: the elements, the grid the arrays were
// checked on, the user's arrays and what was found. The command prints it (cmd_verify.cpp); the
// screenshot and the window draw it (verify_view.cpp).
#pragma once
#include <optional>
#include <string>

#include "app/cli.hpp"
#include "app/grid_flags.hpp"
#include "core/elements.hpp"
#include "core/grid.hpp"
#include "core/verify.hpp"

namespace nbscope {

// The inputs of an arrays check, as the flags give them.
struct VerifyArraysInputs {
  std::string elements_path;            // --input ELEMENTS.csv
  std::string arrays_path;              // --arrays ARRAYS.json
  std::optional<std::string> algorithm; // --algorithm (default: the file's "algorithm" key)
  GridFlags grid_flags;                 // --cell-size/--origin/--cells (must agree with the file's grid keys)
  std::optional<int> base;              // --base 0|1 (must agree with the file's "base" key)
  bool exact = false;                   // --exact: also the book's order within every list
};

// What an arrays check found.
struct VerifyArraysRun {
  Elements elements;
  Grid grid;
  verify::UserArrays user;
  verify::ArraysVerdict verdict;
};

// Takes --input, --arrays, --algorithm, --base, --exact and the grid flags from `args` (gui and
// verify share them); Error on a malformed value. Empty paths when the flag is absent.
VerifyArraysInputs take_verify_inputs(Args& args);

// Reads both files and checks the arrays. Throws Error (exit 2) on bad input: either file, a JSON of
// another schema, wrong array lengths, another dimension, a grid that does not fit the elements.
VerifyArraysRun run_verify_arrays(const VerifyArraysInputs& inputs);

}  // namespace nbscope

// nbscope app: the flags of an arrays check, shared by `nbscope verify` and `nbscope gui --arrays`:
// --input ELEMENTS.csv --arrays ARRAYS.json [--algorithm A] [--cell-size D] [--origin X,Y[,Z]]
// [--cells NX,NY[,NZ]] [--base 0|1] [--exact].
#pragma once
#include "app/cli.hpp"
#include "app/verify_run.hpp"

namespace nbscope {

// The algorithms whose arrays can be checked (they keep heads and next arrays, or sort's permutation).
inline constexpr const char* kVerifiedAlgorithms[] = {"screen", "nbs", "tree", "sort"};

// Takes the arrays check's flags out of `args` (the rest stay for the command). Error when --input
// or --arrays is missing or a value is malformed (--algorithm not one of kVerifiedAlgorithms,
// --base not 0 or 1).
VerifyArraysInputs take_verify_flags(Args& args);

}  // namespace nbscope

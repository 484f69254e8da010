// nbscope fuzz targets: what every target shares. A reader may refuse bytes with nbscope::Error
// (the normal outcome for most inputs); anything else is a bug libFuzzer must see as a crash:
// a sanitizer report, another exception (uncaught, so std::terminate aborts), or a broken
// postcondition, which fuzz_fail() reports before aborting.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace nbscope::fuzz {

// The fault NBSCOPE_FUZZ_FAULT plants ("" for none), so that `scripts/dev fuzz` can show that each
// target's checks catch it before trusting a quiet run: drop-pair (a detector loses a pair),
// bad-row (a reader's result breaks its postcondition), foreign-exception (a reader throws
// something other than nbscope::Error), drop-peek (a pipe loses the bytes a sniff peeked, as
// before io/input_source.hpp).
inline std::string_view planted_fault() {
  static const std::string fault = [] {
    const char* v = std::getenv("NBSCOPE_FUZZ_FAULT");
    return std::string(v == nullptr ? "" : v);
  }();
  return fault;
}

// Prints "fuzz: <what>" and aborts, so that libFuzzer keeps the input as a crash.
[[noreturn]] inline void fuzz_fail(const std::string& what) {
  std::fprintf(stderr, "fuzz: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

}  // namespace nbscope::fuzz

// Aborts with the message `what` (a std::string expression, built only on failure: checks run
// for every row of every input) unless `ok`.
#define FUZZ_CHECK(ok, what)                             \
  do {                                                   \
    if (!(ok)) ::nbscope::fuzz::fuzz_fail(what);         \
  } while (false)

// Fuzz target: a PAIRS.csv through the path `verify --pairs` takes (io/given_pairs.hpp, then
// verify::compare_pairs) on arbitrary bytes, 0- and 1-based, against the book's nine elements. A file
// it reads must be classed pair by pair: every pair given is right, extra, a repeat, with itself or
// out of range, exactly once; missing pairs are the reference's; lines rise through the file.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/pairs.hpp"
#include "core/verify.hpp"
#include "fuzz_check.hpp"
#include "io/given_pairs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The book's nine elements' one contact (Fig. 3.15, 0-based), and a made-up second for variety.
  static const nbscope::PairList reference{{0, 1}, {2, 6}};
  constexpr std::int64_t n = 9;
  const std::string text(reinterpret_cast<const char*>(data), size);
  for (int base : {0, 1}) {
    std::vector<nbscope::verify::GivenPair> given;
    try {
      given = nbscope::parse_given_pairs_csv(text, "fuzz.csv", base, 10'000);
      if (nbscope::fuzz::planted_fault() == "foreign-exception") throw std::logic_error("planted");
    } catch (const nbscope::Error&) {
      continue;  // refused: the normal outcome
    }
    FUZZ_CHECK(given.size() <= 10'000, "pairs: more pairs than the limit");
    for (std::size_t k = 1; k < given.size(); ++k) FUZZ_CHECK(given[k].line > given[k - 1].line, "pairs: lines do not rise");
    nbscope::verify::PairsVerdict v = nbscope::verify::compare_pairs(n, given, reference);
    if (nbscope::fuzz::planted_fault() == "bad-row" && !given.empty()) ++v.right;
    const auto classed = static_cast<std::int64_t>(v.extra.size() + v.duplicates.size() + v.self.size() + v.out_of_range.size()) + v.right;
    FUZZ_CHECK(classed == static_cast<std::int64_t>(given.size()),
               "pairs: " + std::to_string(given.size()) + " given, " + std::to_string(classed) + " classed");
    FUZZ_CHECK(static_cast<std::int64_t>(v.missing.size()) + v.right == static_cast<std::int64_t>(reference.size()),
               "pairs: missing and right do not add up to the reference");
    for (const nbscope::Pair& p : v.missing)
      FUZZ_CHECK(std::binary_search(reference.begin(), reference.end(), p), "pairs: a missing pair not in the reference");
    for (const auto& g : v.out_of_range) FUZZ_CHECK(g.i < 0 || g.j < 0 || g.i >= n || g.j >= n, "pairs: in range called out of range");
    for (const auto& g : v.self) FUZZ_CHECK(g.i == g.j, "pairs: i != j called with itself");
    FUZZ_CHECK(v.ok() == (v.right == static_cast<std::int64_t>(given.size()) && v.missing.empty()), "pairs: ok() disagrees");
  }
  return 0;
}

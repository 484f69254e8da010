// Fuzz target: the ELEMENTS.csv reader (io/csv.hpp) on arbitrary bytes. A set it accepts must hold
// what its contract promises: dimension 2 or 3, equal columns, every value within the supported
// magnitudes (core/elements.hpp).
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "core/error.hpp"
#include "fuzz_check.hpp"
#include "io/csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  nbscope::Elements e;
  try {
    e = nbscope::parse_elements_csv(text, "fuzz.csv");
    if (nbscope::fuzz::planted_fault() == "foreign-exception") throw std::logic_error("planted");
  } catch (const nbscope::Error&) {
    return 0;  // refused: the normal outcome
  }
  if (nbscope::fuzz::planted_fault() == "bad-row" && e.size() > 0) e.r[0] = -e.r[0];
  FUZZ_CHECK(e.dim == 2 || e.dim == 3, "csv: dimension " + std::to_string(e.dim));
  const auto n = e.size();
  FUZZ_CHECK(e.y.size() == n && e.r.size() == n && e.z.size() == (e.dim == 3 ? n : 0), "csv: columns of unequal length");
  FUZZ_CHECK(e.valid(), "csv: accepted a value outside the supported magnitudes");
  for (std::int64_t k = 0; k < n; ++k) FUZZ_CHECK(e.r[k] > 0, "csv: accepted r <= 0 at row " + std::to_string(k));
  return 0;
}

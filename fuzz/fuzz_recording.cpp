// Fuzz target: the .nbsrec reader (io/recording.hpp) on arbitrary bytes. A recording it accepts must
// hold what its contract promises (at least one frame, numbers increasing, times not decreasing, rows
// of the header's dimension (`dim`, 2 or 3) within the supported magnitudes, pairs naming elements of their frame, no element wider than
// a pinned cell_size); then, as `replay` does, its first small frames go through every core detector
// on the recording's grid and must equal brute force (differential.hpp).
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "core/error.hpp"
#include "differential.hpp"
#include "io/recording.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  nbscope::Recording rec;
  try {
    rec = nbscope::parse_recording(text, "fuzz.nbsrec", 1000);
    if (nbscope::fuzz::planted_fault() == "foreign-exception") throw std::logic_error("planted");
  } catch (const nbscope::Error&) {
    return 0;  // refused: the normal outcome
  }
  if (nbscope::fuzz::planted_fault() == "bad-row") rec.frames.back().number = -1;
  FUZZ_CHECK(!rec.frames.empty() && rec.frames.size() <= 1000, "recording: " + std::to_string(rec.frames.size()) + " frames");
  FUZZ_CHECK(rec.pair_base == 0 || rec.pair_base == 1, "recording: base " + std::to_string(rec.pair_base));
  FUZZ_CHECK(rec.dim == 2 || rec.dim == 3, "recording: dim " + std::to_string(rec.dim));
  for (std::size_t f = 0; f < rec.frames.size(); ++f) {
    const nbscope::RecordedFrame& frame = rec.frames[f];
    const auto at = [&] { return "recording: frame " + std::to_string(frame.number) + ": "; };
    if (f > 0) {
      FUZZ_CHECK(frame.number > rec.frames[f - 1].number, at() + "number does not increase");
      FUZZ_CHECK(frame.time >= rec.frames[f - 1].time, at() + "time decreases");
    }
    FUZZ_CHECK(frame.number >= 0 && std::isfinite(frame.time), at() + "bad number or time");
    const nbscope::Elements& e = frame.elements;
    FUZZ_CHECK(e.dim == rec.dim && e.y.size() == e.size() && e.r.size() == e.size() && e.z.size() == (rec.dim == 3 ? e.size() : 0),
               at() + "not a set of the header's dimension");
    FUZZ_CHECK(e.valid(), at() + "a value outside the supported magnitudes");
    if (rec.grid.cell_size) FUZZ_CHECK(2 * e.max_radius() <= *rec.grid.cell_size, at() + "an element wider than cell_size");
    FUZZ_CHECK(rec.has_pairs || frame.pairs.empty(), at() + "pairs without has_pairs");
    for (const nbscope::Pair& p : frame.pairs)
      FUZZ_CHECK(p.i >= 0 && p.j >= 0 && p.i < e.size() && p.j < e.size(), at() + "a pair names an element it does not have");
  }
  // Replay's detection on the recording's grid, for the first few frames small enough for brute force.
  nbscope::fuzz::DetectorSet set(rec.dim);
  for (std::size_t f = 0; f < rec.frames.size() && f < 4; ++f) {
    if (rec.frames[f].elements.size() > 64) continue;
    nbscope::DetectOptions options;
    options.grid = rec.grid;
    nbscope::fuzz::require_every_detector_equals_brute(set, rec.frames[f].elements, options);
  }
  return 0;
}

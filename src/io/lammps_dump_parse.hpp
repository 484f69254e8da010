// nbscope io: what the two dump readers (lammps_dump.cpp, lammps_dump_local.cpp) share: ITEM
// lines, words, integers written as integers or floats, BOX BOUNDS, frames ordered by timestep.
#pragma once
#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "io/dump_text.hpp"
#include "io/lammps_dump.hpp"

namespace nbscope::dump {

// "ITEM: NUMBER OF ATOMS" -> "NUMBER OF ATOMS"; a view with a null data() for a line that is no ITEM.
std::string_view item_of(std::string_view line);
// The next word of [p, end) (blank-separated) into `word`; false when none is left.
inline bool next_word(const char*& p, const char* end, std::string_view& word) {
  while (p < end && (*p == ' ' || *p == '\t')) ++p;
  if (p == end) return false;
  const char* start = p;
  while (p < end && *p != ' ' && *p != '\t') ++p;
  word = std::string_view(start, static_cast<std::size_t>(p - start));
  return true;
}
// The words of `line`.
std::vector<std::string_view> words_of(std::string_view line);
// An integer column: `2753`, or with `allow_float` `2753.0` too (LAMMPS writes local ids as floats);
// Error "<at><what>: '2753.5' is not an integer" (and for an exponent: digits may have been lost).
std::int64_t parse_integer(std::string_view word, const std::string& at, const char* what, bool allow_float);
// The line after an ITEM that holds one integer (TIMESTEP, NUMBER OF ...); Error at a missing line.
std::int64_t integer_line(DumpText& text, const char* item);
// What the printed digits of a set of numbers say about their error (the precision band): the most
// significant digits any of them shows (the format's: 6 for %g, 17 for %.17g, whose trailing zeros
// are not printed; a fixed %.6f shows more for larger numbers) and the largest magnitude.
struct Digits {
  int significant = 0;
  double largest = 0;
  // Counts `word`'s digits (a number already parsed as `value`).
  void add(std::string_view word, double value);
  // Half a unit of the last digit of the largest number shown with `digits` significant digits
  // (default: its own most; 0 when every number was 0).
  [[nodiscard]] double half_unit(int digits = 0) const;
};

// ITEM: BOX BOUNDS's flags (`rest`, after "BOX BOUNDS") and its three lines of lo hi; Error for a
// triclinic box. `digits` gets the bounds' digits (they scale xs ys zs).
void read_box(DumpText& text, std::string_view rest, DumpBox& box, Digits& digits);

// Error "<where>: timestep T where timestep W was (the file changed since it was read?)" unless a
// frame read again at its place (`where`, timestep `got`) is the one indexed there (`wanted`).
void expect_indexed_timestep(const std::string& where, std::int64_t got, std::int64_t wanted);

// Sorts the frames of several files by timestep; Error for one timestep in two files.
template <class Frame>
void order_by_timestep(std::vector<Frame>& frames) {
  std::stable_sort(frames.begin(), frames.end(), [](const Frame& a, const Frame& b) { return a.timestep < b.timestep; });
  for (std::size_t k = 1; k < frames.size(); ++k)
    if (frames[k].timestep == frames[k - 1].timestep)
      throw Error(frames[k].where + ": timestep " + std::to_string(frames[k].timestep) + " is also in " + frames[k - 1].where +
                  " (two dumps of one run?)");
}

}  // namespace nbscope::dump

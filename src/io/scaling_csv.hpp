// nbscope io: the CSV of a scaling run (`nbscope scaling --output`, the Scaling panel's Export CSV,
// `nbscope headless --scaling FILE.csv`): header `algorithm,layout,n,ns_per_element,bytes_per_element,
// pairs,repeats,threads`, then one row per (detector, threads, layout, N). The header without
// `threads` (before --threads) still reads, every row on one thread.
#pragma once
#include <ostream>
#include <string>
#include <vector>

#include "core/scaling.hpp"

namespace nbscope {

// The header line, without its newline.
inline constexpr const char* kScalingCsvHeader = "algorithm,layout,n,ns_per_element,bytes_per_element,pairs,repeats,threads";
// The header of the files written before the threads column.
inline constexpr const char* kScalingCsvHeaderOneThread = "algorithm,layout,n,ns_per_element,bytes_per_element,pairs,repeats";

// Writes the header and `rows` to `out`, numbers in their shortest exact form.
void write_scaling_csv(std::ostream& out, const std::vector<ScalingRow>& rows);
// The same to `path`, whole or not at all; Error("<path>: cannot write: ...").
void write_scaling_csv(const std::string& path, const std::vector<ScalingRow>& rows);
// Parses a scaling CSV from memory (`where` names it); `#` comments and blank lines are skipped.
// Error("<where>:<line>: <what>") for a missing or other header, a wrong column count, an unknown
// detector or layout, N < 1, a time or size that is negative or not finite, a non-integer count,
// repeats < 1, threads not from 1 to kMaxThreads, a (detector, threads, layout, N) given twice;
// Error("<where>: no rows") for none.
std::vector<ScalingRow> parse_scaling_csv(const std::string& text, const std::string& where);
// Reads and parses `path` as parse_scaling_csv() does.
std::vector<ScalingRow> read_scaling_csv(const std::string& path);

}  // namespace nbscope

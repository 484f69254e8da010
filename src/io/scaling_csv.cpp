#include "io/scaling_csv.hpp"

#include <charconv>
#include <cmath>
#include <set>
#include <sstream>
#include <tuple>

#include "core/detector.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/csv.hpp"
#include "io/excerpt.hpp"
#include "io/input_file.hpp"

namespace nbscope {

namespace {

constexpr std::size_t kMaxScalingCsvBytes = std::size_t{64} << 20;
constexpr std::size_t kColumns = 8;

// The shortest text that reads back as exactly `v`.
std::string exact(double v) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : "nan";
}

// A whole number in [min, max]; Error(at + name + ...) otherwise.
std::int64_t parse_count(std::string_view f, const std::string& at, const char* name, std::int64_t min) {
  std::int64_t v = 0;
  const auto [ptr, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (f.empty() || ec != std::errc() || ptr != f.data() + f.size())
    throw Error(at + name + ": '" + excerpt(f) + "' is not a whole number");
  if (v < min) throw Error(at + name + ": " + std::to_string(v) + " is less than " + std::to_string(min));
  return v;
}

// A finite number >= 0.
double parse_amount(std::string_view f, const std::string& at, const char* name) {
  const double v = parse_finite_number(f, at, name);
  if (v < 0) throw Error(at + name + ": " + excerpt(f) + " is negative");
  return v;
}

}  // namespace

void write_scaling_csv(std::ostream& out, const std::vector<ScalingRow>& rows) {
  out << kScalingCsvHeader << '\n';
  for (const ScalingRow& r : rows)
    out << r.algorithm << ',' << r.layout << ',' << r.n << ',' << exact(r.ns_per_element) << ','
        << exact(r.bytes_per_element) << ',' << r.pairs << ',' << r.repeats << ',' << r.threads << '\n';
}

void write_scaling_csv(const std::string& path, const std::vector<ScalingRow>& rows) {
  write_file_atomically(path, [&](std::ostream& out) { write_scaling_csv(out, rows); });
}

std::vector<ScalingRow> parse_scaling_csv(const std::string& text, const std::string& where) {
  std::vector<ScalingRow> rows;
  std::set<std::tuple<std::string, int, std::string, std::int64_t>> seen;
  std::istringstream in(text);
  std::string raw;
  bool header = false;
  std::size_t columns = kColumns;  // 7 in a file of the header without threads
  for (long long line = 1; std::getline(in, raw); ++line) {
    check_line_length(raw, where, static_cast<std::size_t>(line));
    const std::string_view content = strip_comment(raw);
    if (content.empty()) continue;
    const std::string at = where + ":" + std::to_string(line) + ": ";
    if (!header) {
      if (content != kScalingCsvHeader && content != kScalingCsvHeaderOneThread)
        throw Error(at + "expected the header '" + kScalingCsvHeader + "' (a CSV of nbscope scaling)");
      if (content == kScalingCsvHeaderOneThread) columns = kColumns - 1;
      header = true;
      continue;
    }
    const std::vector<std::string_view> f = split_fields(content);
    if (f.size() != columns)
      throw Error(at + std::to_string(f.size()) + " columns; expected " + std::to_string(columns) + " (" +
                  (columns == kColumns ? kScalingCsvHeader : kScalingCsvHeaderOneThread) + ")");
    ScalingRow r;
    r.algorithm = std::string(f[0]);
    bool known = false;
    for (const DetectorInfo& d : detector_infos()) known = known || d.name == r.algorithm;
    if (!known) throw Error(at + "algorithm: '" + excerpt(f[0]) + "' is not one of " + detector_names());
    if (!parse_layout(f[1])) throw Error(at + "layout: '" + excerpt(f[1]) + "' is not one of " + layout_names());
    r.layout = std::string(f[1]);
    r.n = parse_count(f[2], at, "n", 1);
    if (r.n > kMaxElements) throw Error(at + "n: " + std::to_string(r.n) + " is more than " + std::to_string(kMaxElements));
    r.ns_per_element = parse_amount(f[3], at, "ns_per_element");
    r.bytes_per_element = parse_amount(f[4], at, "bytes_per_element");
    r.pairs = parse_count(f[5], at, "pairs", 0);
    r.repeats = static_cast<int>(std::min<std::int64_t>(parse_count(f[6], at, "repeats", 1), 1'000'000'000));
    if (columns == kColumns) {
      const std::int64_t threads = parse_count(f[7], at, "threads", 1);
      if (threads > kMaxThreads) throw Error(at + "threads: " + std::to_string(threads) + " is more than " + std::to_string(kMaxThreads));
      r.threads = static_cast<int>(threads);
    }
    if (!seen.emplace(r.algorithm, r.threads, r.layout, r.n).second)
      throw Error(at + series_name(r.algorithm, r.threads) + " " + r.layout + " N=" + std::to_string(r.n) + " is given twice");
    rows.push_back(std::move(r));
  }
  if (!header) throw Error(where + ": no header; expected '" + kScalingCsvHeader + "' (a CSV of nbscope scaling)");
  if (rows.empty()) throw Error(where + ": no rows (a scaling CSV has one row per detector, layout and N)");
  return rows;
}

std::vector<ScalingRow> read_scaling_csv(const std::string& path) {
  return parse_scaling_csv(read_input_file(path, "scaling CSV", kMaxScalingCsvBytes, kMaxLineBytes), path);
}

}  // namespace nbscope

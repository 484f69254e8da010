#include "io/csv.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/excerpt.hpp"
#include "io/input_file.hpp"
#include "io/plural.hpp"

namespace nbscope {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split_commas(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

bool is_name(std::string_view s) {
  if (s.empty() || !std::isalpha(static_cast<unsigned char>(s.front()))) return false;
  for (char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  // "nan" and "inf" are numbers that are refused below, not column names.
  std::string lower(s);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower != "nan" && lower != "inf" && lower != "infinity";
}

const char* const kColumnNames2[] = {"x", "y", "r"};
const char* const kColumnNames3[] = {"x", "y", "z", "r"};

}  // namespace

std::string_view strip_comment(std::string_view line) {
  const std::size_t hash = line.find('#');
  if (hash != std::string_view::npos) line = line.substr(0, hash);
  return trim(line);
}

std::vector<std::string_view> split_words(std::string_view line, bool commas_too) {
  const auto separator = [&](char c) { return std::isspace(static_cast<unsigned char>(c)) || (commas_too && c == ','); };
  std::vector<std::string_view> out;
  std::size_t k = 0;
  while (k < line.size()) {
    while (k < line.size() && separator(line[k])) ++k;
    const std::size_t start = k;
    while (k < line.size() && !separator(line[k])) ++k;
    if (k > start) out.push_back(line.substr(start, k - start));
  }
  return out;
}

std::vector<std::string_view> split_fields(std::string_view line) { return split_commas(line); }

void check_line_length(std::string_view line, const std::string& where, std::size_t line_no) {
  if (line.size() > kMaxLineBytes)
    throw Error(where + ":" + std::to_string(line_no) + ": a line of " + std::to_string(line.size()) + " bytes '" + excerpt(line) +
                "'; lines are at most " + std::to_string(kMaxLineBytes) + " bytes");
}

double parse_finite_number(std::string_view f, const std::string& at, const char* name) {
  if (f.size() > kMaxNumberBytes)
    throw Error(at + name + ": '" + excerpt(f) + "' (" + std::to_string(f.size()) + " characters) is not a number of at most " +
                std::to_string(kMaxNumberBytes) + " characters");
  double v = 0;
  const auto [ptr, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (f.empty() || ec == std::errc::invalid_argument || ptr != f.data() + f.size())
    throw Error(at + name + ": '" + excerpt(f) + "' is not a number");
  if (ec == std::errc::result_out_of_range || !std::isfinite(v))
    throw Error(at + name + ": '" + excerpt(f) + "' is not a finite number");
  return v;
}

void parse_element_row(const std::vector<std::string_view>& fields, const std::string& at, std::array<double, 4>& out) {
  if (fields.size() != 3 && fields.size() != 4)
    throw Error(at + plural(static_cast<long long>(fields.size()), "column") + "; expected 3 (x,y,r) or 4 (x,y,z,r)");
  const char* const* names = fields.size() == 3 ? kColumnNames2 : kColumnNames3;
  for (std::size_t c = 0; c < fields.size(); ++c)
    if (fields[c].empty())
      throw Error(at + "column " + std::to_string(c + 1) + " (" + names[c] + ") is empty" +
                  (c + 1 == fields.size() ? " (a trailing comma?)" : ""));
  for (std::size_t c = 0; c < fields.size(); ++c) {
    const double v = parse_finite_number(fields[c], at, names[c]);
    const std::string text(fields[c]);
    if (c + 1 == fields.size()) {
      if (!(v > 0)) throw Error(at + "r: radius must be > 0, got " + text);
      if (v < kMinRadius || v > kMaxRadius)
        throw Error(at + "r: " + text + " is outside the supported radii 1e-100 to 1e100");
    } else if (std::abs(v) > kMaxCoordinate) {
      throw Error(at + names[c] + ": " + text + " is outside the supported coordinates -1e100 to 1e100");
    }
    out[c] = v;
  }
}

Elements parse_elements_csv(const std::string& text, const std::string& where) {
  const std::size_t bom = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;  // spreadsheets write a UTF-8 byte order mark
  if (trim(std::string_view(text).substr(bom)).empty()) throw Error(where + ":1: empty file (expected rows of x,y,r or x,y,z,r)");
  Elements e;
  e.dim = 0;
  std::vector<double> cols[4];
  std::size_t line_no = 0;
  bool seen_row_or_header = false;
  std::size_t header_line = 0;
  std::size_t pos = bom;
  while (pos <= text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + pos, end - pos);
    pos = end + 1;
    ++line_no;
    check_line_length(line, where, line_no);
    line = strip_comment(line);
    if (line.empty()) {
      if (end == text.size()) break;
      continue;
    }
    const std::string at = where + ":" + std::to_string(line_no) + ": ";
    const std::vector<std::string_view> fields = split_commas(line);
    if (!seen_row_or_header && is_name(fields.front())) {
      for (std::string_view f : fields)
        if (!is_name(f)) throw Error(at + "header mixes names and numbers: '" + excerpt(f) + "'");
      if (fields.size() != 3 && fields.size() != 4)
        throw Error(at + "header has " + plural(static_cast<long long>(fields.size()), "column") + "; expected x,y,r or x,y,z,r");
      e.dim = fields.size() == 3 ? 2 : 3;  // the header fixes the dimension, as a first row would
      header_line = line_no;
      seen_row_or_header = true;
      continue;
    }
    seen_row_or_header = true;
    if (fields.size() != 3 && fields.size() != 4)
      throw Error(at + plural(static_cast<long long>(fields.size()), "column") + "; expected 3 (x,y,r) or 4 (x,y,z,r)");
    const int dim = fields.size() == 3 ? 2 : 3;
    if (e.dim == 0) e.dim = dim;
    if (dim != e.dim)
      throw Error(at + plural(static_cast<long long>(fields.size()), "column") + ", but " +
                  (header_line != 0 && cols[0].empty() ? "the header on line " + std::to_string(header_line) + " has "
                                                       : std::string("the first row had ")) +
                  std::to_string(e.dim + 1));
    if (static_cast<std::int64_t>(cols[0].size()) >= kMaxElements)
      throw Error(at + "more than " + std::to_string(kMaxElements) + " elements");
    std::array<double, 4> row{};
    parse_element_row(fields, at, row);
    for (std::size_t c = 0; c < fields.size(); ++c) cols[c].push_back(row[c]);
    if (end == text.size()) break;
  }
  if (e.dim == 0) e.dim = 2;
  const auto n = static_cast<Eigen::Index>(cols[0].size());
  auto column = [&](int c) { return Eigen::Map<const Eigen::ArrayXd>(cols[c].data(), n); };
  e.x = column(0);
  e.y = column(1);
  if (e.dim == 3) {
    e.z = column(2);
    e.r = column(3);
  } else {
    e.r = column(2);
  }
  return e;
}

Elements read_elements_csv(const std::string& path) {
  return parse_elements_csv(read_input_file(path, "elements file", kMaxElementsBytes, kMaxLineBytes), path);
}

void write_pairs_csv(std::ostream& out, const PairList& sorted_pairs) {
  // In chunks: fifty million pairs as one string would take 600 MB more than the pairs themselves.
  constexpr std::size_t kChunk = std::size_t{1} << 16;
  std::string buf = "i,j\n";
  buf.reserve(kChunk + 32);
  char num[32];
  for (const Pair& p : sorted_pairs) {
    auto r1 = std::to_chars(num, num + sizeof num, p.i);
    buf.append(num, r1.ptr);
    buf.push_back(',');
    auto r2 = std::to_chars(num, num + sizeof num, p.j);
    buf.append(num, r2.ptr);
    buf.push_back('\n');
    if (buf.size() >= kChunk) {
      out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
      buf.clear();
    }
  }
  out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
}

void write_pairs_csv(const std::string& path, const PairList& sorted_pairs) {
  write_file_atomically(path, [&](std::ostream& out) { write_pairs_csv(out, sorted_pairs); });
}

}  // namespace nbscope

#include "io/csv.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string_view>
#include <utility>
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

// ---- ElementColumns --------------------------------------------------------------------------

ElementColumns::ElementColumns(int count) : count_(count) {}

void ElementColumns::push(const std::array<double, 4>& row) {
  if (size_ == capacity_) {
    capacity_ = std::max<Eigen::Index>(1024, capacity_ * 2);
    for (int c = 0; c < count_; ++c) cols_[c].conservativeResize(capacity_);
  }
  for (int c = 0; c < count_; ++c) cols_[c][size_] = row[static_cast<std::size_t>(c)];
  ++size_;
}

Eigen::ArrayXd ElementColumns::take(int c) {
  cols_[c].conservativeResize(size_);
  return std::move(cols_[c]);
}

void ElementColumns::clear() {
  for (auto& col : cols_) col.resize(0);
  size_ = capacity_ = 0;
}

bool parse_plain_row(std::string_view line, int& count, std::array<double, 4>& out) {
  count = 0;
  std::size_t start = 0;
  for (;;) {
    if (count == 4) return false;
    const std::size_t comma = line.find(',', start);
    const std::string_view f = trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (f.empty() || f.size() > kMaxNumberBytes) return false;
    double v = 0;
    const auto [ptr, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
    if (ec != std::errc() || ptr != f.data() + f.size() || !std::isfinite(v)) return false;
    out[static_cast<std::size_t>(count++)] = v;
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  if (count < 3) return false;
  for (int c = 0; c + 1 < count; ++c)
    if (std::abs(out[static_cast<std::size_t>(c)]) > kMaxCoordinate) return false;
  const double r = out[static_cast<std::size_t>(count - 1)];
  return r >= kMinRadius && r <= kMaxRadius;
}

namespace {

// ELEMENTS.csv one line at a time: from memory or as a file's lines arrive, so that a file with
// too many rows is refused at the first row past the limit, having held only the rows before it.
class ElementsCsvParser {
 public:
  ElementsCsvParser(const std::string& where, std::int64_t max_elements) : where_(where), max_elements_(max_elements) {}

  // Line `line_no` (1-based), without its newline.
  void line(std::string_view raw, std::size_t line_no) {
    if (line_no == 1 && raw.rfind("\xEF\xBB\xBF", 0) == 0) raw.remove_prefix(3);  // spreadsheets write a UTF-8 byte order mark
    const std::string_view line = strip_comment(raw);
    if (!seen_text_ && !trim(raw).empty()) seen_text_ = true;
    if (line.empty()) return;
    if (dim_ != 0 && seen_row_or_header_) {
      int count = 0;
      std::array<double, 4> row{};
      if (parse_plain_row(line, count, row) && count == dim_ + 1 && cols_.size() < max_elements_) {
        cols_.push(row);
        return;
      }
    }
    full_row(line, line_no);
  }

  // The elements read. Error "empty file" when every line was blank.
  Elements finish() {
    if (!seen_text_) throw Error(where_ + ":1: empty file (expected rows of x,y,r or x,y,z,r)");
    Elements e;
    e.dim = dim_ == 0 ? 2 : dim_;
    e.x = cols_.take(0);
    e.y = cols_.take(1);
    if (e.dim == 3) {
      e.z = cols_.take(2);
      e.r = cols_.take(3);
    } else {
      e.r = cols_.take(2);
    }
    return e;
  }

 private:
  // A header, or a row with anything unusual: read with a message for every way it can be wrong.
  void full_row(std::string_view line, std::size_t line_no) {
    const std::string at = where_ + ":" + std::to_string(line_no) + ": ";
    const std::vector<std::string_view> fields = split_commas(line);
    if (!seen_row_or_header_ && is_name(fields.front())) {
      for (std::string_view f : fields)
        if (!is_name(f)) throw Error(at + "header mixes names and numbers: '" + excerpt(f) + "'");
      if (fields.size() != 3 && fields.size() != 4)
        throw Error(at + "header has " + plural(static_cast<long long>(fields.size()), "column") + "; expected x,y,r or x,y,z,r");
      set_dim(fields.size() == 3 ? 2 : 3);  // the header fixes the dimension, as a first row would
      header_line_ = line_no;
      seen_row_or_header_ = true;
      return;
    }
    seen_row_or_header_ = true;
    if (fields.size() != 3 && fields.size() != 4)
      throw Error(at + plural(static_cast<long long>(fields.size()), "column") + "; expected 3 (x,y,r) or 4 (x,y,z,r)");
    const int dim = fields.size() == 3 ? 2 : 3;
    if (dim_ == 0) set_dim(dim);
    if (dim != dim_)
      throw Error(at + plural(static_cast<long long>(fields.size()), "column") + ", but " +
                  (header_line_ != 0 && cols_.size() == 0 ? "the header on line " + std::to_string(header_line_) + " has "
                                                          : std::string("the first row had ")) +
                  std::to_string(dim_ + 1));
    if (cols_.size() >= max_elements_) throw Error(at + "more than " + std::to_string(max_elements_) + " elements");
    std::array<double, 4> row{};
    parse_element_row(fields, at, row);
    cols_.push(row);
  }

  void set_dim(int dim) {
    dim_ = dim;
    cols_ = ElementColumns(dim + 1);
  }

  const std::string& where_;
  std::int64_t max_elements_;
  int dim_ = 0;  // fixed by the header or the first row
  bool seen_text_ = false;
  bool seen_row_or_header_ = false;
  std::size_t header_line_ = 0;
  ElementColumns cols_{3};
};

}  // namespace

Elements parse_elements_csv(const std::string& text, const std::string& where, std::int64_t max_elements) {
  ElementsCsvParser parser(where, max_elements);
  std::size_t line_no = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string_view line(text.data() + pos, end - pos);
    pos = end + 1;
    ++line_no;
    check_line_length(line, where, line_no);
    parser.line(line, line_no);
  }
  return parser.finish();
}

namespace {

// The line of the first row past `max_elements` in `path`, or 0 when there is none: a scan for line
// ends, comments and the header, with no number parsed and no row held. With `copy`, every line
// read is appended to it too (a pipe, which cannot be read twice).
std::size_t first_row_past(const std::string& path, std::int64_t max_elements, std::size_t max_bytes, ScratchFile* copy = nullptr) {
  InputLines lines(path, "elements file", max_bytes, kMaxLineBytes);
  std::string_view line;
  std::int64_t rows = 0;
  bool first = true;
  std::string block;  // lines gathered for the copy: one write a block, not a line
  while (lines.next(line)) {
    if (copy != nullptr) {
      block.append(line).push_back('\n');
      if (block.size() >= (std::size_t{1} << 20)) {
        copy->write(block);
        block.clear();  // its capacity kept: a fresh megabyte each time costs page faults
      }
    }
    if (lines.line_number() == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.remove_prefix(3);
    const std::string_view content = strip_comment(line);
    if (content.empty()) continue;
    if (std::exchange(first, false) && is_name(trim(content.substr(0, content.find(','))))) continue;  // the header
    if (++rows > max_elements) return lines.line_number();
  }
  if (copy != nullptr) copy->write(block);
  return 0;
}

}  // namespace

Elements read_elements_csv(const std::string& path, std::int64_t max_elements, std::size_t max_bytes) {
  // A file that can hold more rows than the limit (a row takes at least 6 bytes, "0,0,1\n") is
  // counted first: one with too many is then refused in seconds, holding nothing, instead of after
  // holding max_elements rows (2.4 GB at 1e8). A pipe or device cannot be read twice: it is copied
  // to an unnamed scratch file (disk, not memory) while its rows are counted, then read from there.
  const auto too_many = [&](std::size_t line) {
    return Error(path + ":" + std::to_string(line) + ": more than " + std::to_string(max_elements) + " elements");
  };
  std::error_code ec;
  std::unique_ptr<ScratchFile> spool;
  if (std::filesystem::is_regular_file(path, ec)) {
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && (size + 1) / 6 > static_cast<std::uintmax_t>(max_elements))
      if (const std::size_t line = first_row_past(path, max_elements, max_bytes); line != 0) throw too_many(line);
  } else if (std::filesystem::exists(path, ec) && !std::filesystem::is_directory(path, ec)) {
    spool = std::make_unique<ScratchFile>(path);
    if (const std::size_t line = first_row_past(path, max_elements, max_bytes, spool.get()); line != 0) throw too_many(line);
  }
  InputLines lines(path, "elements file", max_bytes, kMaxLineBytes, spool ? spool->reopen_path() : std::string());
  ElementsCsvParser parser(path, max_elements);
  std::string_view line;
  while (lines.next(line)) parser.line(line, lines.line_number());
  return parser.finish();
}

void write_pairs_csv(std::ostream& out, const PairList& sorted_pairs, const std::vector<std::int64_t>& ids) {
  // In chunks: fifty million pairs as one string would take 600 MB more than the pairs themselves.
  constexpr std::size_t kChunk = std::size_t{1} << 16;
  // A dump's pairs name atoms by id, and say so: verify --pairs reads an `id1,id2` file as ids.
  std::string buf = ids.empty() ? "i,j\n" : "id1,id2\n";
  buf.reserve(kChunk + 32);
  char num[32];
  for (const Pair& p : sorted_pairs) {
    // A dump's rows ascend by id, so pairs sorted by row are sorted by id too.
    auto r1 = ids.empty() ? std::to_chars(num, num + sizeof num, p.i) : std::to_chars(num, num + sizeof num, ids[static_cast<std::size_t>(p.i)]);
    buf.append(num, r1.ptr);
    buf.push_back(',');
    auto r2 = ids.empty() ? std::to_chars(num, num + sizeof num, p.j) : std::to_chars(num, num + sizeof num, ids[static_cast<std::size_t>(p.j)]);
    buf.append(num, r2.ptr);
    buf.push_back('\n');
    if (buf.size() >= kChunk) {
      out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
      buf.clear();
    }
  }
  out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
}

void write_pairs_csv(const std::string& path, const PairList& sorted_pairs, const std::vector<std::int64_t>& ids) {
  write_file_atomically(path, [&](std::ostream& out) { write_pairs_csv(out, sorted_pairs, ids); });
}

}  // namespace nbscope

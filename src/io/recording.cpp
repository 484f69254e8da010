// Index: helpers (words, numbers) | parse_recording | read_recording | RecordingWriter.
#include "io/recording.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/csv.hpp"
#include "io/input_file.hpp"
#include "io/plural.hpp"

namespace nbscope {

namespace {

// Splits `line` at white space.
std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t k = 0;
  while (k < line.size()) {
    while (k < line.size() && std::isspace(static_cast<unsigned char>(line[k]))) ++k;
    const std::size_t start = k;
    while (k < line.size() && !std::isspace(static_cast<unsigned char>(line[k]))) ++k;
    if (k > start) out.push_back(line.substr(start, k - start));
  }
  return out;
}

// An integer in [min, max] from `f`; Error(at + name + ...) otherwise.
std::int64_t parse_integer(std::string_view f, const std::string& at, const char* name, std::int64_t min, std::int64_t max) {
  std::int64_t v = 0;
  const auto [ptr, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (f.empty() || ec != std::errc() || ptr != f.data() + f.size())
    throw Error(at + name + ": '" + std::string(f) + "' is not an integer");
  if (v < min || v > max)
    throw Error(at + name + ": " + std::string(f) + " is out of range [" + std::to_string(min) + ", " + std::to_string(max) + "]");
  return v;
}

// The single value of a header line "key VALUE"; Error when it has none or more than one.
std::string_view header_value(const std::vector<std::string_view>& words, const std::string& at, const char* form) {
  if (words.size() != 2) throw Error(at + std::string(words.front()) + ": expected '" + form + "'");
  return words[1];
}

// "A,B" into two fields; Error otherwise.
std::vector<std::string_view> two_fields(std::string_view value, const std::string& at, const char* key, const char* form) {
  std::vector<std::string_view> f = split_fields(value);
  if (f.size() != 2) throw Error(at + key + ": '" + std::string(value) + "' is not " + form);
  return f;
}

std::string shortest(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// Moves the collected columns into the frame's Elements.
void finish_frame(RecordedFrame& frame, std::vector<double> (&cols)[3]) {
  const auto n = static_cast<Eigen::Index>(cols[0].size());
  frame.elements.dim = 2;
  frame.elements.x = Eigen::Map<const Eigen::ArrayXd>(cols[0].data(), n);
  frame.elements.y = Eigen::Map<const Eigen::ArrayXd>(cols[1].data(), n);
  frame.elements.r = Eigen::Map<const Eigen::ArrayXd>(cols[2].data(), n);
  for (auto& c : cols) c.clear();
}

}  // namespace

// ---- parse_recording ------------------------------------------------------------------------

Recording parse_recording(const std::string& text, const std::string& where, std::int64_t max_frames) {
  Recording rec;
  rec.path = where;
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw Error(where + ":1: empty file (expected 'nbsrec 1', then frames)");
  bool seen_version = false;
  std::vector<double> cols[3];
  std::size_t line_no = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string_view line = strip_comment(std::string_view(text.data() + pos, end - pos));
    pos = end + 1;
    ++line_no;
    if (line.empty()) continue;
    const std::string at = where + ":" + std::to_string(line_no) + ": ";
    const std::vector<std::string_view> words = words_of(line);
    const std::string_view key = words.front();
    if (!seen_version) {
      if (key != "nbsrec")
        throw Error(at + "expected 'nbsrec 1' as the first line (an nbscope recording), got '" + std::string(line) + "'");
      if (words.size() != 2 || words[1] != "1")
        throw Error(at + "'" + std::string(line) + "': this nbscope reads version 1 ('nbsrec 1') only");
      seen_version = true;
      continue;
    }
    const bool in_header = rec.frames.empty();
    if (key == "cell_size" || key == "origin" || key == "cells") {
      if (!in_header) throw Error(at + std::string(key) + ": header lines come before the first frame");
      if (key == "cell_size") {
        const double d = parse_finite_number(header_value(words, at, "cell_size D"), at, "cell_size");
        if (!(d > 0)) throw Error(at + "cell_size: must be > 0, got " + std::string(words[1]));
        rec.grid.cell_size = d;
      } else if (key == "origin") {
        const auto f = two_fields(header_value(words, at, "origin X,Y"), at, "origin", "X,Y");
        rec.grid.origin = std::array<double, 3>{parse_finite_number(f[0], at, "origin x"), parse_finite_number(f[1], at, "origin y"), 0};
      } else {
        const auto f = two_fields(header_value(words, at, "cells NX,NY"), at, "cells", "NX,NY");
        rec.grid.cells = std::array<std::int64_t, 3>{parse_integer(f[0], at, "cells nx", 1, std::int64_t{1} << 24),
                                                     parse_integer(f[1], at, "cells ny", 1, std::int64_t{1} << 24), 1};
      }
      continue;
    }
    if (key == "frame") {
      if (words.size() != 3) throw Error(at + "expected 'frame NUMBER TIME', got '" + std::string(line) + "'");
      const std::int64_t number = parse_integer(words[1], at, "frame number", 0, std::numeric_limits<std::int64_t>::max());
      const double time = parse_finite_number(words[2], at, "frame time");
      if (!rec.frames.empty()) {
        const RecordedFrame& last = rec.frames.back();
        if (number <= last.number)
          throw Error(at + "frame " + std::to_string(number) + " after frame " + std::to_string(last.number) +
                      ": frame numbers must increase");
        if (time < last.time)
          throw Error(at + "frame " + std::to_string(number) + ": time " + shortest(time) + " is before frame " +
                      std::to_string(last.number) + "'s " + shortest(last.time) + ": times must not decrease");
        finish_frame(rec.frames.back(), cols);
        if (static_cast<std::int64_t>(rec.frames.size()) >= max_frames) return rec;
      }
      rec.frames.push_back({number, time, {}});
      continue;
    }
    if (std::isalpha(static_cast<unsigned char>(key.front())) && line.find(',') == std::string_view::npos)
      throw Error(at + "unknown line '" + std::string(line) + "' (expected frame, cell_size, origin, cells or a row x,y,r)");
    if (in_header) throw Error(at + "an element row before the first 'frame NUMBER TIME' line");
    const std::vector<std::string_view> fields = split_fields(line);
    if (fields.size() == 4) throw Error(at + "4 columns (x,y,z,r): replay is 2D, rows are x,y,r");
    if (fields.size() != 3) throw Error(at + plural(static_cast<long long>(fields.size()), "column") + "; expected 3 (x,y,r)");
    if (static_cast<std::int64_t>(cols[0].size()) >= kMaxElements)
      throw Error(at + "more than " + std::to_string(kMaxElements) + " elements in one frame");
    std::array<double, 4> row{};
    parse_element_row(fields, at, row);
    if (rec.grid.cell_size && 2 * row[2] > *rec.grid.cell_size)
      throw Error(at + "r: diameter " + shortest(2 * row[2]) + " is larger than the header's cell_size " + shortest(*rec.grid.cell_size) +
                  " (contacts could skip a cell)");
    for (int c = 0; c < 3; ++c) cols[c].push_back(row[static_cast<std::size_t>(c)]);
  }
  if (!seen_version) throw Error(where + ":" + std::to_string(line_no) + ": only comments (expected 'nbsrec 1', then frames)");
  if (rec.frames.empty())
    throw Error(where + ":" + std::to_string(line_no) + ": no frames (expected 'frame NUMBER TIME' lines with x,y,r rows)");
  finish_frame(rec.frames.back(), cols);
  return rec;
}

// ---- read_recording -------------------------------------------------------------------------

Recording read_recording(const std::string& path, std::int64_t max_frames) {
  return parse_recording(read_input_file(path, "recording", kMaxRecordingBytes), path, max_frames);
}

// ---- RecordingWriter ------------------------------------------------------------------------

struct RecordingWriter::Impl {
  AtomicFileWriter file;
  std::string buf;
  explicit Impl(const std::string& path) : file(path) {}

  void append(double v) {
    char num[32];
    const auto r = std::to_chars(num, num + sizeof num, v);  // shortest text that reads back exactly
    buf.append(num, r.ptr);
  }
  void flush() {
    file.stream().write(buf.data(), static_cast<std::streamsize>(buf.size()));
    buf.clear();
  }
};

RecordingWriter::RecordingWriter(const std::string& path, const GridOptions& grid, const std::string& comment)
    : impl_(std::make_unique<Impl>(path)) {
  std::string& b = impl_->buf;
  b = "nbsrec 1\n";
  std::size_t start = 0;
  while (start < comment.size()) {
    const std::size_t nl = std::min(comment.find('\n', start), comment.size());
    b += "# " + comment.substr(start, nl - start) + "\n";
    start = nl + 1;
  }
  if (grid.cell_size) {
    b += "cell_size ";
    impl_->append(*grid.cell_size);
    b += "\n";
  }
  if (grid.origin) {
    b += "origin ";
    impl_->append((*grid.origin)[0]);
    b += ",";
    impl_->append((*grid.origin)[1]);
    b += "\n";
  }
  if (grid.cells) b += "cells " + std::to_string((*grid.cells)[0]) + "," + std::to_string((*grid.cells)[1]) + "\n";
  impl_->flush();
}

RecordingWriter::~RecordingWriter() = default;

void RecordingWriter::write_frame(std::int64_t number, double time, const Elements& e) {
  if (e.dim != 2) throw Error("--record: the elements are 3D; a recording holds 2D frames only");
  std::string& b = impl_->buf;
  b += "frame " + std::to_string(number) + " ";
  impl_->append(time);
  b += "\n";
  b.reserve(b.size() + static_cast<std::size_t>(e.size()) * 40);
  for (Eigen::Index k = 0; k < e.size(); ++k) {
    impl_->append(e.x[k]);
    b += ",";
    impl_->append(e.y[k]);
    b += ",";
    impl_->append(e.r[k]);
    b += "\n";
  }
  impl_->flush();
}

void RecordingWriter::commit() { impl_->file.commit(); }

}  // namespace nbscope

// Reading .nbsrec (recording.hpp; the writer is recording_writer.cpp).
// Index: helpers (words, numbers) | parse_recording | read_recording | frames read as shown.
#include "io/recording.hpp"

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "core/error.hpp"
#include "io/csv.hpp"
#include "io/excerpt.hpp"
#include "io/input_file.hpp"
#include "io/plural.hpp"
#include "io/recorded_frames.hpp"

namespace nbscope {

namespace {

// The header lines, each allowed once ("nbsrec" first).
constexpr std::array<std::string_view, 6> kHeaderKeys = {"nbsrec", "cell_size", "origin", "cells", "base", "dim"};
std::size_t header_index(std::string_view key) {
  std::size_t h = 0;
  while (h < kHeaderKeys.size() && kHeaderKeys[h] != key) ++h;
  return h;
}

// An integer in [min, max] from `f`; Error(at + name + ...) otherwise.
std::int64_t parse_integer(std::string_view f, const std::string& at, const char* name, std::int64_t min, std::int64_t max) {
  std::int64_t v = 0;
  const auto [ptr, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (f.empty() || ec != std::errc() || ptr != f.data() + f.size())
    throw Error(at + name + ": '" + excerpt(f) + "' is not an integer");
  if (v < min || v > max)
    throw Error(at + name + ": " + excerpt(f) + " is out of range [" + std::to_string(min) + ", " + std::to_string(max) + "]");
  return v;
}

// The single value of a header line "key VALUE"; Error when it has none or more than one.
std::string_view header_value(const std::vector<std::string_view>& words, const std::string& at, const char* form) {
  if (words.size() != 2) throw Error(at + excerpt(words.front()) + ": expected '" + form + "'");
  return words[1];
}

// "A,B" or "A,B,C" into its fields (x, y and, in a 3D recording, z); Error otherwise.
std::vector<std::string_view> axis_fields(std::string_view value, const std::string& at, const char* key, const char* form) {
  std::vector<std::string_view> f = split_fields(value);
  if (f.size() != 2 && f.size() != 3) throw Error(at + key + ": '" + excerpt(value) + "' is not " + form);
  return f;
}

std::string shortest(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// Moves the collected columns (x, y, [z,] r) into the frame's Elements of dimension `dim`.
void finish_frame(RecordedFrame& frame, ElementColumns& cols, int dim) {
  frame.elements.dim = dim;
  frame.elements.x = cols.take(0);
  frame.elements.y = cols.take(1);
  if (dim == 3) frame.elements.z = cols.take(2);
  frame.elements.r = cols.take(dim);
  cols.clear();
}

// What the parser knows of the frame being read, for its pairs block.
struct FrameState {
  std::size_t line = 0;       // of its `frame` line: messages about the whole frame name it
  bool has_pairs = false;     // its `pairs` line was seen: every data row after it is a pair
};

// "frame 3 has no pairs block, but frame 0 has one: ..." when `frame` disagrees with the first
// frame (every frame has a pairs block, or none); `first_has` is the first frame's.
void check_all_or_none(const Recording& rec, const FrameState& state, bool first_has, const std::string& where) {
  if (rec.frames.size() < 2 || state.has_pairs == first_has) return;
  const std::string at = where + ":" + std::to_string(state.line) + ": ";
  const std::string number = std::to_string(rec.frames.back().number), first = std::to_string(rec.frames.front().number);
  throw Error(at + "frame " + number + (state.has_pairs ? " has a pairs block, but frame " + first + " has none"
                                                        : " has no pairs block, but frame " + first + " has one") +
              ": give every frame its pairs, or none");
}

// One row `i,j` of frame `frame`'s pairs block, 0-based, into its pairs; Error (at) for anything
// but two integers naming elements of the frame (`n` of them, numbered from `base`).
void parse_pair_row(std::string_view line, const std::string& at, int base, std::int64_t n, RecordedFrame& frame) {
  const std::vector<std::string_view> f = split_fields(line);
  if (f.size() == 3 || f.size() == 4)
    throw Error(at + "an element row after frame " + std::to_string(frame.number) +
                "'s 'pairs' line (a frame's element rows come before its pairs)");
  if (f.size() != 2) throw Error(at + "pair row '" + excerpt(line) + "': expected i,j (two integers)");
  const std::string text = excerpt(f[0]) + "," + excerpt(f[1]);
  std::int64_t ij[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    const std::string_view v = f[static_cast<std::size_t>(k)];
    const auto [ptr, ec] = std::from_chars(v.data(), v.data() + v.size(), ij[k]);
    if (v.empty() || ec == std::errc::invalid_argument || ptr != v.data() + v.size())
      throw Error(at + "pair row '" + text + "': '" + excerpt(v) + "' is not an integer");
    // Too large for 64 bits is out of range like any other index the frame does not have.
    if (ec == std::errc::result_out_of_range || ij[k] < base || ij[k] >= n + base)
      throw Error(at + "pair " + text + ": frame " + std::to_string(frame.number) + " has " + plural(n, "element") +
                  (n == 0 ? "" : " (" + std::to_string(base) + ".." + std::to_string(n - 1 + base) + ")"));
  }
  if (frame.pairs.size() >= kDefaultMaxPairs)
    throw Error(at + "more than " + std::to_string(kDefaultMaxPairs) + " pairs in one frame");
  frame.pairs.push_back({static_cast<ElementId>(ij[0] - base), static_cast<ElementId>(ij[1] - base)});
}

}  // namespace

// ---- parse_recording ------------------------------------------------------------------------

namespace {

// A recording one line at a time: from memory or as a file's lines arrive, so that reading stops
// after the frames wanted (an endless pipe included) and a limit passed stops it at that line.
class RecordingParser {
 public:
  // `keep_rows` false: each frame's rows are counted, not parsed (read_recorded_frames), its place kept.
  RecordingParser(const std::string& where, std::int64_t max_frames, std::size_t frame_limit, bool keep_rows = true)
      : where_(where), max_frames_(max_frames), frame_limit_(frame_limit), keep_rows_(keep_rows) {
    rec_.path = where;
  }
  // One frame's block (its `frame` line first) of a recording whose header was read: `header`'s facts,
  // its `dim` line on `dim_line` (0: none), for messages.
  RecordingParser(const Recording& header, const std::string& where, std::size_t dim_line) : where_(where), max_frames_(1), frame_limit_(1) {
    first_line_[kDimKey] = dim_line;
    rec_.path = header.path;
    rec_.dim = header.dim;
    rec_.grid = header.grid;
    rec_.pair_base = header.pair_base;
    seen_text_ = seen_version_ = true;
  }

  // Line `line_no` (1-based) starting at byte `offset`, without its newline; false once `max_frames`
  // frames are complete (this line starts the next one, which is not read).
  bool line(std::string_view raw, std::size_t line_no, std::size_t offset = 0) {
    last_line_ = line_no;
    offset_ = offset;
    if (!seen_text_ && raw.find_first_not_of(" \t\r") != std::string_view::npos) seen_text_ = true;
    if (rec_.frames.empty()) keep_comment(raw);
    const std::string_view line = strip_comment(raw);
    if (line.empty()) return true;
    if (plain_element_row(line)) return true;
    const std::string at = where_ + ":" + std::to_string(line_no) + ": ";
    const std::vector<std::string_view> words = split_words(line);
    const std::string_view key = words.front();
    if (!seen_version_) {
      if (key != "nbsrec")
        throw Error(at + "expected 'nbsrec 1' as the first line (an nbscope recording), got '" + excerpt(line) + "'");
      if (words.size() != 2 || words[1] != "1")
        throw Error(at + "'" + excerpt(line) + "': this nbscope reads version 1 ('nbsrec 1') only");
      seen_version_ = true;
      first_line_[0] = line_no;
      return true;
    }
    const bool in_header = rec_.frames.empty();
    if (const std::size_t h = header_index(key); h < kHeaderKeys.size()) {
      header_line(words, key, h, at, line_no, in_header);
      return true;
    }
    if (key == "frame") return frame_line(words, line, at, line_no);
    if (key == "pairs") {
      if (words.size() != 1) throw Error(at + "expected 'pairs' alone on its line, got '" + excerpt(line) + "'");
      if (in_header) throw Error(at + "a 'pairs' line before the first 'frame NUMBER TIME' line");
      if (state_.has_pairs)
        throw Error(at + "a second 'pairs' line in frame " + std::to_string(rec_.frames.back().number) + " (one pairs block a frame)");
      state_.has_pairs = true;
      // A block where the first frame has none is refused here, before its rows are read.
      if (rec_.frames.size() > 1) check_all_or_none(rec_, state_, rec_.has_pairs, where_);
      return true;
    }
    if (std::isalpha(static_cast<unsigned char>(key.front())) && line.find(',') == std::string_view::npos)
      throw Error(at + "unknown line '" + excerpt(line) + "' (expected frame, pairs, dim, cell_size, origin, cells, base or a row " +
                  (rec_.dim == 3 ? "x,y,z,r)" : "x,y,r)"));
    if (in_header) throw Error(at + "an element row before the first 'frame NUMBER TIME' line");
    if (state_.has_pairs) {
      parse_pair_row(line, at, rec_.pair_base, rows(), rec_.frames.back());
      return true;
    }
    element_row(line, at);
    return true;
  }

  // Where each frame's `frame` line starts (byte, line), and where the last frame ends (the byte of
  // the line that stopped the read, else `end`).
  [[nodiscard]] const std::vector<std::array<std::size_t, 2>>& places() const { return places_; }
  [[nodiscard]] std::size_t stop_offset(std::size_t end) const { return stopped_ ? offset_ : end; }

  // The recording read (at most max_frames frames).
  Recording finish() {
    if (!stopped_) {
      if (!seen_text_) throw Error(where_ + ":1: empty file (expected 'nbsrec 1', then frames)");
      if (!seen_version_) throw Error(where_ + ":" + std::to_string(last_line_) + ": only comments (expected 'nbsrec 1', then frames)");
      if (rec_.frames.empty())
        throw Error(where_ + ":" + std::to_string(last_line_) + ": no frames (expected 'frame NUMBER TIME' lines with x,y,r rows)");
      end_frame();
    }
    return std::move(rec_);
  }

 private:
  void header_line(const std::vector<std::string_view>& words, std::string_view key, std::size_t h, const std::string& at,
                   std::size_t line_no, bool in_header) {
    // One value per key: a second line would silently win over the first.
    if (first_line_[h] != 0)
      throw Error(at + std::string(key) + " given twice (first on line " + std::to_string(first_line_[h]) + ")");
    first_line_[h] = line_no;
    if (!in_header)
      throw Error(at + std::string(key) + ": header lines come before the first frame" +
                  (key == "dim" ? " (the dimension decides how every row reads)" : ""));
    if (key == "cell_size") {
      const double d = parse_finite_number(header_value(words, at, "cell_size D"), at, "cell_size");
      if (!(d > 0)) throw Error(at + "cell_size: must be > 0, got " + excerpt(words[1]));
      rec_.grid.cell_size = d;
    } else if (key == "origin") {
      const auto f = axis_fields(header_value(words, at, "origin X,Y[,Z]"), at, "origin", "X,Y (2D) or X,Y,Z (3D)");
      rec_.grid.origin = std::array<double, 3>{parse_finite_number(f[0], at, "origin x"), parse_finite_number(f[1], at, "origin y"),
                                               f.size() == 3 ? parse_finite_number(f[2], at, "origin z") : 0};
      axis_counts_[0] = f.size();
    } else if (key == "cells") {
      const auto f = axis_fields(header_value(words, at, "cells NX,NY[,NZ]"), at, "cells", "NX,NY (2D) or NX,NY,NZ (3D)");
      constexpr std::int64_t kMost = std::int64_t{1} << 24;
      rec_.grid.cells = std::array<std::int64_t, 3>{parse_integer(f[0], at, "cells nx", 1, kMost), parse_integer(f[1], at, "cells ny", 1, kMost),
                                                    f.size() == 3 ? parse_integer(f[2], at, "cells nz", 1, kMost) : 1};
      axis_counts_[1] = f.size();
    } else if (key == "dim") {
      const std::string_view d = header_value(words, at, "dim 2|3");
      if (d != "2" && d != "3")
        throw Error(at + "dim: '" + excerpt(d) + "': a recording is 2D ('dim 2', the default: rows x,y,r) or 3D ('dim 3': rows x,y,z,r)");
      rec_.dim = d == "3" ? 3 : 2;
    } else {
      const std::string_view b = header_value(words, at, "base 0|1");
      if (b != "0" && b != "1")
        throw Error(at + "base: '" + excerpt(b) + "': pairs number elements from 0 ('base 0', the default) or 1 ('base 1')");
      rec_.pair_base = b == "1" ? 1 : 0;
    }
  }

  bool frame_line(const std::vector<std::string_view>& words, std::string_view line, const std::string& at, std::size_t line_no) {
    if (words.size() != 3) throw Error(at + "expected 'frame NUMBER TIME', got '" + excerpt(line) + "'");
    const std::int64_t number = parse_integer(words[1], at, "frame number", 0, std::numeric_limits<std::int64_t>::max());
    const double time = parse_finite_number(words[2], at, "frame time");
    if (rec_.frames.empty()) {
      check_header_axes();
      cols_ = ElementColumns(rec_.dim + 1);
    } else {
      const RecordedFrame& last = rec_.frames.back();
      if (number <= last.number)
        throw Error(at + "frame " + std::to_string(number) + " after frame " + std::to_string(last.number) +
                    ": frame numbers must increase");
      if (time < last.time)
        throw Error(at + "frame " + std::to_string(number) + ": time " + shortest(time) + " is before frame " +
                    std::to_string(last.number) + "'s " + shortest(last.time) + ": times must not decrease");
      end_frame();
      if (static_cast<std::int64_t>(rec_.frames.size()) >= max_frames_) {
        stopped_ = true;
        return false;
      }
    }
    // ~110 bytes a frame from a 10-byte line: millions of empty frames must not take the machine.
    if (rec_.frames.size() >= frame_limit_)
      throw Error(at + "more than " + std::to_string(frame_limit_) + " frames, the limit for a recording (replay --frames N reads the first N)");
    rec_.frames.push_back({number, time, {}, {}, {}, {}, 0, nullptr, nullptr});
    places_.push_back({offset_, line_no});
    state_ = FrameState{line_no, false};
    return true;
  }

  // An ordinary x,y,r row of the frame being read, taken without building a message; false for any
  // other line, which line() reads (or refuses) with its message.
  bool plain_element_row(std::string_view line) {
    if (rec_.frames.empty() || state_.has_pairs) return false;
    if (!keep_rows_) {
      // Counted, not parsed: a row is parsed (and refused) when its frame is read.
      const char c = line.front();
      if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.') || rows() >= kMaxElements) return false;
      ++counted_;
      return true;
    }
    int count = 0;
    std::array<double, 4> row{};
    if (!parse_plain_row(line, count, row) || count != rec_.dim + 1 || cols_.size() >= kMaxElements) return false;
    if (rec_.grid.cell_size && 2 * row[static_cast<std::size_t>(rec_.dim)] > *rec_.grid.cell_size) return false;
    cols_.push(row);
    return true;
  }

  void element_row(std::string_view line, const std::string& at) {
    const std::vector<std::string_view> fields = split_fields(line);
    const std::size_t columns = static_cast<std::size_t>(rec_.dim) + 1;
    const std::string expected = "; expected " + std::to_string(columns) + (rec_.dim == 3 ? " (x,y,z,r)" : " (x,y,r)");
    if (rec_.dim == 2 && fields.size() == 4)
      throw Error(at + "4 columns (x,y,z,r) in a 2D recording: add 'dim 3' before the first frame (without it rows are x,y,r)");
    if (rec_.dim == 3 && fields.size() == 3)
      throw Error(at + "3 columns (x,y,r) in a 3D recording ('dim 3' on line " + std::to_string(first_line_[kDimKey]) + "): rows are x,y,z,r");
    if (fields.size() == 2) throw Error(at + "2 columns" + expected + " (a pair i,j? pairs come after the frame's 'pairs' line)");
    if (fields.size() != columns) throw Error(at + plural(static_cast<long long>(fields.size()), "column") + expected);
    if (rows() >= kMaxElements) throw Error(at + "more than " + std::to_string(kMaxElements) + " elements in one frame");
    std::array<double, 4> row{};
    parse_element_row(fields, at, row);
    const double r = row[static_cast<std::size_t>(rec_.dim)];
    if (rec_.grid.cell_size && 2 * r > *rec_.grid.cell_size)
      throw Error(at + "r: diameter " + shortest(2 * r) + " is larger than the header's cell_size " + shortest(*rec_.grid.cell_size) +
                  " (contacts could skip a cell)");
    cols_.push(row);
  }

  // The frame being read is complete: its elements into place, its pairs block held to the first frame's.
  void end_frame() {
    RecordedFrame& f = rec_.frames.back();
    finish_frame(f, cols_, rec_.dim);
    if (rec_.frames.size() == 1) rec_.has_pairs = state_.has_pairs;
    check_all_or_none(rec_, state_, rec_.has_pairs, where_);
    if (keep_rows_) return;
    counts_.push_back(f.elements.size() + counted_);
    counted_ = 0;
    f.elements = Elements();
    PairList().swap(f.pairs);
  }

 public:
  // The line of the header's `dim` (0: none).
  [[nodiscard]] std::size_t dim_line() const { return first_line_[kDimKey]; }
  // The rows of the frame being read.
  [[nodiscard]] std::int64_t rows() const { return static_cast<std::int64_t>(cols_.size()) + counted_; }
  // Each frame's element count (keep_rows false: its rows are gone).
  [[nodiscard]] const std::vector<std::int64_t>& counts() const { return counts_; }

 private:

  // A whole-line comment of the header into rec_.comment: its text after '#' and one space, up to
  // kMaxKeptComment bytes (a recording recorded again keeps it, and stays the same file).
  void keep_comment(std::string_view raw) {
    const std::size_t start = raw.find_first_not_of(" \t");
    if (start == std::string_view::npos || raw[start] != '#') return;
    std::string_view text = raw.substr(start + 1);
    if (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    if (comment_full_ || rec_.comment.size() + text.size() + 1 > kMaxKeptComment) {
      comment_full_ = true;  // the first lines kept, none after: the comment stays a prefix of the file's
      return;
    }
    if (comment_lines_++ > 0) rec_.comment += '\n';
    rec_.comment += text;
  }

  // origin and cells give one value per axis of the recording (`dim`, which may come after them):
  // checked when the first frame starts, naming their own line.
  void check_header_axes() const {
    constexpr const char* kKeys[2] = {"origin", "cells"};
    constexpr const char* kForms[2][2] = {{"X,Y", "X,Y,Z"}, {"NX,NY", "NX,NY,NZ"}};
    for (std::size_t k = 0; k < 2; ++k) {
      if (axis_counts_[k] == 0 || axis_counts_[k] == static_cast<std::size_t>(rec_.dim)) continue;
      const std::string at = where_ + ":" + std::to_string(first_line_[k + 2]) + ": " + kKeys[k] + ": ";
      if (rec_.dim == 2) throw Error(at + "3 values (" + kForms[k][1] + ") in a 2D recording: add 'dim 3' before the first frame");
      throw Error(at + "2 values (" + kForms[k][0] + ") in a 3D recording ('dim 3' on line " + std::to_string(first_line_[kDimKey]) +
                  "): expected " + kForms[k][1]);
    }
  }

  static constexpr std::size_t kDimKey = 5;  // kHeaderKeys[5]
  const std::string& where_;
  std::int64_t max_frames_;
  std::size_t frame_limit_;
  bool keep_rows_ = true;
  std::size_t offset_ = 0;  // of the line being read
  std::vector<std::array<std::size_t, 2>> places_;
  std::vector<std::int64_t> counts_;
  std::int64_t counted_ = 0;  // rows of the frame being read counted, not parsed (keep_rows false)
  Recording rec_;
  bool seen_text_ = false;
  bool seen_version_ = false;
  bool stopped_ = false;  // max_frames frames read; the rest is not
  ElementColumns cols_{3};
  FrameState state_;  // of rec_.frames.back()
  std::size_t first_line_[kHeaderKeys.size()] = {};  // of each header key, 0 until seen ("nbsrec": the version line)
  std::size_t last_line_ = 0;
  std::size_t comment_lines_ = 0;  // kept in rec_.comment
  bool comment_full_ = false;      // kMaxKeptComment reached
  std::size_t axis_counts_[2] = {};  // values given on the origin and cells lines (0: no such line)
};

}  // namespace

Recording parse_recording(const std::string& text, const std::string& where, std::int64_t max_frames, std::size_t frame_limit) {
  RecordingParser parser(where, max_frames, frame_limit);
  std::size_t line_no = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string_view raw(text.data() + pos, end - pos);
    pos = end + 1;
    ++line_no;
    check_line_length(raw, where, line_no);
    if (!parser.line(raw, line_no)) break;
  }
  return parser.finish();
}

// ---- read_recording -------------------------------------------------------------------------

Recording read_recording(const std::string& path, std::int64_t max_frames, std::size_t frame_limit, std::size_t max_bytes) {
  InputLines lines(path, "recording", max_bytes, kMaxLineBytes);
  RecordingParser parser(path, max_frames, frame_limit);
  std::string_view line;
  while (lines.next(line))
    if (!parser.line(line, lines.line_number())) break;  // the frames wanted are read: the rest is not
  return parser.finish();
}

}  // namespace nbscope

// ---- frames read as shown -------------------------------------------------------------------

namespace nbscope {

namespace {

// A .nbsrec file's frames, each parsed again from its place in the file when it is asked for.
class RecordingFileFrames final : public RecordedFrames {
 public:
  RecordingFileFrames(Recording header, std::vector<RecordedEntry> entries, std::vector<std::array<std::size_t, 2>> places, std::size_t end,
                      std::size_t dim_line)
      : header_(std::move(header)), entries_(std::move(entries)), places_(std::move(places)), end_(end), dim_line_(dim_line) {}

  [[nodiscard]] const Recording& header() const override { return header_; }
  [[nodiscard]] const std::vector<RecordedEntry>& entries() const override { return entries_; }
  [[nodiscard]] bool reads_files() const override { return true; }

  [[nodiscard]] std::shared_ptr<const RecordedFrame> read(std::size_t index) override {
    const RecordedEntry& e = entries_.at(index);
    const std::size_t begin = places_[index][0];
    const std::size_t stop = index + 1 < places_.size() ? places_[index + 1][0] : end_;
    const std::string changed = header_.path + ":" + std::to_string(places_[index][1]) + ": frame " + std::to_string(e.number) +
                                " is not what it was (the file changed since it was read?)";
    std::string text(stop - begin, '\0');
    std::ifstream in(header_.path, std::ios::binary);
    if (!in) throw Error(header_.path + ": cannot open the recording again: " + std::strerror(errno));
    in.seekg(static_cast<std::streamoff>(begin));
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (static_cast<std::size_t>(in.gcount()) != text.size()) throw Error(changed);
    RecordingParser parser(header_, header_.path, dim_line_);
    std::size_t line_no = places_[index][1];
    for (std::size_t pos = 0; pos < text.size(); ++line_no) {
      std::size_t nl = text.find('\n', pos);
      if (nl == std::string::npos) nl = text.size();
      const std::string_view raw(text.data() + pos, nl - pos);
      pos = nl + 1;
      check_line_length(raw, header_.path, line_no);
      if (!parser.line(raw, line_no)) throw Error(changed);
    }
    Recording r = parser.finish();
    if (r.frames.size() != 1 || r.frames[0].number != e.number || r.frames[0].time != e.time || r.frames[0].elements.size() != e.elements)
      throw Error(changed);
    return std::make_shared<const RecordedFrame>(std::move(r.frames[0]));
  }

 private:
  Recording header_;
  std::vector<RecordedEntry> entries_;
  std::vector<std::array<std::size_t, 2>> places_;  // each frame's `frame` line: byte, line
  std::size_t end_;                                 // where the last frame read ends
  std::size_t dim_line_;                            // the header's `dim` line, for messages
};

}  // namespace

std::unique_ptr<RecordedFrames> read_recorded_frames(const std::string& path, std::int64_t max_frames) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return held_frames(read_recording(path, max_frames));
  // Every line read and checked as read_recording does, the rows dropped: no byte limit is needed.
  InputLines lines(path, "recording", std::numeric_limits<std::size_t>::max(), kMaxLineBytes);
  RecordingParser parser(path, max_frames, kMaxRecordedFrames, false);
  std::string_view line;
  while (lines.next(line))
    if (!parser.line(line, lines.line_number(), lines.line_offset())) break;
  const std::size_t end = parser.stop_offset(lines.offset());
  Recording rec = parser.finish();
  std::vector<RecordedEntry> entries;
  entries.reserve(rec.frames.size());
  for (std::size_t k = 0; k < rec.frames.size(); ++k)
    entries.push_back(RecordedEntry{rec.frames[k].number, rec.frames[k].time, parser.counts()[k]});
  rec.frames.clear();
  rec.frames.shrink_to_fit();
  return std::make_unique<RecordingFileFrames>(std::move(rec), std::move(entries), parser.places(), end, parser.dim_line());
}

}  // namespace nbscope

// The `dump custom` reader: header items, ATOMS columns by name, rows as they stream in; each
// frame's rows then go to ascending id order (lammps_dump_frame.cpp).
#include "io/lammps_dump.hpp"

#include <charconv>
#include <cmath>
#include <string_view>
#include <utility>

#include "core/error.hpp"
#include "io/dump_text.hpp"
#include "io/excerpt.hpp"
#include "io/lammps_dump_frame.hpp"
#include "io/lammps_dump_layout.hpp"
#include "io/lammps_dump_parse.hpp"

namespace nbscope {

namespace {

using dump::Digits;

using dump::Column;
using dump::kColumnName;
using dump::Layout;
using dump::layout_of;

// One frame's header as its ITEMs arrive.
struct Header {
  std::optional<std::int64_t> timestep, atoms;
  std::optional<double> time;
  bool has_box = false;
  DumpBox box;
  Digits box_digits;
  std::size_t timestep_line = 0;
};

class CustomReader {
 public:
  CustomReader(DumpText& text, const DumpOptions& options) : text_(text), options_(options) {}

  // Every frame of the text, at most `limit`.
  std::vector<DumpFrame> read(std::int64_t limit) {
    std::vector<DumpFrame> frames;
    Header header;
    std::string_view names;
    while (static_cast<std::int64_t>(frames.size()) < limit && next_header(header, names)) {
      DumpFrame f = begin_frame(header);
      const Layout lay = layout_of(names, text_.at(), options_);
      parse_rows(header, lay, f, nullptr);
      frames.push_back(std::move(f));
    }
    return frames;
  }

  // Every frame located (DumpFrameAt, `file` 0), at most `limit`: the ITEM lines read and checked,
  // the rows counted, not parsed.
  std::vector<DumpFrameAt> index(std::int64_t limit) {
    std::vector<DumpFrameAt> found;
    Header header;
    std::string_view names;
    for (;;) {
      const std::size_t offset = text_.offset(), line = text_.line_number() + 1;
      if (static_cast<std::int64_t>(found.size()) >= limit || !next_header(header, names)) break;
      DumpFrame f = begin_frame(header);
      (void)layout_of(names, text_.at(), options_);  // a bad ATOMS line is refused up front
      skip_rows(header, f);
      found.push_back(DumpFrameAt{f.timestep, f.time, *header.atoms, 0, offset, line, f.where});
    }
    return found;
  }

  // The frame whose items come next, parsed; Error when the text has none.
  DumpFrame next_frame() {
    Header header;
    std::string_view names;
    any_ = true;  // the text starts mid-file: its end is not an empty file
    if (!next_header(header, names)) throw Error(text_.at() + "no frame here (the file changed since it was read?)");
    DumpFrame f = begin_frame(header);
    const Layout lay = layout_of(names, text_.at(), options_);
    parse_rows(header, lay, f, nullptr);
    return f;
  }

  // The frame whose items come next, its rows parsed when `wanted` holds for its box, else skipped
  // (none returned); Error when the text has none.
  template <class Wanted>
  std::optional<DumpFrame> next_frame_if(Wanted wanted) {
    Header header;
    std::string_view names;
    any_ = true;
    if (!next_header(header, names)) throw Error(text_.at() + "no frame here");
    DumpFrame f = begin_frame(header);
    const Layout lay = layout_of(names, text_.at(), options_);
    if (!wanted(f.box)) {
      skip_rows(header, f);
      return std::nullopt;
    }
    parse_rows(header, lay, f, nullptr);
    return f;
  }

  // The frame of `timestep` (none: the first) parsed, every other one's rows counted only; stops
  // after the frame of `timestep`.
  DumpSeek seek(std::optional<std::int64_t> timestep) {
    DumpSeek found;
    Header header;
    std::string_view names;
    std::optional<Error> refused;  // the first frame's bad row, without a timestep
    for (;;) {
      const std::size_t offset = text_.offset();
      if (!next_header(header, names)) break;
      DumpFrame f = begin_frame(header);
      const Layout lay = layout_of(names, text_.at(), options_);  // a bad ATOMS line is refused in any frame
      if (found.frames++ == 0) found.first_timestep = f.timestep;
      found.last_timestep = f.timestep;
      const bool wanted = timestep ? f.timestep == *timestep : found.frames == 1;
      if (!wanted) {
        skip_rows(header, f);
        continue;
      }
      found.offset = offset;
      if (timestep) {
        parse_rows(header, lay, f, nullptr);
        found.frame = std::move(f);
        break;  // timesteps increase within a file: no other frame can be it
      }
      // The first of maybe several: a bad row waits until the file proves to hold this frame alone.
      if (parse_rows(header, lay, f, &refused)) found.frame = std::move(f);
    }
    if (refused && found.frames == 1) throw *refused;
    return found;
  }

 private:
  // The ITEM lines up to the next ITEM: ATOMS into `header` (cleared first), its column names into
  // `names`; false at the end of the text.
  bool next_header(Header& header, std::string_view& names) {
    header = Header{};
    std::string_view line;
    while (text_.next(line)) {
      if (line.find_first_not_of(" \t") == std::string_view::npos) continue;
      any_ = true;
      const std::string_view item = dump::item_of(line);
      if (item.data() == nullptr)
        throw Error(text_.at() + "'" + excerpt(line) + "' where an ITEM line was expected" +
                    (header.timestep || frames_ == 0 ? "" : " (more rows than NUMBER OF ATOMS?)"));
      if (item == "TIMESTEP") {
        if (header.timestep) throw Error(text_.at() + "a second ITEM: TIMESTEP before ITEM: ATOMS");
        header.timestep_line = text_.line_number();
        header.timestep = dump::integer_line(text_, "TIMESTEP");
      } else if (item == "TIME") {
        header.time = time_line();
      } else if (item == "NUMBER OF ATOMS") {
        header.atoms = dump::integer_line(text_, "NUMBER OF ATOMS");
        if (*header.atoms < 0 || *header.atoms > kMaxElements)
          throw Error(text_.at() + "NUMBER OF ATOMS " + std::to_string(*header.atoms) + " is outside 0 to " +
                      std::to_string(kMaxElements) + ", the most elements nbscope reads");
      } else if (item.rfind("BOX BOUNDS", 0) == 0) {
        dump::read_box(text_, item.substr(10), header.box, header.box_digits);
        header.has_box = true;
      } else if (item.rfind("ATOMS", 0) == 0) {
        names = item.substr(5);
        ++frames_;
        return true;
      } else if (item == "UNITS" || item == "LABEL") {
        text_.next(line);  // one line of text nbscope does not use
      } else if (item.rfind("NUMBER OF", 0) == 0 || item.rfind("ENTRIES", 0) == 0) {
        throw Error(text_.at() + "ITEM: " + excerpt(item) + ": this is a `dump local` file (contacts), not `dump custom` atoms");
      } else {
        throw Error(text_.at() + "unknown item 'ITEM: " + excerpt(item) + "'");
      }
    }
    if (!any_) throw Error(text_.path() + ":1: empty file (expected a LAMMPS `dump custom` file)");
    if (header.timestep || header.atoms || header.has_box) throw Error(text_.at() + "the file ends before ITEM: ATOMS (a frame cut short)");
    return false;
  }

  double time_line() {
    std::string_view line;
    if (!text_.next(line)) throw Error(text_.at() + "the file ends after ITEM: TIME");
    std::string_view w;
    const char* p = line.data();
    double t = 0;
    if (dump::next_word(p, line.data() + line.size(), w)) {
      auto [ptr, ec] = std::from_chars(w.data(), w.data() + w.size(), t);
      if (ec == std::errc() && ptr == w.data() + w.size() && std::isfinite(t)) return t;
    }
    throw Error(text_.at() + "TIME: '" + excerpt(line) + "' is not a finite number");
  }

  // The frame of a complete header, its rows not read yet; Error for a missing item or a timestep
  // not after the one before it.
  DumpFrame begin_frame(const Header& header) {
    const std::string at = text_.at();
    if (!header.timestep) throw Error(at + "ITEM: ATOMS before ITEM: TIMESTEP");
    if (!header.atoms) throw Error(at + "ITEM: ATOMS before ITEM: NUMBER OF ATOMS");
    if (!header.has_box) throw Error(at + "ITEM: ATOMS before ITEM: BOX BOUNDS");
    DumpFrame f;
    f.timestep = *header.timestep;
    f.where = text_.path() + ":" + std::to_string(header.timestep_line);
    if (last_ && f.timestep <= last_->first)
      throw Error(f.where + ": timestep " + std::to_string(f.timestep) + " after timestep " + std::to_string(last_->first) + " (" +
                  last_->second + "): timesteps must increase within a file");
    last_.emplace(f.timestep, f.where);
    f.time = header.time;
    f.box = header.box;
    return f;
  }

  // "<path>:<line>: timestep 500 has 7 rows, NUMBER OF ATOMS says 9": the text ended or an ITEM
  // line came after `rows` of them.
  [[noreturn]] void cut_short(const DumpFrame& f, std::int64_t rows, std::int64_t atoms) {
    throw Error(text_.at() + "timestep " + std::to_string(f.timestep) + " has " + std::to_string(rows) +
                " rows, NUMBER OF ATOMS says " + std::to_string(atoms));
  }

  // Passes over the frame's NUMBER OF ATOMS rows without parsing them (a seek's other frames).
  void skip_rows(const Header& header, const DumpFrame& f) {
    std::string_view line;
    for (std::int64_t k = 0; k < *header.atoms; ++k)
      if (!text_.next(line) || line.rfind("ITEM:", 0) == 0) cut_short(f, k, *header.atoms);
  }

  // The frame's rows, parsed into `f`. With `refused`, a bad row or atom is kept there instead of
  // thrown (false returned), the rest of the rows counted as skip_rows does.
  bool parse_rows(const Header& header, const Layout& lay, DumpFrame& f, std::optional<Error>* refused) {
    dump::RawAtoms raw(lay.has_z ? 3 : 2, lay.has_type);
    if (options_.keep_columns) {
      raw.keep_columns = true;
      raw.header = lay.names;
      raw.kept_names = lay.kept_names;
      raw.kept_values.resize(lay.kept_names.size());
      raw.kept_numeric.assign(lay.kept_names.size(), 1);
      row_kept_.assign(lay.kept_names.size(), 0.0);
    }
    // Slots by id only for as many rows as the text left can hold (a row is 8 bytes or more).
    raw.start(*header.atoms, static_cast<std::uint64_t>(*header.atoms) <= text_.bytes_left() / 8);
    raw.first_line = text_.line_number() + 1;
    bool bad = false;
    for (std::int64_t k = 0; k < *header.atoms; ++k) {
      std::string_view line;
      if (!text_.next(line) || dump::item_of(line).data() != nullptr) cut_short(f, k, *header.atoms);
      if (bad) continue;
      try {
        row(line, lay, raw);
      } catch (const Error& e) {
        if (refused == nullptr) throw;
        refused->emplace(e);
        bad = true;
      }
    }
    if (bad) return false;
    const double box_half = header.box_digits.half_unit();
    try {
      dump::finish_frame(raw, f, options_, lay.scaled, box_half, lay.radius == Column::kDiameter);
    } catch (const Error& e) {
      if (refused == nullptr) throw;
      refused->emplace(e);
      return false;
    }
    return true;
  }

  [[noreturn]] void bad_number(std::size_t c, std::string_view w, const Layout& lay, const char* what) {
    throw Error(text_.at() + lay.names[c] + ": '" + excerpt(w) + "' " + what);
  }

  // One atom row into `raw`; the fast path parses each number where it stands.
  void row(std::string_view line, const Layout& lay, dump::RawAtoms& raw) {
    const char* p = line.data();
    const char* end = p + line.size();
    const std::size_t ncols = lay.roles.size();
    std::size_t c = 0;
    std::string_view w;
    double pos[3] = {0, 0, 0};
    double radius = 0;
    std::int64_t id = 0, type = 0;
    for (; dump::next_word(p, end, w); ++c) {
      if (c >= ncols) continue;
      const Column role = lay.roles[c];
      if (role == Column::kOther) {
        if (const int k = lay.kept[c]; k >= 0) keep_value(w, raw, static_cast<std::size_t>(k));
        continue;
      }
      if (role == Column::kId || role == Column::kType) {
        std::int64_t v = 0;
        const auto [end_int, ec_int] = std::from_chars(w.data(), w.data() + w.size(), v);
        if (ec_int != std::errc() || end_int != w.data() + w.size())  // the message's path
          v = dump::parse_integer(w, text_.at(), kColumnName[static_cast<int>(role)], false);
        (role == Column::kId ? id : type) = v;
        continue;
      }
      double v = 0;
      const auto [ptr, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
      if (ec != std::errc() && ec != std::errc::result_out_of_range) bad_number(c, w, lay, "is not a number");
      if (ptr != w.data() + w.size()) bad_number(c, w, lay, "is not a number");
      if (ec != std::errc() || !std::isfinite(v)) bad_number(c, w, lay, "is not a finite number");
      if (role == Column::kRadius || role == Column::kDiameter) {
        if (!(v > 0)) bad_number(c, w, lay, "is not > 0");
        radius = role == Column::kDiameter ? v / 2 : v;
        raw.radius_digits.add(w, v);
      } else {
        pos[static_cast<int>(role) - static_cast<int>(Column::kX)] = v;
        raw.position_digits.add(w, v);
      }
    }
    if (c != ncols)
      throw Error(text_.at() + std::to_string(c) + " columns; ITEM: ATOMS names " + std::to_string(ncols));
    if (lay.radius == Column::kOther) radius = radius_of(type, lay);
    if (radius < kMinRadius || radius > kMaxRadius)
      throw Error(text_.at() + "radius " + std::to_string(radius) + " is outside the supported radii 1e-100 to 1e100");
    if (type < INT32_MIN || type > INT32_MAX) throw Error(text_.at() + "type " + std::to_string(type) + " does not fit 32 bits");
    raw.push(id, static_cast<std::int32_t>(type), pos, radius, row_kept_.data());
  }

  // A kept column's value; a word that is no number makes the column a text one, dropped (LAMMPS's `element`).
  void keep_value(std::string_view w, dump::RawAtoms& raw, std::size_t k) {
    double v = 0;
    const auto [ptr, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || ptr != w.data() + w.size()) {
      raw.kept_numeric[k] = 0;
      v = 0;
    }
    row_kept_[k] = v;
  }

  double radius_of(std::int64_t type, const Layout& lay) {
    if (lay.has_type) {
      const auto it = options_.type_radius.find(type);
      if (it != options_.type_radius.end()) return it->second;
    }
    if (options_.radius) return *options_.radius;
    throw Error(text_.at() + "no radius for type " + std::to_string(type) + " (--type-radius names no such type)");
  }

  DumpText& text_;
  const DumpOptions& options_;
  bool any_ = false;        // a line that is not blank was read
  std::int64_t frames_ = 0;  // ITEM: ATOMS lines read
  std::vector<double> row_kept_;  // the row's kept columns (DumpOptions::keep_columns)
  std::optional<std::pair<std::int64_t, std::string>> last_;  // the timestep of the frame before, and its where
};

std::vector<DumpFrame> merge(std::vector<std::vector<DumpFrame>> per_file, std::int64_t max_frames) {
  std::vector<DumpFrame> all;
  for (auto& frames : per_file)
    for (auto& f : frames) all.push_back(std::move(f));
  dump::order_by_timestep(all);
  if (static_cast<std::int64_t>(all.size()) > max_frames) all.resize(static_cast<std::size_t>(max_frames));
  if (all.size() > kMaxRecordedFrames) throw Error(all[kMaxRecordedFrames].where + ": more than " +
                                                   std::to_string(kMaxRecordedFrames) + " frames, the limit for a recording");
  return all;
}

}  // namespace

std::vector<DumpFrame> read_dump_frames(const std::vector<std::string>& paths, const DumpOptions& options) {
  std::vector<std::vector<DumpFrame>> per_file;
  for (const std::string& path : paths) {
    DumpText text(path);
    per_file.push_back(CustomReader(text, options).read(options.max_frames));
  }
  return merge(std::move(per_file), options.max_frames);
}

std::vector<DumpFrame> parse_dump_frames(const std::string& text, const std::string& where, const DumpOptions& options) {
  DumpText lines(text, where);
  std::vector<std::vector<DumpFrame>> one;
  one.push_back(CustomReader(lines, options).read(options.max_frames));
  return merge(std::move(one), options.max_frames);
}

std::vector<DumpFrameAt> index_dump_frames(const std::vector<std::string>& paths, const DumpOptions& options) {
  std::vector<DumpFrameAt> all;
  for (std::size_t k = 0; k < paths.size(); ++k) {
    DumpText text(paths[k]);
    for (DumpFrameAt& at : CustomReader(text, options).index(options.max_frames)) {
      at.file = k;
      all.push_back(std::move(at));
    }
  }
  dump::order_by_timestep(all);
  if (static_cast<std::int64_t>(all.size()) > options.max_frames) all.resize(static_cast<std::size_t>(options.max_frames));
  if (all.size() > kMaxRecordedFrames)
    throw Error(all[kMaxRecordedFrames].where + ": more than " + std::to_string(kMaxRecordedFrames) + " frames, the limit for a recording");
  return all;
}

DumpCursor::DumpCursor(std::string path) : path_(std::move(path)) {}
DumpCursor::~DumpCursor() = default;

DumpText& DumpCursor::text_at(const DumpFrameAt& at) {
  // On from the last frame read when this one starts where it ended (a replay's next frame), else opened again at it.
  if (text_ == nullptr || text_->offset() != at.offset) text_ = std::make_unique<DumpText>(path_, at.offset, at.line);
  return *text_;
}

DumpFrame DumpCursor::read_frame(const DumpFrameAt& at, const DumpOptions& options) {
  DumpFrame f = CustomReader(text_at(at), options).next_frame();
  dump::expect_indexed_timestep(f.where, f.timestep, at.timestep);
  return f;
}

DumpSeek seek_dump_frame(const std::string& path, std::optional<std::int64_t> timestep, const DumpOptions& options) {
  if (timestep) {
    if (const std::optional<std::size_t> at = find_dump_frame(path, *timestep)) {
      try {
        DumpText text(path, *at, 0);
        DumpSeek found = CustomReader(text, options).seek(timestep);
        if (found.frame) {
          found.frame->where = path + " at byte " + std::to_string(found.offset);  // the lines before were not counted
          return found;
        }
      } catch (const Error&) {
        // Read in order below: its message names the line, and checks the frames before it too.
      }
    }
  }
  DumpText text(path);
  return CustomReader(text, options).seek(timestep);
}

std::optional<DumpFrame> first_z_periodic_frame(const std::string& path, const DumpOptions& options) {
  DumpText text(path);
  CustomReader reader(text, options);
  std::optional<DumpFrame> last;
  for (int k = 0; k < 16 && (!last || last->elements.size() == 0); ++k) {  // LIGGGHTS's frame 0 may be empty
    if (last && text.bytes_left() == 0) break;
    std::optional<DumpFrame> next;
    try {
      next = reader.next_frame_if([](const DumpBox& box) { return box.flags[2] == "pp"; });
    } catch (const Error&) {
      if (!last) throw;
      break;  // the end of the file: the frames before are what it holds
    }
    if (!next) return std::nullopt;  // z is not periodic: no `dimension 2` run
    last = std::move(next);
  }
  return last;
}

DumpHead read_dump_head(const std::string& path) {
  DumpText text(path);
  DumpHead head;
  std::string_view line;
  while (text.next(line)) {
    const std::string_view item = dump::item_of(line);
    if (item == "TIME") head.has_time = true;
    if (item == "UNITS" && text.next(line)) {
      const std::vector<std::string_view> words = dump::words_of(line);
      if (words.size() == 1) head.units = std::string(words.front());
    }
    if (item.data() != nullptr && item.rfind("ATOMS", 0) == 0) break;
  }
  return head;
}

DumpSeek seek_dump_frame_in(const std::string& text, const std::string& where, std::optional<std::int64_t> timestep,
                            const DumpOptions& options) {
  DumpText lines(text, where);
  return CustomReader(lines, options).seek(timestep);
}

}  // namespace nbscope

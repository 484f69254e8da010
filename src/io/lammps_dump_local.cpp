// The `dump local` reader (contact lists: LIGGGHTS's compute pair/gran/local, LAMMPS's
// property/local patom1 patom2), and the dump frames as a Recording.
#include <glob.h>

#include <algorithm>
#include <filesystem>
#include <unordered_map>

#include "core/error.hpp"
#include "io/dump_text.hpp"
#include "io/excerpt.hpp"
#include "io/lammps_dump.hpp"
#include "io/lammps_dump_parse.hpp"

namespace nbscope {

namespace {

// The 0-based columns of the two ids, from `columns` or the ENTRIES names; -1, -1 when only the
// LIGGGHTS pair/gran/local order may tell (decided by the values: see guess_liggghts).
std::array<int, 2> id_columns(const std::vector<std::string_view>& names, const ContactColumns& columns, const std::string& at) {
  const int n = static_cast<int>(names.size());
  if (columns.numbers) {
    for (int c : *columns.numbers)
      if (c < 1 || c > n)
        throw Error(at + "--contact-ids: column " + std::to_string(c) + " is not among the " + std::to_string(n) + " ENTRIES columns");
    return {(*columns.numbers)[0] - 1, (*columns.numbers)[1] - 1};
  }
  const auto find = [&](std::string_view name) {
    for (int c = 0; c < n; ++c)
      if (names[static_cast<std::size_t>(c)] == name) return c;
    return -1;
  };
  if (columns.names) {
    std::array<int, 2> out{};
    for (int k = 0; k < 2; ++k) {
      out[static_cast<std::size_t>(k)] = find((*columns.names)[static_cast<std::size_t>(k)]);
      if (out[static_cast<std::size_t>(k)] < 0)
        throw Error(at + "--contact-ids: no ENTRIES column named '" + excerpt((*columns.names)[static_cast<std::size_t>(k)]) + "'");
    }
    return out;
  }
  for (auto [a, b] : {std::pair{"id1", "id2"}, {"i", "j"}, {"atom1", "atom2"}, {"patom1", "patom2"}})
    if (find(a) >= 0 && find(b) >= 0) return {find(a), find(b)};
  if (n == 2) return {0, 1};   // property/local patom1 patom2 alone
  if (n >= 8) return {-1, -1};  // pair/gran/local `pos id ...`: columns 7 and 8, if the values fit
  throw Error(at + "which ENTRIES columns hold the contact's atom ids? Give --contact-ids (column numbers 7,8 or names)");
}

class LocalReader {
 public:
  LocalReader(DumpText& text, const ContactColumns& columns) : text_(text), columns_(columns) {}

  std::vector<DumpContacts> read() {
    std::vector<DumpContacts> frames;
    DumpContacts c;
    while (next(c, true)) frames.push_back(std::move(c));
    return frames;
  }

  // Every frame located (DumpFrameAt: `atoms` its NUMBER OF ENTRIES, `file` 0): the ITEM lines read
  // and checked, the rows counted, not parsed.
  std::vector<DumpFrameAt> index() {
    std::vector<DumpFrameAt> found;
    DumpContacts c;
    for (;;) {
      const std::size_t offset = text_.offset(), line = text_.line_number() + 1;
      if (!next(c, false)) break;
      found.push_back(DumpFrameAt{c.timestep, std::nullopt, static_cast<std::int64_t>(c.lines.size()), 0, offset, line, c.where});
    }
    return found;
  }

  // The frame whose items come next, its rows parsed; Error when the text has none.
  DumpContacts next_frame() {
    DumpContacts c;
    any_ = true;  // the text starts mid-file: its end is not an empty file
    if (!next(c, true)) throw Error(text_.at() + "no contact frame here (the file changed since it was read?)");
    return c;
  }

 private:
  // The next frame into `c` (cleared first), its rows parsed, or with `parse` false only counted
  // (`lines` holds their line numbers); false at the end of the text.
  bool next(DumpContacts& c, bool parse) {
    c = DumpContacts{};
    std::int64_t timestep = 0, entries = 0;  // valid when has_timestep, has_entries
    bool has_timestep = false, has_entries = false;
    std::size_t timestep_line = 0;
    std::string_view line;
    while (text_.next(line)) {
      if (line.find_first_not_of(" \t") == std::string_view::npos) continue;
      any_ = true;
      const std::string_view item = dump::item_of(line);
      if (item.data() == nullptr)
        throw Error(text_.at() + "'" + excerpt(line) + "' where an ITEM line was expected" +
                    (has_timestep || !last_ ? "" : " (more rows than NUMBER OF ENTRIES?)"));
      if (item == "TIMESTEP") {
        timestep_line = text_.line_number();
        timestep = dump::integer_line(text_, "TIMESTEP");
        has_timestep = true;
      } else if (item.rfind("NUMBER OF ATOMS", 0) == 0 || item.rfind("ATOMS", 0) == 0) {
        throw Error(text_.at() + "ITEM: " + excerpt(item) + ": this is a `dump custom` file (atoms), not a `dump local` one");
      } else if (item.rfind("NUMBER OF", 0) == 0) {
        entries = dump::integer_line(text_, "NUMBER OF ENTRIES");
        has_entries = true;
        if (entries < 0 || static_cast<std::uint64_t>(entries) > kDefaultMaxPairs)
          throw Error(text_.at() + "NUMBER OF ENTRIES " + std::to_string(entries) + " is outside 0 to " +
                      std::to_string(kDefaultMaxPairs) + ", the most contacts of one frame nbscope reads");
      } else if (item.rfind("BOX BOUNDS", 0) == 0) {
        DumpBox box;
        dump::Digits digits;
        dump::read_box(text_, item.substr(10), box, digits);
      } else if (item == "TIME" || item == "UNITS" || item == "LABEL") {
        text_.next(line);
      } else if (item.rfind("ENTRIES", 0) == 0 || has_timestep) {
        if (!has_timestep) throw Error(text_.at() + "ITEM: ENTRIES before ITEM: TIMESTEP");
        if (!has_entries) throw Error(text_.at() + "ITEM: ENTRIES before ITEM: NUMBER OF ENTRIES");
        c.timestep = timestep;
        c.path = text_.path();
        c.where = text_.path() + ":" + std::to_string(timestep_line);
        if (last_ && c.timestep <= last_->first)
          throw Error(c.where + ": timestep " + std::to_string(c.timestep) + " after timestep " + std::to_string(last_->first) + " (" +
                      last_->second + "): timesteps must increase within a file");
        last_.emplace(c.timestep, c.where);
        rows(item.substr(item.find(' ') == std::string_view::npos ? item.size() : item.find(' ')), entries, c, parse);
        return true;
      } else {
        throw Error(text_.at() + "unknown item 'ITEM: " + excerpt(item) + "'");
      }
    }
    if (!any_) throw Error(text_.path() + ":1: empty file (expected a LAMMPS `dump local` file)");
    if (has_timestep) throw Error(text_.at() + "the file ends before ITEM: ENTRIES (a frame cut short)");
    return false;
  }

  void rows(std::string_view names_line, std::int64_t count, DumpContacts& c, bool parse) {
    const std::string at = text_.at();
    const std::vector<std::string_view> words = dump::words_of(names_line);
    std::array<int, 2> col = id_columns(words, columns_, at);
    // Copies: the ENTRIES line's bytes move when the rows' reading refills the text.
    const std::vector<std::string> names(words.begin(), words.end());
    const bool guessed = col[0] < 0;
    if (guessed) col = {6, 7};
    if (parse) c.ids.reserve(static_cast<std::size_t>(std::min<std::int64_t>(count, 1 << 20)));
    for (std::int64_t k = 0; k < count; ++k) {
      std::string_view line;
      if (!text_.next(line) || dump::item_of(line).data() != nullptr)
        throw Error(text_.at() + "timestep " + std::to_string(c.timestep) + " has " + std::to_string(k) +
                    " rows, NUMBER OF ENTRIES says " + std::to_string(count));
      if (!parse) {
        c.lines.push_back(static_cast<std::int64_t>(text_.line_number()));
        continue;
      }
      const char* p = line.data();
      std::string_view w;
      std::array<std::int64_t, 2> ids{};
      int n = 0;
      for (; dump::next_word(p, line.data() + line.size(), w); ++n) {
        for (int s = 0; s < 2; ++s)
          if (n == col[static_cast<std::size_t>(s)]) ids[static_cast<std::size_t>(s)] = id(w, names, n, guessed);
      }
      if (n != static_cast<int>(names.size()))
        throw Error(text_.at() + std::to_string(n) + " columns; ITEM: ENTRIES names " + std::to_string(names.size()));
      c.ids.push_back(ids);
      c.lines.push_back(static_cast<std::int64_t>(text_.line_number()));
    }
  }

  std::int64_t id(std::string_view w, const std::vector<std::string>& names, int column, bool guessed) {
    const std::string what = "column " + std::to_string(column + 1) + " (" + std::string(names[static_cast<std::size_t>(column)]) + ")";
    try {
      const std::int64_t v = dump::parse_integer(w, text_.at(), what.c_str(), true);
      if (guessed && v < 1) throw Error(text_.at() + what + ": " + std::to_string(v) + " is no atom id");
      return v;
    } catch (const Error& e) {
      if (!guessed) throw;
      throw Error(std::string(e.what()) + "; read as LIGGGHTS's compute pair/gran/local `pos id` order (ids in columns 7 and 8), "
                  "which these values do not fit: give --contact-ids");
    }
  }

  DumpText& text_;
  const ContactColumns& columns_;
  bool any_ = false;  // a line that is not blank was read
  std::optional<std::pair<std::int64_t, std::string>> last_;  // the timestep of the frame before, and its where
};

std::vector<DumpContacts> merge(std::vector<DumpContacts> all) {
  dump::order_by_timestep(all);
  return all;
}

}  // namespace

std::vector<DumpContacts> read_dump_contacts(const std::vector<std::string>& paths, const ContactColumns& columns) {
  std::vector<DumpContacts> all;
  for (const std::string& path : paths) {
    DumpText text(path);
    for (auto& c : LocalReader(text, columns).read()) all.push_back(std::move(c));
  }
  return merge(std::move(all));
}

std::vector<DumpFrameAt> index_dump_contacts(const std::vector<std::string>& paths, const ContactColumns& columns) {
  std::vector<DumpFrameAt> all;
  for (std::size_t k = 0; k < paths.size(); ++k) {
    DumpText text(paths[k]);
    for (DumpFrameAt& at : LocalReader(text, columns).index()) {
      at.file = k;
      all.push_back(std::move(at));
    }
  }
  dump::order_by_timestep(all);
  return all;
}

DumpContacts DumpCursor::read_contacts(const DumpFrameAt& at, const ContactColumns& columns) {
  DumpContacts c = LocalReader(text_at(at), columns).next_frame();
  dump::expect_indexed_timestep(c.where, c.timestep, at.timestep);
  return c;
}

std::vector<DumpContacts> parse_dump_contacts(const std::string& text, const std::string& where, const ContactColumns& columns) {
  DumpText lines(text, where);
  return merge(LocalReader(lines, columns).read());
}

std::vector<std::string> expand_dump_spec(const std::string& flag, const std::string& spec) {
  if (spec.find_first_of("*?[") == std::string::npos) {
    std::error_code ec;
    if (!std::filesystem::exists(spec, ec)) throw Error(flag + ": '" + spec + "': no file matches");
    return {spec};
  }
  glob_t g{};
  const int rc = glob(spec.c_str(), 0, nullptr, &g);
  std::vector<std::string> out;
  if (rc == 0)
    for (std::size_t k = 0; k < g.gl_pathc; ++k) out.emplace_back(g.gl_pathv[k]);
  globfree(&g);
  if (out.empty()) throw Error(flag + ": '" + spec + "': no file matches");
  return out;
}

PairList contacts_as_rows(const DumpFrame& frame, const DumpContacts& contacts) {
  PairList pairs;
  pairs.reserve(contacts.ids.size());
  const auto row_of = [&](std::int64_t id) {
    const auto it = std::lower_bound(frame.ids.begin(), frame.ids.end(), id);
    return it != frame.ids.end() && *it == id ? static_cast<ElementId>(it - frame.ids.begin()) : ElementId{-1};
  };
  for (std::size_t k = 0; k < contacts.ids.size(); ++k) {
    const auto [a, b] = contacts.ids[k];
    const ElementId i = row_of(a), j = row_of(b);
    if (i < 0 || j < 0)
      throw Error(contacts.path + ":" + std::to_string(k < contacts.lines.size() ? contacts.lines[k] : 0) + ": contact (" + std::to_string(a) +
                  ", " + std::to_string(b) + "): atom " + std::to_string(i < 0 ? a : b) + " is not in the frame of timestep " +
                  std::to_string(frame.timestep) + " (" + frame.where + ")");
    pairs.push_back({i, j});
  }
  return pairs;
}

double dump_frame_time(std::int64_t timestep, std::optional<double> time, std::optional<double> dt) {
  return time ? *time : dt ? *dt * static_cast<double>(timestep) : static_cast<double>(timestep);
}

RecordedFrame recorded_from_dump(DumpFrame f, const DumpContacts* contacts, std::optional<double> dt) {
  RecordedFrame r;
  r.number = f.timestep;
  r.time = dump_frame_time(f.timestep, f.time, dt);
  if (contacts != nullptr) r.pairs = contacts_as_rows(f, *contacts);
  r.elements = std::move(f.elements);
  r.ids = std::move(f.ids);
  r.ranks = std::move(f.ranks);
  r.subdomains = std::move(f.subdomains);
  r.precision = f.precision;
  r.columns = std::move(f.columns);
  return r;
}

Recording recording_from_dumps(std::vector<DumpFrame> frames, const std::vector<DumpContacts>& contacts, std::optional<double> dt,
                               const std::string& path) {
  if (frames.empty()) throw Error(path + ": no frames");
  Recording rec;
  rec.path = path;
  rec.has_pairs = !contacts.empty();
  rec.frame_unit = FrameUnit::timestep;
  std::unordered_map<std::int64_t, std::size_t> by_step;
  for (std::size_t k = 0; k < contacts.size(); ++k) by_step.emplace(contacts[k].timestep, k);
  // A contact frame past the last dump frame is one `--frames N` left out, not a mismatch.
  const std::int64_t last = frames.back().timestep;
  std::size_t used = 0;
  for (const DumpContacts& c : contacts)
    if (c.timestep <= last) ++used;
  rec.frames.reserve(frames.size());
  for (DumpFrame& f : frames) {
    const DumpContacts* c = nullptr;
    if (rec.has_pairs) {
      const auto it = by_step.find(f.timestep);
      if (it == by_step.end()) throw Error(f.where + ": timestep " + std::to_string(f.timestep) + " has no contact frame");
      c = &contacts[it->second];
      --used;
    }
    rec.frames.push_back(recorded_from_dump(std::move(f), c, dt));
  }
  if (used != 0)
    for (const DumpContacts& c : contacts)
      if (c.timestep <= last && std::none_of(rec.frames.begin(), rec.frames.end(), [&](const RecordedFrame& r) { return r.number == c.timestep; }))
        throw Error(c.where + ": contact frame of timestep " + std::to_string(c.timestep) + " has no dump frame");
  return rec;
}

}  // namespace nbscope

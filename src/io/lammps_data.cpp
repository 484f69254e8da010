// The LAMMPS data file reader (lammps_data.hpp): header lines, then sections, the Atoms one parsed
// into the rows a dump frame's are (io/lammps_dump_frame.hpp), every other one skipped.
#include "io/lammps_data.hpp"

#include <charconv>
#include <cmath>
#include <optional>
#include <vector>

#include "core/error.hpp"
#include "io/dump_text.hpp"
#include "io/excerpt.hpp"
#include "io/lammps_dump_frame.hpp"
#include "io/lammps_dump_parse.hpp"

namespace nbscope {

namespace {

// `line` without its `# comment`, and the comment (after '#' and blanks) in `comment`.
std::string_view strip_comment(std::string_view line, std::string_view* comment = nullptr) {
  const std::size_t hash = line.find('#');
  if (comment != nullptr) {
    *comment = hash == std::string_view::npos ? std::string_view() : line.substr(hash + 1);
    while (!comment->empty() && (comment->front() == ' ' || comment->front() == '\t')) comment->remove_prefix(1);
    while (!comment->empty() && (comment->back() == ' ' || comment->back() == '\t')) comment->remove_suffix(1);
  }
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

// The value after `key = ` in write_data's title ("..., timestep = 5000, units = lj"), or empty.
std::string_view title_value(std::string_view title, std::string_view key) {
  for (std::size_t at = title.find(key); at != std::string_view::npos; at = title.find(key, at + 1)) {
    if (at > 0 && title[at - 1] != ' ' && title[at - 1] != ',') continue;
    std::string_view rest = title.substr(at + key.size());
    while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
    if (rest.empty() || rest.front() != '=') continue;
    rest.remove_prefix(1);
    while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
    return rest.substr(0, std::min(rest.find_first_of(", \t"), rest.size()));
  }
  return {};
}

bool starts_section(std::string_view line) {
  const std::size_t k = line.find_first_not_of(" \t");
  return k != std::string_view::npos && ((line[k] >= 'A' && line[k] <= 'Z') || (line[k] >= 'a' && line[k] <= 'z'));
}

class DataReader {
 public:
  DataReader(DumpText& text, const DumpOptions& options) : text_(text), options_(options) {}

  DumpFrame read(std::string* units) {
    std::string_view line;
    if (!text_.next(line)) throw Error(text_.path() + ":1: empty file (expected a LAMMPS data file)");
    const std::string title(line);
    if (units != nullptr) *units = std::string(title_value(title, "units"));
    DumpFrame f;
    if (const std::string_view t = title_value(title, "timestep"); !t.empty())
      f.timestep = dump::parse_integer(t, text_.at(), "timestep", false);
    f.box.lo[2] = -0.5;  // LAMMPS's default z bounds (a 2D file may omit them)
    f.box.hi[2] = 0.5;
    f.box.flags = {"ff", "ff", "ff"};
    bool have_atoms_section = false;
    bool in_header = true;
    std::optional<std::string_view> pending;  // a section line met while skipping
    for (;;) {
      if (pending) {
        line = *pending;
        pending.reset();
      } else if (!text_.next(line)) {
        break;
      }
      const std::string_view body = strip_comment(line);
      if (body.find_first_not_of(" \t") == std::string_view::npos) continue;
      if (!starts_section(body)) {
        if (!in_header) throw Error(text_.at() + "'" + excerpt(line) + "' where a section (Atoms, Velocities, ...) was expected");
        header_line(body, f);
        continue;
      }
      in_header = false;
      const std::vector<std::string_view> words = dump::words_of(body);
      if (words.front() == "Atoms") {
        if (have_atoms_section) throw Error(text_.at() + "a second Atoms section");
        have_atoms_section = true;
        std::string_view style;
        strip_comment(line, &style);
        f.where = text_.path() + ":" + std::to_string(text_.line_number());
        pending = atoms(style, f);
      } else {
        pending = skip_section();
      }
    }
    if (!atoms_) throw Error(text_.path() + ":1: no `N atoms` header line (is this a LAMMPS data file?)");
    if (!have_atoms_section) throw Error(text_.at() + "no Atoms section (the file ends without one)");
    return f;
  }

 private:
  // One header line: `N atoms`, `N atom types`, `lo hi xlo xhi`...; others (bonds, ...) are not needed.
  void header_line(std::string_view body, DumpFrame& f) {
    const std::vector<std::string_view> w = dump::words_of(body);
    if (w.size() >= 3 && (w[w.size() - 3] == "xy" || w.back() == "yz"))
      throw Error(text_.at() + "a triclinic box (xy xz yz): nbscope reads orthogonal boxes only");
    if (w.size() == 2 && w[1] == "atoms") {
      const std::int64_t n = dump::parse_integer(w[0], text_.at(), "atoms", false);
      if (n < 0 || n > kMaxElements)
        throw Error(text_.at() + std::to_string(n) + " atoms is outside 0 to " + std::to_string(kMaxElements) + ", the most elements nbscope reads");
      atoms_ = n;
      return;
    }
    if (w.size() == 4 && w[2].size() == 3 && w[3].size() == 3 && w[2].substr(1) == "lo" && w[3].substr(1) == "hi" &&
        w[2][0] == w[3][0] && w[2][0] >= 'x' && w[2][0] <= 'z') {
      const int a = w[2][0] - 'x';
      double v[2] = {0, 0};
      for (int k = 0; k < 2; ++k) v[k] = number(w[static_cast<std::size_t>(k)], w[2]);
      if (!(v[0] <= v[1])) throw Error(text_.at() + std::string(w[2]) + " " + excerpt(w[0]) + " is above " + std::string(w[3]) + " " + excerpt(w[1]));
      f.box.lo[a] = v[0];
      f.box.hi[a] = v[1];
    }
  }

  double number(std::string_view w, std::string_view what) {
    double v = 0;
    const auto [ptr, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if ((ec != std::errc() && ec != std::errc::result_out_of_range) || ptr != w.data() + w.size())
      throw Error(text_.at() + std::string(what) + ": '" + excerpt(w) + "' is not a number");
    if (ec != std::errc() || !std::isfinite(v)) throw Error(text_.at() + std::string(what) + ": '" + excerpt(w) + "' is not a finite number");
    return v;
  }

  // Lines up to the next section line (returned; none at the end of the text).
  std::optional<std::string_view> skip_section() {
    std::string_view line;
    while (text_.next(line))
      if (starts_section(strip_comment(line))) return line;
    return std::nullopt;
  }

  // The Atoms section of atom style `style`, its rows into `f`; returns the section line after it.
  std::optional<std::string_view> atoms(std::string_view style, DumpFrame& f) {
    const std::string at = text_.at();
    if (style.empty())
      throw Error(at + "Atoms without its `# style` comment (write_data writes `Atoms # sphere`): nbscope reads the styles "
                       "sphere and atomic; add `# sphere` or `# atomic`");
    const bool sphere = style == "sphere";
    if (!sphere && style != "atomic")
      throw Error(at + "atom style '" + excerpt(style) + "': nbscope reads the styles sphere (id type diameter density x y z) and atomic (id type x y z)");
    if (!atoms_) throw Error(at + "Atoms before the `N atoms` header line");
    if (!sphere && !options_.radius && options_.type_radius.empty())
      throw Error(at + "atom style atomic has no diameter: give --type-radius TYPE:R,... or --radius R");
    const std::size_t first = sphere ? 4 : 2;  // the x column
    const std::size_t columns = first + 3;
    const int dim = options_.force_2d ? 2 : 3;
    dump::RawAtoms raw(dim, true);
    raw.start(*atoms_, static_cast<std::uint64_t>(*atoms_) <= text_.bytes_left() / 8);
    bool periodic[3] = {false, false, false};
    std::int64_t rows = 0;
    std::string_view line;
    std::optional<std::string_view> next;
    while (text_.next(line)) {
      const std::string_view body = strip_comment(line);
      if (body.find_first_not_of(" \t") == std::string_view::npos) continue;
      if (starts_section(body)) {
        next = line;
        break;
      }
      if (rows == *atoms_) throw Error(text_.at() + "more rows in Atoms than the header's " + std::to_string(*atoms_) + " atoms");
      if (raw.first_line == 0) raw.first_line = text_.line_number();
      const std::vector<std::string_view> w = dump::words_of(body);
      if (w.size() != columns && w.size() != columns + 3)
        throw Error(text_.at() + std::to_string(w.size()) + " columns; atom style " + std::string(style) + " has " +
                    std::to_string(columns) + " (" + (sphere ? "id type diameter density x y z" : "id type x y z") + ") or " +
                    std::to_string(columns + 3) + " (and ix iy iz)");
      const std::int64_t id = dump::parse_integer(w[0], text_.at(), "id", false);
      const std::int64_t type = dump::parse_integer(w[1], text_.at(), "type", false);
      if (type < INT32_MIN || type > INT32_MAX) throw Error(text_.at() + "type " + std::to_string(type) + " does not fit 32 bits");
      double radius = 0;
      if (sphere) {
        const double d = number(w[2], "diameter");
        if (!(d > 0)) throw Error(text_.at() + "diameter: '" + excerpt(w[2]) + "' is not > 0 (a point particle has no extent to detect)");
        (void)number(w[3], "density");
        radius = d / 2;
        raw.radius_digits.add(w[2], d);
      } else {
        radius = radius_of(type);
      }
      if (radius < kMinRadius || radius > kMaxRadius)
        throw Error(text_.at() + "radius " + std::to_string(radius) + " is outside the supported radii 1e-100 to 1e100");
      double pos[3] = {0, 0, 0};
      for (int a = 0; a < 3; ++a) {
        const std::string_view v = w[first + static_cast<std::size_t>(a)];
        pos[a] = number(v, a == 0 ? "x" : a == 1 ? "y" : "z");
        if (a < dim) raw.position_digits.add(v, pos[a]);
      }
      if (w.size() == columns + 3)
        for (int a = 0; a < 3; ++a)
          if (dump::parse_integer(w[columns + static_cast<std::size_t>(a)], text_.at(), a == 0 ? "ix" : a == 1 ? "iy" : "iz", false) != 0)
            periodic[a] = true;
      raw.push(id, static_cast<std::int32_t>(type), pos, radius);
      ++rows;
    }
    if (rows < *atoms_)
      throw Error(text_.at() + "the Atoms section has " + std::to_string(rows) + " rows, the header says " + std::to_string(*atoms_) + " atoms");
    for (int a = 0; a < 3; ++a)
      if (periodic[a]) f.box.flags[static_cast<std::size_t>(a)] = "pp";
    dump::finish_frame(raw, f, options_, false, 0, sphere);
    return next;
  }

  double radius_of(std::int64_t type) {
    const auto it = options_.type_radius.find(type);
    if (it != options_.type_radius.end()) return it->second;
    if (options_.radius) return *options_.radius;
    throw Error(text_.at() + "no radius for type " + std::to_string(type) + " (--type-radius names no such type)");
  }

  DumpText& text_;
  const DumpOptions& options_;
  std::optional<std::int64_t> atoms_;  // the `N atoms` header line
};

}  // namespace

bool looks_like_lammps_data(std::string_view head) {
  if (head.find("LAMMPS data file") < head.find('\n')) return true;
  // A hand-written title: an `N atoms` line among the header lines that follow it.
  std::size_t start = head.find('\n');
  for (int lines = 0; start != std::string_view::npos && lines < 40; ++lines) {
    const std::size_t end = head.find('\n', start + 1);
    const std::string_view line = strip_comment(head.substr(start + 1, end == std::string_view::npos ? std::string_view::npos : end - start - 1));
    const std::vector<std::string_view> w = dump::words_of(line);
    if (w.size() == 2 && w[1] == "atoms" && w[0].find_first_not_of("0123456789") == std::string_view::npos) return true;
    if (!w.empty() && starts_section(line)) return false;
    start = end;
  }
  return false;
}

std::string lammps_data_units(std::string_view head) { return std::string(title_value(head.substr(0, head.find('\n')), "units")); }

DumpFrame read_lammps_data(const std::string& path, const DumpOptions& options, std::string* units) {
  DumpText text(path);
  return DataReader(text, options).read(units);
}

DumpFrame parse_lammps_data(const std::string& text, const std::string& where, const DumpOptions& options, std::string* units) {
  DumpText lines(text, where);
  return DataReader(lines, options).read(units);
}

}  // namespace nbscope

#include "core/pairs.hpp"
#include "app/dump_input.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "core/error.hpp"
#include "io/csv.hpp"
#include "io/dump_frames.hpp"
#include "io/dump_ranks.hpp"
#include "io/input_source.hpp"
#include "io/lammps_data.hpp"

namespace nbscope {

namespace {

// "A,B" of --contact-ids: two 1-based column numbers, or two ENTRIES names.
ContactColumns parse_contact_ids(const std::string& text) {
  const std::vector<std::string> parts = split_names("--contact-ids", text);
  if (parts.size() != 2) throw Error("--contact-ids: '" + text + "' is not two columns A,B (numbers from 1, or ENTRIES names)");
  ContactColumns c;
  const auto number = [](const std::string& s) -> int {
    if (s.empty() || s.size() > 6 || !std::all_of(s.begin(), s.end(), [](char ch) { return ch >= '0' && ch <= '9'; })) return 0;
    return std::stoi(s);
  };
  const int a = number(parts[0]), b = number(parts[1]);
  if (a > 0 && b > 0) c.numbers = std::array<int, 2>{a, b};
  else if (a == 0 && b == 0) c.names = std::array<std::string, 2>{parts[0], parts[1]};
  else throw Error("--contact-ids: '" + text + "' mixes a column number and a name (give two numbers from 1, or two names)");
  return c;
}

// "1:0.0015,2:0.00225" of --type-radius.
std::map<std::int64_t, double> parse_type_radius(const std::string& text) {
  std::map<std::int64_t, double> out;
  for (const std::string& item : split_names("--type-radius", text)) {
    const auto colon = item.find(':');
    const auto bad = [&] { return Error("--type-radius: '" + item + "' is not TYPE:RADIUS (e.g. 1:0.0015,2:0.00225)"); };
    if (colon == std::string::npos) throw bad();
    std::size_t used = 0;
    long long type = 0;
    double r = 0;
    try {
      type = std::stoll(item.substr(0, colon), &used);
      if (used != colon) throw bad();
      const std::string rs = item.substr(colon + 1);
      r = std::stod(rs, &used);
      if (used != rs.size()) throw bad();
    } catch (const std::logic_error&) {
      throw bad();
    }
    if (!(r >= kMinRadius && r <= kMaxRadius)) throw Error("--type-radius: '" + item + "': the radius must be positive and finite");
    if (!out.emplace(type, r).second) throw Error("--type-radius: type " + std::to_string(type) + " given twice");
  }
  return out;
}

// "x,y[,z]" of --periodic.
std::array<bool, 3> parse_periodic(const std::string& text) {
  std::array<bool, 3> axes{false, false, false};
  for (const std::string& a : split_names("--periodic", text)) {
    if (a != "x" && a != "y" && a != "z") throw Error("--periodic: '" + a + "' is not an axis (x, y or z: e.g. --periodic x,y)");
    axes[static_cast<std::size_t>(a[0] - 'x')] = true;
  }
  return axes;
}

// "XLO:XHI,YLO:YHI[,ZLO:ZHI]" of --box.
DumpBox parse_box(const std::string& text) {
  // Split by hand: split_names refuses repeats, and a square box repeats its ranges (0:12,0:12).
  std::vector<std::string> axes;
  for (std::size_t start = 0;;) {
    const std::size_t comma = text.find(',', start);
    axes.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  const auto bad = [&] { return Error("--box: '" + text + "' is not XLO:XHI,YLO:YHI[,ZLO:ZHI] with XLO < XHI (finite numbers)"); };
  if (axes.size() < 2 || axes.size() > 3) throw bad();
  DumpBox box;
  for (std::size_t a = 0; a < axes.size(); ++a) {
    const auto colon = axes[a].find(':');
    if (colon == std::string::npos) throw bad();
    const std::string lo_text = axes[a].substr(0, colon), hi_text = axes[a].substr(colon + 1);
    double lo = 0, hi = 0;
    const auto lo_end = std::from_chars(lo_text.data(), lo_text.data() + lo_text.size(), lo);
    const auto hi_end = std::from_chars(hi_text.data(), hi_text.data() + hi_text.size(), hi);
    if (lo_end.ec != std::errc() || lo_end.ptr != lo_text.data() + lo_text.size() || hi_end.ec != std::errc() ||
        hi_end.ptr != hi_text.data() + hi_text.size())
      throw bad();
    if (!(lo < hi) || std::abs(lo) > kMaxCoordinate || std::abs(hi) > kMaxCoordinate) throw bad();
    box.lo[a] = lo;
    box.hi[a] = hi;
    box.flags[a] = "pp";
  }
  return box;
}

std::int64_t timestep_of(const DumpFrameAt& f) { return f.timestep; }
std::int64_t timestep_of(std::int64_t t) { return t; }

// "contacts.750.dump:1: timestep 750 has contacts but no atoms frame; skipped", or for several
// "contacts.250.dump:1: 4 timesteps have contacts but no atoms frame (250, 750, 1250, ...); skipped".
std::string unmatched_contacts_note(const std::vector<DumpFrameAt>& unmatched) {
  const std::string& where = unmatched.front().where;
  if (unmatched.size() == 1)
    return where + ": timestep " + std::to_string(unmatched.front().timestep) + " has contacts but no atoms frame; skipped";
  std::string steps;
  constexpr std::size_t kNamed = 3;
  for (std::size_t k = 0; k < unmatched.size() && k < kNamed; ++k) steps += (k > 0 ? ", " : "") + std::to_string(unmatched[k].timestep);
  if (unmatched.size() > kNamed) steps += ", ...";
  return where + ": " + std::to_string(unmatched.size()) + " timesteps have contacts but no atoms frame (" + steps + "); skipped";
}

// The frames of `paths` where some are data files (one frame each): all read whole, ordered by timestep.
std::vector<DumpFrame> read_frames_and_data(const std::vector<std::string>& paths, const DumpOptions& options) {
  std::vector<std::string> dumps;
  std::vector<DumpFrame> frames;
  for (const std::string& p : paths) {
    if (is_data_file(p)) frames.push_back(read_lammps_data(p, options));
    else dumps.push_back(p);
  }
  if (!dumps.empty())
    for (DumpFrame& f : read_dump_frames(dumps, options)) frames.push_back(std::move(f));
  std::stable_sort(frames.begin(), frames.end(), [](const DumpFrame& a, const DumpFrame& b) { return a.timestep < b.timestep; });
  for (std::size_t k = 1; k < frames.size(); ++k)
    if (frames[k].timestep == frames[k - 1].timestep)
      throw Error(frames[k].where + ": timestep " + std::to_string(frames[k].timestep) + " is also in " + frames[k - 1].where +
                  " (two files of one timestep)");
  if (static_cast<std::int64_t>(frames.size()) > options.max_frames) frames.resize(static_cast<std::size_t>(options.max_frames));
  return frames;
}

}  // namespace

DumpFlags take_dump_flags(Args& args) {
  DumpFlags f;
  if (const auto c = args.value("--contact-ids")) f.columns = parse_contact_ids(*c);
  f.options.radius = args.number("--radius");  // its range is its row's (dump_input_options)
  if (const auto t = args.value("--type-radius")) f.options.type_radius = parse_type_radius(*t);
  f.options.force_2d = args.flag("--2d");
  f.options.tolerance = args.number("--tolerance");
  if (const auto p = args.value("--periodic")) f.options.periodic = parse_periodic(*p);
  if (const auto b = args.value("--box")) f.box = parse_box(*b);
  f.units = args.value("--units");  // one of its row's choices
  f.log = args.value("--log");
  return f;
}

bool is_dump_file(const std::string& path) {
  std::string head;
  try {
    head = peek_input(path, 5, "input file");  // a pipe keeps these bytes for the reader
  } catch (const Error&) {
    return false;  // the reader that opens it says what is wrong, in its words
  }
  if (head.size() >= 2 && static_cast<unsigned char>(head[0]) == 0x1f && static_cast<unsigned char>(head[1]) == 0x8b) return true;
  return head == "ITEM:";
}

std::unique_ptr<RecordedFrames> read_dump_recording(const DumpFlags& flags, std::int64_t max_frames) {
  if (flags.dumps.empty()) throw Error("replay: --dump FILES is required with --contacts");
  std::vector<std::string> paths, contact_paths;
  for (const std::string& spec : flags.dumps)
    for (std::string& p : expand_dump_spec("--dump", spec)) paths.push_back(std::move(p));
  for (const std::string& spec : flags.contacts)
    for (std::string& p : expand_dump_spec("--contacts", spec)) contact_paths.push_back(std::move(p));
  DumpFrameFiles f;
  f.options = flags.options;
  f.columns = flags.columns;
  f.dt = flags.dt;
  f.name = flags.dumps.front();
  // One frame past --frames N, to tell a dump that --frames cut from one that ends there.
  f.options.max_frames = max_frames < std::numeric_limits<std::int64_t>::max() ? max_frames + 1 : max_frames;
  // Regular files are indexed and read again as frames are shown; a pipe only once, so whole.
  const auto regular = [](const std::vector<std::string>& v) {
    return std::all_of(v.begin(), v.end(), [](const std::string& p) {
      std::error_code ec;
      return std::filesystem::is_regular_file(p, ec);
    });
  };
  // A data file is one frame, read whole; so is every dump beside it then.
  const bool data = std::any_of(paths.begin(), paths.end(), [](const std::string& p) { return is_data_file(p); });
  const bool files = regular(paths) && regular(contact_paths) && !data;
  // A run under MPI: one file per rank (a name with `%`), each timestep's pieces read as one frame.
  if (const auto by_rank = split_by_rank(paths); by_rank.size() > 1 && !data) {
    if (!files) throw Error("--dump: per-rank files (" + paths.front() + ", ...) are read from files, not through a pipe");
    index_rank_files(f, by_rank, contact_paths, max_frames);
    return dump_frames(std::move(f));
  }
  std::vector<DumpFrame> whole;
  std::vector<DumpContacts> whole_contacts;
  if (files) {
    f.frames = index_dump_frames(paths, f.options);
  } else {
    whole = data ? read_frames_and_data(paths, f.options) : read_dump_frames(paths, f.options);
    for (const DumpFrame& d : whole) f.frames.push_back(DumpFrameAt{d.timestep, d.time, d.elements.size(), 0, 0, 0, d.where});
  }
  const bool cut = static_cast<std::int64_t>(f.frames.size()) > max_frames;
  if (cut) {
    f.frames.resize(static_cast<std::size_t>(max_frames));
    if (!files) whole.resize(f.frames.size());
  }
  if (!contact_paths.empty()) {
    if (files) {
      f.contacts = index_dump_contacts(contact_paths, flags.columns);
    } else {
      whole_contacts = read_dump_contacts(contact_paths, flags.columns);
      for (const DumpContacts& c : whole_contacts)
        f.contacts.push_back(DumpFrameAt{c.timestep, std::nullopt, static_cast<std::int64_t>(c.ids.size()), 0, 0, 0, c.where});
    }
    // --frames N keeps the contact frames of the dump frames kept.
    if (cut) {
      const std::int64_t last = f.frames.back().timestep;
      std::erase_if(f.contacts, [&](const DumpFrameAt& c) { return c.timestep > last; });
      std::erase_if(whole_contacts, [&](const DumpContacts& c) { return c.timestep > last; });
    }
    // A contact frame no atoms frame matches (contacts dumped more often than atoms): nothing to check
    // it against; skipped, with one note for all of them.
    std::vector<DumpFrameAt> unmatched;
    std::erase_if(f.contacts, [&](const DumpFrameAt& c) {
      const bool alone = !std::binary_search(f.frames.begin(), f.frames.end(), c.timestep,
                                             [](const auto& a, const auto& b) { return timestep_of(a) < timestep_of(b); });
      if (alone) unmatched.push_back(c);
      return alone;
    });
    if (!unmatched.empty() && f.contacts.empty() && !f.frames.empty())  // nothing left to check: not a note
      throw Error(unmatched.front().where + ": no contact frame has the timestep of an atoms frame (contacts from timestep " +
                  std::to_string(unmatched.front().timestep) + ", atoms from " + std::to_string(f.frames.front().timestep) + ")");
    if (!unmatched.empty()) {
      std::erase_if(whole_contacts, [&](const DumpContacts& c) {
        return std::any_of(unmatched.begin(), unmatched.end(), [&](const DumpFrameAt& u) { return u.timestep == c.timestep; });
      });
      std::fprintf(stderr, "nbscope: note: %s\n", unmatched_contacts_note(unmatched).c_str());
    }
  }
  if (!files) return held_frames(recording_from_dumps(std::move(whole), whole_contacts, flags.dt, f.name));
  f.paths = std::move(paths);
  f.contact_paths = std::move(contact_paths);
  return dump_frames(std::move(f));
}

DumpFrame read_dump_input(const std::string& path, const DumpFlags& flags) {
  if (is_data_file(path)) {
    DumpFrame f = read_lammps_data(path, flags.options);
    if (flags.timestep && *flags.timestep != f.timestep)
      throw Error(path + ": a data file of timestep " + std::to_string(f.timestep) + ", not " + std::to_string(*flags.timestep));
    return f;
  }
  // A seek: only the chosen frame is parsed (a big dump's other frames are counted, not held).
  DumpSeek seek = seek_dump_frame(path, flags.timestep, flags.options);
  if (seek.frames == 0) throw Error(path + ": no frames");
  const std::string range = std::to_string(seek.first_timestep) + ".." + std::to_string(seek.last_timestep);
  if (flags.timestep && !seek.frame)
    throw Error(path + ": no frame of timestep " + std::to_string(*flags.timestep) + " (its timesteps: " + range + ", " +
                std::to_string(seek.frames) + " frames)");
  if (!flags.timestep && seek.frames > 1)
    throw Error(path + ": " + std::to_string(seek.frames) + " frames (timesteps " + range + "): choose one with --timestep S");
  return std::move(*seek.frame);
}

void apply_periodic_flags(const DumpFlags& flags, Elements& elements) {
  if (!flags.options.periodic && !flags.box) return;
  if (!flags.options.periodic) throw Error("--box: needs --periodic x,y[,z] (which axes of the box repeat)");
  if (!flags.box) throw Error("--periodic: needs --box XLO:XHI,YLO:YHI[,ZLO:ZHI] (the period of each axis) for elements from a CSV file");
  const std::array<bool, 3>& axes = *flags.options.periodic;
  if (axes[2] && elements.dim == 2) throw Error("--periodic: z is periodic, but the elements are 2D");
  if (elements.dim == 3 && flags.box->flags[2].empty()) throw Error("--box: the elements are 3D: give ZLO:ZHI too");
  for (int a = 0; a < 3; ++a) {
    elements.box.periodic[a] = axes[static_cast<std::size_t>(a)];
    elements.box.lo[a] = flags.box->lo[a];
    elements.box.hi[a] = flags.box->hi[a];
  }
  wrap_into_box(elements);
}

InputFrame read_input_frame(const std::string& path, const DumpFlags& flags) {
  InputFrame in;
  if (is_dump_file(path) || is_data_file(path)) {
    if (flags.box) throw Error("--box: " + path + " is a dump: its box is its BOX BOUNDS (--periodic x,y[,z] makes axes periodic)");
    DumpFrame f = read_dump_input(path, flags);
    if (!flags.options.force_2d && is_planar(f)) {
      make_planar(f);
      in.note = planar_note(path);
    }
    in.elements = std::move(f.elements);
    in.ids = f.ids;
    in.precision = f.precision;
    f.elements = Elements();
    in.dump = std::move(f);
    return in;
  }
  if (flags.timestep || flags.columns.numbers || flags.columns.names || flags.options.radius || !flags.options.type_radius.empty() ||
      flags.options.force_2d || flags.options.tolerance)
    throw Error(path + ": not a dump (no ITEM: line first): --timestep, --contact-ids, --radius, --type-radius, --2d and --tolerance "
                       "read dumps");
  in.elements = read_elements_csv(path);
  apply_periodic_flags(flags, in.elements);
  return in;
}

std::unique_ptr<RecordedFrames> read_input_recording(const std::string& path, const DumpFlags& flags, std::int64_t max_frames) {
  if (is_dump_file(path) || is_data_file(path)) {
    if (flags.box) throw Error("--box: " + path + " is a dump: its box is its BOX BOUNDS (--periodic x,y[,z] makes axes periodic)");
    DumpFlags every = flags;
    every.dumps = {path};  // every frame of it, without contacts
    return read_dump_recording(every, max_frames);
  }
  InputFrame in = read_input_frame(path, flags);
  Recording r;
  r.path = path;
  RecordedFrame& f = r.frames.emplace_back();
  f.elements = std::move(in.elements);
  return held_frames(std::move(r));
}

const std::vector<OptionSpec>& dump_input_options() {
  static const std::vector<OptionSpec> options = {
      {"--timestep", "S", "the only frame", "with --input FILE.dump: the frame of timestep S (a dump with several frames needs it)",
       integer_value(0, std::numeric_limits<long long>::max())},
      {"--contact-ids", "A,B", "id1 id2 by name, else LIGGGHTS's pair/gran/local `pos id` order (7,8)",
       "the two columns of a dump local file holding a contact's atom ids: numbers from 1, or ENTRIES names"},
      {"--radius", "R", "", "every atom's radius, for a dump without a radius or diameter column",
       number_value(kMinRadius, kMaxRadius, "must be positive and finite")},
      {"--type-radius", "T:R,...", "", "radii by atom type, for a dump without a radius or diameter column (1:0.0015,2:0.00225)"},
      {"--2d", "", "2D without a z column, or with every z 0 in a thin z box (a `dimension 2` run: a note says so)",
       "read a dump as 2D: z dropped (LAMMPS's and LIGGGHTS's dimension 2 write z = 0)",
       flag_value()},
      {"--tolerance", "L", "half a unit of the last printed digit", "the precision band of a dump's contacts: a disagreement whose "
                                                                   "gap is within L is at the boundary, not a violation",
       number_value(0, std::numeric_limits<double>::infinity(), "must be 0 or more (a length)")},
      {"--periodic", "x,y[,z]", "a dump's pp axes", "these axes periodic: contacts by the minimum image (nbs and brute)"},
      {"--box", "XLO:XHI,YLO:YHI[,ZLO:ZHI]", "a dump's BOX BOUNDS", "the periodic box of elements from a CSV file (with --periodic)"},
      {"--units", "lj|real|metal|si|cgs|micro|nano", "a dump's ITEM: UNITS, a data file's `units =`, else --log's, else m and s",
       "the run's LAMMPS units: every length and time printed and shown is in them (lj: sigma and tau; real: Angstrom "
       "and fs; metal: Angstrom and ps; si: m and s; cgs: cm and s; micro: micrometre and microsecond; nano: nm and ns)",
       choice_value({"lj", "real", "metal", "si", "cgs", "micro", "nano"})},
      {"--log", "log.lammps", "", "the run's LAMMPS log: its `units` command (when --units is not given) and its `timestep` "
                                  "(when --dt is not given)"},
  };
  return options;
}

const std::vector<OptionSpec>& dump_replay_options() {
  static const std::vector<OptionSpec> options = [] {
    std::vector<OptionSpec> o = {
        {"--dump", "FILES", "", "LAMMPS/LIGGGHTS dump custom frames (id, x y [z], radius ...): a file or a quoted glob, .gz too, "
                                "or a LAMMPS data file (one frame); repeatable; frames ordered by timestep", repeated_value()},
        {"--contacts", "FILES", "", "the code's contact list, dump local (LIGGGHTS compute pair/gran/local pos id): the recorded pairs",
         repeated_value()},
        {"--dt", "S", "", "seconds per timestep: a frame's time is S x timestep (ITEM: TIME wins; neither: the timestep)",
         number_value(std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::infinity(),
                      "must be positive (seconds per timestep)")},
    };
    for (const OptionSpec& s : dump_input_options())
      if (std::string_view(s.name) != "--timestep") o.push_back(s);
    return o;
  }();
  return options;
}

OptionSpec touching_option() {
  return {"--touching", "inclusive|strict", "inclusive",
          "whether a pair at exactly zero gap is a contact: inclusive |c_i - c_j| <= r_i + r_j, or strict < (LAMMPS, LIGGGHTS)",
          choice_value({"inclusive", "strict"},
                       "{} is not inclusive (|c_i - c_j| <= r_i + r_j, the default) or strict (<, as LAMMPS and LIGGGHTS)")};
}

}  // namespace nbscope

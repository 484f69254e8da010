// nbscope io: per-rank dump files as one frame per timestep (dump_ranks.hpp).
#include "io/dump_ranks.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <numeric>
#include <set>

#include "core/error.hpp"
#include "io/dump_text.hpp"

namespace nbscope {

namespace {

// A name cut into its digit runs and what lies between them ("atoms.1.500.dump": "atoms.", "1", ".", "500", ".dump").
struct NameParts {
  std::vector<std::string> text;  // text[k] comes before runs[k]; one more than runs (the tail)
  std::vector<std::int64_t> runs;
};

NameParts parts_of(const std::string& name) {
  NameParts p;
  std::string text;
  std::size_t k = 0;
  while (k < name.size()) {
    if (std::isdigit(static_cast<unsigned char>(name[k])) == 0) {
      text += name[k++];
      continue;
    }
    std::size_t end = k;
    while (end < name.size() && std::isdigit(static_cast<unsigned char>(name[end])) != 0) ++end;
    p.text.push_back(std::move(text));
    text.clear();
    p.runs.push_back(end - k > 15 ? -1 : std::stoll(name.substr(k, end - k)));
    k = end;
  }
  p.text.push_back(std::move(text));
  return p;
}

// The name with digit run `skip` left out, as a grouping key.
std::string key_without(const NameParts& p, std::size_t skip) {
  std::string key;
  for (std::size_t k = 0; k < p.runs.size(); ++k) key += p.text[k] + (k == skip ? "%" : std::to_string(p.runs[k]));
  return key + p.text.back();
}

}  // namespace

int rank_run_of(const std::vector<std::string>& paths) {
  if (paths.size() < 2) return -1;
  std::vector<NameParts> parts;
  for (const std::string& p : paths) parts.push_back(parts_of(p));
  const std::size_t runs = parts.front().runs.size();
  for (const NameParts& p : parts)
    if (p.runs.size() != runs || p.text != parts.front().text) return -1;
  for (std::size_t rank_run = 0; rank_run < runs; ++rank_run) {
    std::map<std::string, std::set<std::int64_t>> groups;
    bool repeated = false;
    for (const NameParts& p : parts) repeated = !groups[key_without(p, rank_run)].insert(p.runs[rank_run]).second || repeated;
    if (repeated) continue;
    const std::size_t ranks = groups.begin()->second.size();
    const bool numbered = ranks >= 2 && std::all_of(groups.begin(), groups.end(), [&](const auto& g) {
      return g.second.size() == ranks && *g.second.begin() == 0 && *g.second.rbegin() == static_cast<std::int64_t>(ranks) - 1;
    });
    if (numbered) return static_cast<int>(rank_run);
  }
  return -1;
}

std::int64_t digit_run(const std::string& path, int run) {
  const NameParts p = parts_of(path);
  return run >= 0 && static_cast<std::size_t>(run) < p.runs.size() ? p.runs[static_cast<std::size_t>(run)] : -1;
}

std::string with_digit_run(const std::string& path, int run, std::int64_t value) {
  const NameParts p = parts_of(path);
  std::string out;
  for (std::size_t k = 0; k < p.runs.size(); ++k)
    out += p.text[k] + std::to_string(static_cast<int>(k) == run ? value : p.runs[k]);
  return out + p.text.back();
}

std::vector<std::vector<std::string>> split_by_rank(const std::vector<std::string>& paths) {
  const int run = rank_run_of(paths);
  if (run < 0) return {paths};
  std::vector<std::vector<std::string>> by_rank;
  for (const std::string& p : paths) {
    const auto rank = static_cast<std::size_t>(digit_run(p, run));
    if (by_rank.size() <= rank) by_rank.resize(rank + 1);
    by_rank[rank].push_back(p);
  }
  return by_rank;
}

namespace {

// Rank `rank`'s frames must be rank 0's timesteps, one for one.
void expect_aligned(const std::vector<DumpFrameAt>& zero, const std::vector<DumpFrameAt>& other, std::size_t rank, const char* what) {
  const auto timesteps = [](const std::vector<DumpFrameAt>& v) {
    std::string s;
    for (std::size_t k = 0; k < v.size() && k < 4; ++k) s += (k > 0 ? ", " : "") + std::to_string(v[k].timestep);
    return s + (v.size() > 4 ? ", ..." : "");
  };
  bool same = zero.size() == other.size();
  for (std::size_t k = 0; same && k < zero.size(); ++k) same = zero[k].timestep == other[k].timestep;
  if (!same)
    throw Error((other.empty() ? std::string("rank ") + std::to_string(rank) : other.front().where) + ": rank " + std::to_string(rank) +
                "'s " + what + " frames (timesteps " + timesteps(other) + ") are not rank 0's (" + timesteps(zero) +
                "): per-rank files of one run hold the same timesteps");
}

}  // namespace

void index_rank_files(DumpFrameFiles& f, const std::vector<std::vector<std::string>>& atoms_by_rank,
                      const std::vector<std::string>& contact_paths, std::int64_t max_frames) {
  const std::size_t ranks = atoms_by_rank.size();
  const auto cut = [&](std::vector<DumpFrameAt>& frames) {
    if (static_cast<std::int64_t>(frames.size()) > max_frames) frames.resize(static_cast<std::size_t>(max_frames));
  };
  f.paths = atoms_by_rank.front();
  f.frames = index_dump_frames(f.paths, f.options);
  cut(f.frames);
  f.other_ranks.resize(ranks - 1);
  for (std::size_t r = 1; r < ranks; ++r) {
    DumpFrameFiles::Rank& rank = f.other_ranks[r - 1];
    rank.paths = atoms_by_rank[r];
    rank.frames = index_dump_frames(rank.paths, f.options);
    cut(rank.frames);
    expect_aligned(f.frames, rank.frames, r, "atoms");
  }
  if (contact_paths.empty()) return;
  const std::vector<std::vector<std::string>> contacts_by_rank = split_by_rank(contact_paths);
  if (contacts_by_rank.size() != ranks)
    throw Error("--contacts: the atoms are in " + std::to_string(ranks) + " ranks' files, the contacts in " +
                std::to_string(contacts_by_rank.size()) + " (a dump local name holds `%` too: contacts.%.*.dump)");
  f.contact_paths = contacts_by_rank.front();
  f.contacts = index_dump_contacts(f.contact_paths, f.columns);
  const std::int64_t last = f.frames.empty() ? 0 : f.frames.back().timestep;
  std::erase_if(f.contacts, [&](const DumpFrameAt& c) { return c.timestep > last; });
  for (std::size_t r = 1; r < ranks; ++r) {
    DumpFrameFiles::Rank& rank = f.other_ranks[r - 1];
    rank.contact_paths = contacts_by_rank[r];
    rank.bare_contacts = std::all_of(rank.contact_paths.begin(), rank.contact_paths.end(), is_bare_rows);
    if (!rank.bare_contacts) {
      rank.contacts = index_dump_contacts(rank.contact_paths, f.columns);
      std::erase_if(rank.contacts, [&](const DumpFrameAt& c) { return c.timestep > last; });
      expect_aligned(f.contacts, rank.contacts, r, "contact");
      continue;
    }
    // Bare rows: the timestep is the one of rank 0's file of the same name; that file holds one frame.
    std::vector<int> frames_in(f.contact_paths.size(), 0);
    for (const DumpFrameAt& c : f.contacts) ++frames_in[c.file];
    for (const DumpFrameAt& c : f.contacts) {
      if (frames_in[c.file] != 1)
        throw Error(rank.contact_paths.at(c.file) + ": bare rows (only rank 0's dump local file has the ITEM lines) can be read only "
                    "beside a rank-0 file of one frame, and " + f.contact_paths[c.file] + " has " + std::to_string(frames_in[c.file]) +
                    " (write one file a frame: contacts.%.*.dump)");
      rank.contacts.push_back(DumpFrameAt{c.timestep, std::nullopt, 0, c.file, 0, 1, rank.contact_paths.at(c.file) + ":1"});
    }
  }
}

DumpFrame merge_rank_frames(std::vector<DumpFrame> pieces) {
  if (pieces.size() == 1) return std::move(pieces.front());
  DumpFrame out;
  const DumpFrame& first = pieces.front();
  out.timestep = first.timestep;
  out.time = first.time;
  out.box = first.box;  // every rank writes the global box
  out.where = first.where;
  std::int64_t n = 0;
  for (const DumpFrame& p : pieces) n += p.elements.size();
  // Rows of every rank by ascending id: (id, rank, row).
  std::vector<std::array<std::int64_t, 3>> order;
  order.reserve(static_cast<std::size_t>(n));
  for (std::size_t r = 0; r < pieces.size(); ++r) {
    out.precision = std::max(out.precision, pieces[r].precision);
    for (std::size_t row = 0; row < pieces[r].ids.size(); ++row)
      order.push_back({pieces[r].ids[row], static_cast<std::int64_t>(r), static_cast<std::int64_t>(row)});
  }
  std::sort(order.begin(), order.end());
  out.elements.dim = first.elements.dim;
  out.elements.box = first.elements.box;
  out.elements.resize(n);
  out.ids.resize(static_cast<std::size_t>(n));
  out.ranks.resize(static_cast<std::size_t>(n));
  const bool typed = std::all_of(pieces.begin(), pieces.end(), [](const DumpFrame& p) { return !p.types.empty() || p.ids.empty(); });
  if (typed) out.types.resize(static_cast<std::size_t>(n));
  // The kept columns (DumpOptions::keep_columns) when every rank's file has the same ones.
  const bool columned = first.columns && std::all_of(pieces.begin(), pieces.end(), [&](const DumpFrame& p) {
    return p.columns && p.columns->names == first.columns->names;
  });
  std::shared_ptr<AtomColumns> columns;
  if (columned) {
    columns = std::make_shared<AtomColumns>();
    columns->header = first.columns->header;
    columns->names = first.columns->names;
    columns->values.assign(columns->names.size(), std::vector<double>(static_cast<std::size_t>(n)));
  }
  for (std::size_t k = 0; k < order.size(); ++k) {
    const auto [id, r, row] = order[k];
    if (k > 0 && order[k - 1][0] == id)
      throw Error(pieces[static_cast<std::size_t>(r)].where + ": atom " + std::to_string(id) + " is also in rank " +
                  std::to_string(order[k - 1][1]) + "'s frame (" + pieces[static_cast<std::size_t>(order[k - 1][1])].where +
                  "): an atom belongs to one rank");
    const DumpFrame& p = pieces[static_cast<std::size_t>(r)];
    const auto i = static_cast<Eigen::Index>(k);
    out.elements.x[i] = p.elements.x[row];
    out.elements.y[i] = p.elements.y[row];
    if (out.elements.dim == 3) out.elements.z[i] = p.elements.z[row];
    out.elements.r[i] = p.elements.r[row];
    out.ids[k] = id;
    out.ranks[k] = static_cast<std::int32_t>(r);
    if (typed) out.types[k] = p.types[static_cast<std::size_t>(row)];
    if (columns)
      for (std::size_t c = 0; c < columns->values.size(); ++c) columns->values[c][k] = p.columns->values[c][static_cast<std::size_t>(row)];
  }
  out.columns = std::move(columns);
  // How the run split its box among the ranks (every rank's file holds the global box): drawn by the views.
  Bounds box;
  for (std::size_t a = 0; a < 3; ++a) {
    box.min[a] = out.box.lo[a];
    box.max[a] = out.box.hi[a];
  }
  if (auto split = infer_subdomains(out.elements, out.ranks, static_cast<int>(pieces.size()), box))
    out.subdomains = std::make_shared<const Subdomains>(*split);
  return out;
}

DumpContacts merge_rank_contacts(std::vector<DumpContacts> pieces) {
  if (pieces.size() == 1) return std::move(pieces.front());
  DumpContacts out;
  out.timestep = pieces.front().timestep;
  out.path = pieces.front().path;
  out.where = pieces.front().where;
  // A pair (either order) listed by another rank before is the same contact seen from both sides.
  std::map<std::array<std::int64_t, 2>, std::size_t> first_rank;
  for (std::size_t r = 0; r < pieces.size(); ++r) {
    for (std::size_t k = 0; k < pieces[r].ids.size(); ++k) {
      const auto [a, b] = pieces[r].ids[k];
      const std::array<std::int64_t, 2> key{std::min(a, b), std::max(a, b)};
      const auto [it, fresh] = first_rank.emplace(key, r);
      if (!fresh && it->second != r) continue;
      out.ids.push_back(pieces[r].ids[k]);
      out.lines.push_back(k < pieces[r].lines.size() ? pieces[r].lines[k] : 0);
    }
  }
  return out;
}

bool is_bare_rows(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char head[5] = {};
  in.read(head, 5);
  if (in.gcount() >= 2 && static_cast<unsigned char>(head[0]) == 0x1f && static_cast<unsigned char>(head[1]) == 0x8b) return false;
  return in.gcount() == 0 || std::string(head, static_cast<std::size_t>(in.gcount())) != "ITEM:";
}

DumpContacts read_bare_contacts(const std::string& path, const std::string& header_path, const DumpFrameAt& header_at,
                                const ContactColumns& columns) {
  // Rank 0's items up to its ENTRIES line (which names the columns), then this file's rows.
  std::string header;
  std::size_t header_lines = 0;
  {
    DumpText text(header_path, header_at.offset, header_at.line);
    std::string_view line;
    bool count_next = false;
    while (text.next(line)) {
      ++header_lines;
      if (count_next) {
        header += "@ENTRIES@\n";
        count_next = false;
        continue;
      }
      header.append(line).push_back('\n');
      if (line.rfind("ITEM: NUMBER OF", 0) == 0) count_next = true;
      if (line.rfind("ITEM: ENTRIES", 0) == 0) break;
    }
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot be read");
  std::string rows((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!rows.empty() && rows.back() != '\n') rows.push_back('\n');
  const auto count = static_cast<std::int64_t>(std::count(rows.begin(), rows.end(), '\n'));
  header.replace(header.find("@ENTRIES@"), 9, std::to_string(count));
  std::vector<DumpContacts> frames;
  try {
    frames = parse_dump_contacts(header + rows, path, columns);
  } catch (const Error& e) {
    // "<path>:<line>: ..." of the text read names the file's own line.
    std::string what = e.what();
    const std::string prefix = path + ":";
    if (what.rfind(prefix, 0) == 0) {
      const std::size_t colon = what.find(':', prefix.size());
      try {
        const long line = std::stol(what.substr(prefix.size(), colon - prefix.size())) - static_cast<long>(header_lines);
        what = prefix + std::to_string(std::max(line, 1L)) + what.substr(colon);
      } catch (const std::exception&) {
      }
    }
    throw Error(what);
  }
  DumpContacts c = std::move(frames.front());
  for (std::int64_t& line : c.lines) line -= static_cast<std::int64_t>(header_lines);
  c.where = path + ":1";
  return c;
}

}  // namespace nbscope

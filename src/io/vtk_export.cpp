// --export-vtk's files (vtk_export.hpp). The XML follows VTK's "XML File Formats" page: PolyData,
// one Piece, ASCII DataArrays; offsets are each cell's end in connectivity.
#include "io/vtk_export.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <iterator>
#include <map>
#include <sstream>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace nbscope {

namespace {

// Numbers written shortest-round-trip, so a reader gets the very doubles nbscope had.
template <class T>
void put(std::string& out, T v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

template <class T, class Get>
void data_array(std::string& out, const char* type, const std::string& name, std::size_t n, Get get, int components = 1) {
  out += "        <DataArray type=\"";
  out += type;
  out += "\" Name=\"" + name + "\"";
  if (components > 1) out += " NumberOfComponents=\"" + std::to_string(components) + "\"";
  out += " format=\"ascii\">\n";
  for (std::size_t k = 0; k < n; ++k) {
    out += k % 12 == 0 ? (k > 0 ? "\n          " : "          ") : " ";
    put<T>(out, get(k));
  }
  out += "\n        </DataArray>\n";
}

// An XML attribute value: a column's name with & < > " escaped.
std::string escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

struct Line {
  Pair pair;
  std::int32_t kind;
};

// R and A merged: each pair once, kind by which of them holds it.
std::vector<Line> lines_of(const VtkFrame& f) {
  std::vector<Line> out;
  static const PairList kNone;
  const PairList& r = f.checked && f.reference != nullptr ? *f.reference : kNone;
  const PairList& a = f.detected != nullptr ? *f.detected : kNone;
  const auto n = f.elements->size();
  const auto valid = [n](const Pair& p) { return p.i >= 0 && p.j >= 0 && p.i < n && p.j < n; };
  std::size_t i = 0, j = 0;
  while (i < r.size() || j < a.size()) {
    if (j == a.size() || (i < r.size() && r[i] < a[j])) {
      if (valid(r[i])) out.push_back({r[i], kVtkMissing});
      ++i;
    } else if (i == r.size() || a[j] < r[i]) {
      if (valid(a[j])) out.push_back({a[j], f.checked ? kVtkExtra : kVtkContact});
      ++j;
    } else {
      if (valid(r[i])) out.push_back({r[i], kVtkContact});
      ++i;
      ++j;
    }
  }
  return out;
}

}  // namespace

std::string vtk_polydata(const VtkFrame& f) {
  const Elements& e = *f.elements;
  const auto n = static_cast<std::size_t>(e.size());
  const std::vector<Line> lines = lines_of(f);
  static const PairList kNone;
  const PairList& touching = f.checked && f.reference != nullptr ? *f.reference : f.detected != nullptr ? *f.detected : kNone;
  const std::vector<double> overlap = element_overlaps(e, touching);
  std::string out;
  out.reserve(n * 64 + lines.size() * 24 + 1024);
  out += "<?xml version=\"1.0\"?>\n";
  out += "<!-- nbscope export, timestep " + std::to_string(f.timestep) + "; cell data kind: 0 atom, 1 contact, 2 missing, 3 extra -->\n";
  out += "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <PolyData>\n";
  out += "    <Piece NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfVerts=\"" + std::to_string(n) + "\" NumberOfLines=\"" +
         std::to_string(lines.size()) + "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";
  out += "      <PointData Scalars=\"radius\">\n";
  const bool with_ids = f.ids != nullptr && f.ids->size() == n;
  data_array<std::int64_t>(out, "Int64", "id", n, [&](std::size_t k) { return with_ids ? (*f.ids)[k] : static_cast<std::int64_t>(k); });
  data_array<double>(out, "Float64", "radius", n, [&](std::size_t k) { return e.r[static_cast<Eigen::Index>(k)]; });
  data_array<double>(out, "Float64", "overlap", n, [&](std::size_t k) { return overlap[k]; });
  if (f.columns != nullptr)
    for (std::size_t c = 0; c < f.columns->names.size(); ++c) {
      const std::vector<double>& v = f.columns->values[c];
      if (v.size() != n || f.columns->names[c] == "id" || f.columns->names[c] == "radius" || f.columns->names[c] == "overlap") continue;
      if (f.columns->names[c] == "type" || f.columns->names[c] == "proc")
        data_array<std::int32_t>(out, "Int32", f.columns->names[c], n, [&](std::size_t k) { return static_cast<std::int32_t>(v[k]); });
      else
        data_array<double>(out, "Float64", escaped(f.columns->names[c]), n, [&](std::size_t k) { return v[k]; });
    }
  out += "      </PointData>\n      <CellData Scalars=\"kind\">\n";
  data_array<std::int32_t>(out, "Int32", "kind", n + lines.size(),
                           [&](std::size_t k) { return k < n ? std::int32_t{kVtkAtom} : lines[k - n].kind; });
  data_array<double>(out, "Float64", "gap", n + lines.size(),
                     [&](std::size_t k) { return k < n ? 0.0 : contact_gap(e, lines[k - n].pair.i, lines[k - n].pair.j); });
  out += "      </CellData>\n      <Points>\n";
  data_array<double>(out, "Float64", "Points", 3 * n,
                     [&](std::size_t k) {
                       const auto row = static_cast<Eigen::Index>(k / 3);
                       const int a = static_cast<int>(k % 3);
                       return a < e.dim ? e.axis(a)[row] : 0.0;
                     },
                     3);
  out += "      </Points>\n      <Verts>\n";
  data_array<std::int64_t>(out, "Int64", "connectivity", n, [](std::size_t k) { return static_cast<std::int64_t>(k); });
  data_array<std::int64_t>(out, "Int64", "offsets", n, [](std::size_t k) { return static_cast<std::int64_t>(k + 1); });
  out += "      </Verts>\n      <Lines>\n";
  data_array<std::int64_t>(out, "Int64", "connectivity", 2 * lines.size(), [&](std::size_t k) {
    const Pair& p = lines[k / 2].pair;
    return static_cast<std::int64_t>(k % 2 == 0 ? p.i : p.j);
  });
  data_array<std::int64_t>(out, "Int64", "offsets", lines.size(), [](std::size_t k) { return static_cast<std::int64_t>(2 * (k + 1)); });
  out += "      </Lines>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  return out;
}

VtkSeries::VtkSeries(std::string dir) : dir_(std::move(dir)) {
  if (dir_.empty()) throw Error("--export-vtk: missing directory name");
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (std::filesystem::exists(dir_) && !std::filesystem::is_directory(dir_)) throw Error("--export-vtk: " + dir_ + ": exists and is not a directory");
  if (!std::filesystem::is_directory(dir_)) throw Error("--export-vtk: " + dir_ + ": cannot make it (" + ec.message() + ")");
  check_output_path(dir_ + "/series.pvd");  // writable: refused before any frame runs
}

void VtkSeries::add(const VtkFrame& frame) {
  const std::string name = "frame_" + std::to_string(frame.timestep) + ".vtp";
  const std::string text = vtk_polydata(frame);
  write_bytes_atomically(dir_ + "/" + name, text.data(), text.size());
  files_.emplace_back(frame.timestep, name);
}

void VtkSeries::finish() {
  std::map<std::int64_t, std::string> by_step;
  for (const auto& [step, name] : files_) by_step[step] = name;
  std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n";
  for (const auto& [step, name] : by_step)
    out += "    <DataSet timestep=\"" + std::to_string(step) + "\" group=\"\" part=\"0\" file=\"" + name + "\"/>\n";
  out += "  </Collection>\n</VTKFile>\n";
  write_bytes_atomically(dir_ + "/series.pvd", out.data(), out.size());
}

}  // namespace nbscope

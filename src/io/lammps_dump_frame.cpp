#include "io/lammps_dump_frame.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>

#include "core/error.hpp"

namespace nbscope::dump {

void RawAtoms::start(std::int64_t n, bool by_id_allowed) {
  by_id = by_id_allowed && n > 0 && n <= kMaxElements;
  if (by_id) {
    const auto k = static_cast<std::size_t>(n);
    x.resize(n);
    y.resize(n);
    if (dim == 3) z.resize(n);
    r.resize(n);
    for (Eigen::ArrayXd& c : kept_values) c.resize(n);
    if (with_types) types.assign(k, 0);
    file_row.assign(k, 0);
    size = n;
    return;
  }
  grow(std::min<std::int64_t>(n, std::int64_t{1} << 24));
}

void RawAtoms::grow(Eigen::Index n) {
  n = std::max(n, size);
  ids.reserve(static_cast<std::size_t>(n));
  if (with_types) types.reserve(static_cast<std::size_t>(n));
  file_row.reserve(static_cast<std::size_t>(n));
  x.conservativeResize(n);
  y.conservativeResize(n);
  if (dim == 3) z.conservativeResize(n);
  r.conservativeResize(n);
  for (Eigen::ArrayXd& c : kept_values) c.conservativeResize(n);
}

void RawAtoms::leave_by_id() {
  by_id = false;
  Eigen::Index kept = 0;
  ids.reserve(static_cast<std::size_t>(size));
  for (Eigen::Index k = 0; k < size; ++k) {
    const auto s = static_cast<std::size_t>(k);
    if (file_row[s] == 0) continue;
    const auto d = static_cast<std::size_t>(kept);
    x[kept] = x[k];
    y[kept] = y[k];
    if (dim == 3) z[kept] = z[k];
    r[kept] = r[k];
    for (Eigen::ArrayXd& c : kept_values) c[kept] = c[k];
    ids.push_back(k + 1);
    if (with_types) types[d] = types[s];
    file_row[d] = file_row[s] - 1;
    ++kept;
  }
  size = kept;
  const auto n = static_cast<std::size_t>(kept);
  if (with_types) types.resize(n);
  file_row.resize(n);
}

void repeated_id(const RawAtoms& raw, const DumpFrame& frame, std::uint32_t a, std::uint32_t b) {
  const std::size_t la = raw.first_line + std::min(raw.file_row[a], raw.file_row[b]);
  const std::size_t lb = raw.first_line + std::max(raw.file_row[a], raw.file_row[b]);
  const std::string path = frame.where.substr(0, frame.where.rfind(':'));
  throw Error(path + ":" + std::to_string(lb) + ": atom id " + std::to_string(raw.ids[a]) + " appears twice in the frame of timestep " +
              std::to_string(frame.timestep) + " (lines " + std::to_string(la) + " and " + std::to_string(lb) + ")");
}

namespace {

// Row order by ascending id: a slot per id when the ids are dense (LAMMPS's 1..N with gaps), else
// a sort of (id, row). Repeated ids are refused either way.
std::vector<std::uint32_t> id_order(const RawAtoms& raw, const DumpFrame& where) {
  const std::size_t n = raw.ids.size();
  std::vector<std::uint32_t> order;
  if (n == 0) return order;
  const auto [lo_it, hi_it] = std::minmax_element(raw.ids.begin(), raw.ids.end());
  const std::int64_t lo = *lo_it, hi = *hi_it;
  if (std::adjacent_find(raw.ids.begin(), raw.ids.end(), std::greater_equal<>()) == raw.ids.end()) {
    order.resize(n);  // `dump_modify sort id`: already in order
    for (std::size_t k = 0; k < n; ++k) order[k] = static_cast<std::uint32_t>(k);
    return order;
  }
  constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();
  if (hi - lo < static_cast<std::int64_t>(2 * n + 1024) && hi - lo >= 0) {
    std::vector<std::uint32_t> slot(static_cast<std::size_t>(hi - lo) + 1, kEmpty);
    for (std::size_t k = 0; k < n; ++k) {
      std::uint32_t& s = slot[static_cast<std::size_t>(raw.ids[k] - lo)];
      if (s != kEmpty) repeated_id(raw, where, s, static_cast<std::uint32_t>(k));
      s = static_cast<std::uint32_t>(k);
    }
    order.reserve(n);
    for (std::uint32_t s : slot)
      if (s != kEmpty) order.push_back(s);
    return order;
  }
  std::vector<std::pair<std::int64_t, std::uint32_t>> keyed(n);
  for (std::size_t k = 0; k < n; ++k) keyed[k] = {raw.ids[k], static_cast<std::uint32_t>(k)};
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t k = 1; k < n; ++k)
    if (keyed[k].first == keyed[k - 1].first) repeated_id(raw, where, keyed[k - 1].second, keyed[k].second);
  order.resize(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = keyed[k].second;
  return order;
}

// The rows put in `order` (order[k]: the row that goes to k) in place, cycle by cycle; `order`
// becomes the identity.
void permute(RawAtoms& raw, std::vector<std::uint32_t>& order) {
  std::vector<Eigen::ArrayXd*> cols = {&raw.x, &raw.y, &raw.r};
  if (raw.dim == 3) cols.push_back(&raw.z);
  for (Eigen::ArrayXd& c : raw.kept_values) cols.push_back(&c);
  std::vector<double> saved(cols.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (order[i] == i) continue;
    for (std::size_t c = 0; c < cols.size(); ++c) saved[c] = (*cols[c])[static_cast<Eigen::Index>(i)];
    const std::int64_t saved_id = raw.ids[i];
    const std::int32_t saved_type = raw.with_types ? raw.types[i] : 0;
    std::size_t j = i;
    for (;;) {
      const std::size_t k = order[j];
      order[j] = static_cast<std::uint32_t>(j);
      const auto dj = static_cast<Eigen::Index>(j), dk = static_cast<Eigen::Index>(k);
      if (k == i) {
        for (std::size_t c = 0; c < cols.size(); ++c) (*cols[c])[dj] = saved[c];
        raw.ids[j] = saved_id;
        if (raw.with_types) raw.types[j] = saved_type;
        break;
      }
      for (std::size_t c = 0; c < cols.size(); ++c) (*cols[c])[dj] = (*cols[c])[dk];
      raw.ids[j] = raw.ids[k];
      if (raw.with_types) raw.types[j] = raw.types[k];
      j = k;
    }
  }
}

// The frame's columns (DumpFrame::columns): `type`, then each kept column that held numbers only.
std::shared_ptr<const AtomColumns> kept_columns(RawAtoms& raw, const std::vector<std::int32_t>& types) {
  auto out = std::make_shared<AtomColumns>();
  out->header = raw.header;
  if (!types.empty()) {
    out->names.emplace_back("type");
    out->values.emplace_back(types.begin(), types.end());
  }
  for (std::size_t c = 0; c < raw.kept_values.size(); ++c) {
    if (raw.kept_numeric[c] == 0) continue;
    out->names.push_back(raw.kept_names[c]);
    const Eigen::ArrayXd& v = raw.kept_values[c];
    out->values.emplace_back(v.data(), v.data() + raw.size);
  }
  std::vector<Eigen::ArrayXd>().swap(raw.kept_values);
  return out;
}

// v moved by whole periods into [lo, hi).
double wrap(double v, double lo, double hi) {
  const double length = hi - lo;
  if (v >= lo && v < hi) return v;
  double w = v - length * std::floor((v - lo) / length);
  if (w >= hi || w < lo) w = lo;  // rounding at the edge: x == hi is the image of lo
  return w;
}

}  // namespace

void finish_frame(RawAtoms& raw, DumpFrame& frame, const DumpOptions& options, bool scaled, double box_half, bool from_diameter) {
  if (raw.by_id) {  // every slot is filled: NUMBER OF ATOMS rows, each at its own id
    raw.ids.resize(static_cast<std::size_t>(raw.size));
    for (std::size_t k = 0; k < raw.ids.size(); ++k) raw.ids[k] = static_cast<std::int64_t>(k) + 1;
  } else {
    std::vector<std::uint32_t> order = id_order(raw, frame);
    permute(raw, order);
  }
  std::vector<std::uint32_t>().swap(raw.file_row);
  Elements& e = frame.elements;
  e.dim = raw.dim;
  double length_max = 0;
  for (int a = 0; a < raw.dim; ++a) length_max = std::max(length_max, frame.box.hi[a] - frame.box.lo[a]);
  Eigen::ArrayXd* columns[3] = {&raw.x, &raw.y, &raw.z};
  for (int a = 0; a < raw.dim; ++a) {
    Eigen::ArrayXd& c = *columns[a];
    c.conservativeResize(raw.size);
    const double lo = frame.box.lo[a], hi = frame.box.hi[a];
    if (scaled) c = lo + c * (hi - lo);
    const bool periodic = options.periodic ? (*options.periodic)[static_cast<std::size_t>(a)] : frame.box.flags[static_cast<std::size_t>(a)] == "pp";
    if (periodic) {
      if (!(hi > lo)) throw Error(frame.where + ": a periodic axis with an empty box (lo == hi)");
      for (Eigen::Index k = 0; k < c.size(); ++k) c[k] = wrap(c[k], lo, hi);
      e.box.periodic[a] = true;
      e.box.lo[a] = lo;
      e.box.hi[a] = hi;
    }
    if (c.size() > 0 && c.abs().maxCoeff() > kMaxCoordinate)
      throw Error(frame.where + ": a coordinate outside the supported -1e100 to 1e100");
    (a == 0 ? e.x : a == 1 ? e.y : e.z) = std::move(c);
  }
  raw.r.conservativeResize(raw.size);
  e.r = std::move(raw.r);
  frame.ids = std::move(raw.ids);
  frame.types = std::move(raw.types);
  if (raw.keep_columns) frame.columns = kept_columns(raw, frame.types);
  if (options.tolerance) {
    frame.precision = *options.tolerance;
    return;
  }
  // One format prints a frame's floats (dump_modify format float/line): the most digits any shows
  // is theirs, also for a radius whose %.17g trailing zeros were dropped (0.0015).
  const int digits = std::max(raw.position_digits.significant, raw.radius_digits.significant);
  double position_half = raw.position_digits.half_unit(digits);
  if (scaled) position_half = position_half * length_max + box_half;
  const double radius_half = raw.radius_digits.half_unit(digits) / (from_diameter ? 2 : 1);
  frame.precision = 2 * std::sqrt(static_cast<double>(raw.dim)) * position_half + 2 * radius_half;
}

}  // namespace nbscope::dump

namespace nbscope {

bool is_planar(const DumpFrame& frame) {
  const Elements& e = frame.elements;
  if (e.dim != 3 || (e.size() > 0 && (e.z != 0).any())) return false;
  const double lo = frame.box.lo[2], hi = frame.box.hi[2];
  if (lo == -0.5 && hi == 0.5) return true;
  return e.size() > 0 && hi - lo < 4 * e.r.maxCoeff();
}

void make_planar(DumpFrame& frame) {
  Elements& e = frame.elements;
  if (e.dim != 3) return;
  e.dim = 2;
  e.z.resize(0);
  e.box.periodic[2] = false;
  e.box.lo[2] = e.box.hi[2] = 0;
}

}  // namespace nbscope

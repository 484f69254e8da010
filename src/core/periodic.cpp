// nbscope core: the touching convention's name, and periodic frames: the minimum-image gap,
// wrapping centres into the box, and the checks detectors make before they trust a box.
#include <charconv>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/pairs.hpp"

namespace nbscope {

namespace {
constexpr const char* kAxisName[3] = {"x", "y", "z"};

// The shortest text that reads back as `v`.
std::string fmt(double v) {
  char buf[64];
  const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
  return std::string(buf, end);
}
}  // namespace

const char* touching_name(Touching touching) {
  return touching == Touching::strict ? "strict" : "inclusive";
}

std::vector<double> element_overlaps(const Elements& e, const PairList& pairs) {
  std::vector<double> out(static_cast<std::size_t>(e.size()), 0.0);
  for (const Pair& p : pairs) {
    if (p.i < 0 || p.j < 0 || p.i >= e.size() || p.j >= e.size() || p.i == p.j) continue;  // a code's own pairs may be bad
    const double overlap = -contact_gap(e, p.i, p.j);
    double& a = out[static_cast<std::size_t>(p.i)];
    double& b = out[static_cast<std::size_t>(p.j)];
    a = std::max(a, overlap);
    b = std::max(b, overlap);
  }
  return out;
}

double contact_gap(const Elements& e, ElementId i, ElementId j) {
  return std::sqrt(centre_distance2(e, i, j)) - (e.r[i] + e.r[j]);
}

void wrap_into_box(Elements& e) {
  for (int a = 0; a < e.dim; ++a) {
    if (!e.box.periodic[a]) continue;
    const double lo = e.box.lo[a];
    const double period = e.box.length(a);
    if (!(period > 0) || !std::isfinite(period)) continue;  // check_periodic_box names it
    Eigen::ArrayXd& v = a == 0 ? e.x : (a == 1 ? e.y : e.z);
    for (Eigen::Index k = 0; k < v.size(); ++k) {
      if (v[k] >= lo && v[k] < e.box.hi[a]) continue;
      double w = lo + (v[k] - lo - period * std::floor((v[k] - lo) / period));
      // Rounding can leave w at hi (a centre a hair below lo) or a hair outside: fold it back.
      if (w >= e.box.hi[a]) w = lo;
      if (w < lo) w = lo;
      v[k] = w;
    }
  }
}

std::string periodic_axes(const Elements& e) {
  std::string names;
  for (int a = 0; a < e.dim; ++a) {
    if (!e.box.periodic[a]) continue;
    if (!names.empty()) names += ", ";
    names += kAxisName[a];
  }
  return names;
}

void refuse_periodic(const Elements& e, std::string_view detector) {
  const std::string axes = periodic_axes(e);
  if (axes.empty()) return;
  throw Error(std::string(detector) + ": the frame is periodic in " + axes +
              "; only nbs and brute find contacts across a periodic boundary");
}

void check_periodic_box(const Elements& e, std::string_view detector) {
  for (int a = 0; a < e.dim; ++a) {
    if (!e.box.periodic[a]) continue;
    const double lo = e.box.lo[a], hi = e.box.hi[a];
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo)) {
      throw Error(std::string(detector) + ": " + kAxisName[a] + " is periodic over [" + fmt(lo) + ", " + fmt(hi) +
                  "), which is not a positive finite period");
    }
    const Eigen::ArrayXd& v = e.axis(a);
    for (Eigen::Index k = 0; k < v.size(); ++k) {
      if (v[k] >= lo && v[k] < hi) continue;
      throw Error(std::string(detector) + ": element " + std::to_string(k) + " has " + kAxisName[a] + " = " +
                  fmt(v[k]) + ", outside the periodic box [" + fmt(lo) + ", " + fmt(hi) + ") (wrap it in first)");
    }
  }
}

}  // namespace nbscope

#include "core/elements.hpp"

#include <cassert>
#include <cstring>

namespace nbscope {

void Elements::resize(std::int64_t n) {
  assert(n >= 0 && n <= kMaxElements && "Elements::resize: count out of range");
  x.resize(n);
  y.resize(n);
  z.resize(dim == 3 ? n : 0);
  r.resize(n);
}

void Elements::push_back(double px, double py, double pz, double pr) {
  const std::int64_t n = size();
  x.conservativeResize(n + 1);
  y.conservativeResize(n + 1);
  r.conservativeResize(n + 1);
  x[n] = px;
  y[n] = py;
  r[n] = pr;
  if (dim == 3) {
    z.conservativeResize(n + 1);
    z[n] = pz;
  }
}

double Elements::max_radius() const { return size() == 0 ? 0.0 : r.maxCoeff(); }

Bounds Elements::centre_bounds() const {
  Bounds b;
  if (size() == 0) return b;
  for (int a = 0; a < dim; ++a) {
    b.min[a] = axis(a).minCoeff();
    b.max[a] = axis(a).maxCoeff();
  }
  return b;
}

bool Elements::valid() const {
  if (y.size() != x.size() || r.size() != x.size()) return false;
  if (dim == 3 && z.size() != x.size()) return false;
  // Written as "all within" so that NaN fails too.
  const auto coordinates_ok = [](const Eigen::ArrayXd& v) { return (v.abs() <= kMaxCoordinate).all(); };
  if (!coordinates_ok(x) || !coordinates_ok(y) || (dim == 3 && !coordinates_ok(z))) return false;
  return ((r >= kMinRadius) && (r <= kMaxRadius)).all();
}

std::uint64_t hash_elements(const Elements& e) {
  // FNV-1a taken a 64-bit word at a time (not a byte): one multiply per coordinate, so the hash of
  // every frame costs little beside its detection.
  constexpr std::uint64_t kPrime = 0x100000001b3ULL;
  std::uint64_t h = 0xcbf29ce484222325ULL;
  const auto mix = [&](std::uint64_t word) {
    h ^= word;
    h *= kPrime;
    h ^= h >> 32;  // folds the high bits back: a word-wise multiply alone spreads changes only upwards
  };
  mix(static_cast<std::uint64_t>(e.dim));
  mix(static_cast<std::uint64_t>(e.size()));
  const auto column = [&](const Eigen::ArrayXd& v) {
    for (Eigen::Index k = 0; k < v.size(); ++k) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &v[k], sizeof bits);
      mix(bits);
    }
  };
  column(e.x);
  column(e.y);
  if (e.dim == 3) column(e.z);
  column(e.r);
  if (e.box.any()) {  // the same centres in another periodic box are another frame
    for (int a = 0; a < 3; ++a) {
      std::uint64_t lo = 0, hi = 0;
      std::memcpy(&lo, &e.box.lo[a], sizeof lo);
      std::memcpy(&hi, &e.box.hi[a], sizeof hi);
      mix(e.box.periodic[a] ? 1 : 0);
      mix(lo);
      mix(hi);
    }
  }
  return h;
}

Elements make_elements_2d(const Eigen::ArrayXd& x, const Eigen::ArrayXd& y, const Eigen::ArrayXd& r) {
  Elements e;
  e.dim = 2;
  e.x = x;
  e.y = y;
  e.r = r;
  return e;
}

}  // namespace nbscope

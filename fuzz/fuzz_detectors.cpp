// Fuzz target: the differential one. Bytes decode into up to three small 2D or 3D element sets (at
// most 64 elements each) and a grid, derived or pinned; every registered detector (box2d included,
// 2D) must find exactly brute force's pairs on each set, or refuse it where the contract says so
// (differential.hpp). The detectors are kept from one set to the next, as in a simulation.
//
// Values come mostly from a small table that makes the degenerate cases likely: equal positions,
// exact touching (on a lattice of binary fractions, where |c_i - c_j| = r_i + r_j holds exactly),
// one ulp either side of touching, centres on cell boundaries, radii from 1e-100 to 1e3 and equal;
// the rest are arbitrary doubles within the supported magnitudes.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "core/elements.hpp"
#include "differential.hpp"
#include "fuzz_bytes.hpp"
#include "physics/box2d_detector.hpp"

namespace {

using nbscope::Elements;
using nbscope::fuzz::Bytes;

// A radius: table values (binary fractions, extremes, the previous radius) or an arbitrary one.
double decode_radius(Bytes& in, double previous) {
  // Binary fractions (exact sums), then radii whose diameter has no exact reciprocal (1/d rounds,
  // so integerisation rounds: the case the grid's guard is for), then the extremes.
  static constexpr double kTable[] = {0.5, 0.25, 1, 0.125, 2, 0.375, 0.75, 1.5,
                                      0.1, 0.3, 0.35, 49.0 / 128, 1.0 / 3, 0.7, 5.5, 0.45,
                                      nbscope::kMinRadius, 1e-3, 1e-9, 1e3};
  const std::uint8_t b = in.u8();
  if (b < 20) return kTable[b];
  if (b < 40) return previous;
  // m * 2^e, m in 1..65536, e in -72..-9: from ~2e-22 to 128.
  const double m = 1.0 + static_cast<double>(in.u8() << 8 | in.u8());
  return std::ldexp(m, (b % 64) - 72);
}

// One coordinate on axis `a` of element k (radius r) of `e` (elements 0..k-1 decoded), `d` the
// largest diameter of the set (a cell's side where the grid is derived).
double decode_coordinate(Bytes& in, const Elements& e, std::int64_t k, int a, double r, double d) {
  const std::uint8_t b = in.u8();
  const std::uint8_t kind = b >> 4, low = b & 15;
  // Another element on this axis (equal positions), or its position shifted to touch exactly.
  const auto other = [&]() -> std::int64_t { return k == 0 ? -1 : low % k; };
  switch (kind) {
    case 0: case 1: case 2: return (static_cast<double>(b) - 24.0) * 0.25;  // lattice -6 .. 1.75
    case 3: case 4: {                                                       // equal to another's
      const std::int64_t j = other();
      return j < 0 ? 0.0 : e.axis(a)[j];
    }
    case 5: case 6: {  // touching another exactly along this axis (only this axis differs when the others copy)
      const std::int64_t j = other();
      if (j < 0) return 0.0;
      const double sum = r + e.r[j];
      return kind == 5 ? e.axis(a)[j] + sum : e.axis(a)[j] - sum;
    }
    case 7: {  // one ulp beyond or inside touching
      const std::int64_t j = other();
      if (j < 0) return 0.0;
      const double touch = e.axis(a)[j] + r + e.r[j];
      return (low & 1) ? std::nextafter(touch, INFINITY) : std::nextafter(touch, -INFINITY);
    }
    case 8: case 9: {  // on a cell boundary of a derived grid from 0: k * d
      const double k = static_cast<double>(static_cast<std::int8_t>(in.u8()));
      return (low & 1) ? k * d : k * d + static_cast<double>(low) * 0.125;
    }
    case 10: return std::nextafter((static_cast<double>(low) - 4.0) * d, (low & 1) ? INFINITY : -INFINITY);
    case 11: {  // large magnitudes, where a unit step is one ulp or more
      const double base = std::ldexp(1.0, 40 + 4 * (low & 7));
      return ((low & 8) ? -base : base) + static_cast<double>(in.u8() % 8);
    }
    default: {  // arbitrary: m * 2^e, |m| < 2^31, e from -80 to 47
      const auto m = static_cast<double>(static_cast<std::int32_t>(in.u32()));
      return std::ldexp(m, static_cast<int>(in.u8() % 128) - 111);
    }
  }
}

// One set: n and a style from a byte each, radii first (so coordinates can touch exactly), then
// the centres. Style bit 0: every radius is the first (as in many DEM models); bit 1: every centre
// on the x axis (y, z = 0). Both make the few bytes of a rounding case at a cell boundary likely.
Elements decode_elements(Bytes& in, int dim) {
  Elements e;
  e.dim = dim;
  const std::int64_t n = in.u8() % 65;
  const std::uint8_t style = in.u8();
  e.resize(n);
  double previous = 0.5;
  double d = 0;
  for (std::int64_t k = 0; k < n; ++k) {
    e.r[k] = previous = (k > 0 && (style & 1)) ? previous : decode_radius(in, previous);
    d = std::max(d, 2 * e.r[k]);
  }
  for (std::int64_t k = 0; k < n; ++k)
    for (int a = 0; a < dim; ++a) {
      Eigen::ArrayXd& col = a == 0 ? e.x : (a == 1 ? e.y : e.z);
      col[k] = (a > 0 && (style & 2)) ? 0.0 : decode_coordinate(in, e, k, a, e.r[k], d);
    }
  return e;
}

// The grid: each of cell size, origin and cells pinned or derived, chosen by bits of `mode`.
nbscope::GridOptions decode_grid(Bytes& in, const Elements& e, std::uint8_t mode) {
  nbscope::GridOptions g;
  const double d = 2 * e.max_radius();
  if (mode & 1) {
    const std::uint8_t b = in.u8();
    switch (b % 6) {
      case 0: g.cell_size = d; break;                                    // the book's d, exactly
      case 1: g.cell_size = std::nextafter(d, INFINITY); break;
      case 2: g.cell_size = std::nextafter(d, 0.0); break;               // below: refused by every grid detector
      case 3: g.cell_size = d * (1.0 + static_cast<double>(b) / 16.0); break;
      case 4: g.cell_size = std::ldexp(1.0, b % 16 - 4); break;          // 1/16 .. 2048, maybe below d
      default: g.cell_size = 1.0; break;
    }
  }
  if (mode & 2) {
    std::array<double, 3> o{0, 0, 0};
    const std::uint8_t b = in.u8();
    const nbscope::Bounds box = e.centre_bounds();
    for (int a = 0; a < e.dim; ++a) {
      switch (b % 4) {
        case 0: o[a] = box.min[a]; break;
        case 1: o[a] = box.min[a] - static_cast<double>(in.u8() % 8) * 0.25; break;
        case 2: o[a] = e.size() == 0 ? 0.0 : e.axis(a)[in.u8() % e.size()]; break;  // inside the data: clamping
        default: o[a] = (box.min[a] + box.max[a]) / 2 + static_cast<double>(static_cast<std::int8_t>(in.u8())); break;
      }
    }
    g.origin = o;
  }
  if (mode & 4) {
    std::array<std::int64_t, 3> c{1, 1, 1};
    for (int a = 0; a < e.dim; ++a) {
      const std::uint8_t b = in.u8();
      c[a] = b == 255 ? nbscope::kMaxCellsPerSide : b % 17;  // 0: refused; 2^24: at the limit
    }
    g.cells = c;
  }
  return g;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool registered = (nbscope::register_physics_detectors(), true);
  (void)registered;
  Bytes in(data, size);
  const std::uint8_t head = in.u8();
  const int dim = (head & 1) ? 3 : 2;
  nbscope::fuzz::DetectorSet set(dim);
  // Up to three sets through the same detector instances, while the input lasts.
  for (int frame = 0; frame < 3 && (frame == 0 || !in.done()); ++frame) {
    const std::uint8_t mode = in.u8();
    const Elements e = decode_elements(in, dim);
    nbscope::DetectOptions options;
    options.grid = decode_grid(in, e, mode);
    if (mode & 8) options.max_pairs = in.u8() % 32;
    nbscope::fuzz::require_every_detector_equals_brute(set, e, options);
  }
  return 0;
}

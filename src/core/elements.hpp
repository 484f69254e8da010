// nbscope core: a set of bounding circles (2D) or spheres (3D), stored structure-of-arrays.
#pragma once
#include <Eigen/Core>
#include <cstdint>

namespace nbscope {

// Element ids are 0-based row indices and fit in int32 (the book's integer arrays).
using ElementId = std::int32_t;

// Most elements one set may hold: ids stay int32 and the arrays stay within memory.
inline constexpr std::int64_t kMaxElements = 100'000'000;

// The supported magnitudes. Inside them every square of the contact test (pairs.hpp) is a finite,
// normal double, so |c_i - c_j| <= r_i + r_j is decided without overflow or underflow; DEM/FDEM
// models live many orders of magnitude inside. Readers refuse values outside (io/csv.hpp).
inline constexpr double kMaxCoordinate = 1e100;  // |x|, |y|, |z|
inline constexpr double kMinRadius = 1e-100;
inline constexpr double kMaxRadius = 1e100;

// Axis-aligned box of the element centres.
struct Bounds {
  double min[3] = {0, 0, 0};
  double max[3] = {0, 0, 0};
};

// The box of a periodic frame (a LAMMPS `pp` boundary, or --periodic with --box): on each periodic
// axis a the space repeats with period hi[a] - lo[a], centres lie in [lo[a], hi[a]) (wrap_into_box,
// core/pairs.hpp) and contacts are measured by the minimum image. No periodic axis: an open space.
struct PeriodicBox {
  bool periodic[3] = {false, false, false};
  double lo[3] = {0, 0, 0};
  double hi[3] = {0, 0, 0};
  // True when at least one axis is periodic.
  [[nodiscard]] bool any() const { return periodic[0] || periodic[1] || periodic[2]; }
  // The period of axis a, hi - lo.
  [[nodiscard]] double length(int a) const { return hi[a] - lo[a]; }
};

// N bounding circles (dim 2: x, y, r) or spheres (dim 3: x, y, z, r); z is empty in 2D.
struct Elements {
  int dim = 2;
  Eigen::ArrayXd x, y, z, r;
  PeriodicBox box;  // the frame's periodic axes (none: open space)

  // Number of elements.
  [[nodiscard]] std::int64_t size() const { return x.size(); }
  // Resizes every column to n (z only in 3D); contents are unspecified.
  void resize(std::int64_t n);
  // Appends one element; z is ignored in 2D.
  void push_back(double px, double py, double pz, double pr);
  // Coordinate column by axis (0 = x, 1 = y, 2 = z).
  [[nodiscard]] const Eigen::ArrayXd& axis(int a) const { return a == 0 ? x : (a == 1 ? y : z); }
  // Largest radius, 0 for an empty set.
  [[nodiscard]] double max_radius() const;
  // Bounding box of the centres (all zero for an empty set).
  [[nodiscard]] Bounds centre_bounds() const;
  // True when every coordinate is within +-kMaxCoordinate and every radius in [kMinRadius, kMaxRadius].
  [[nodiscard]] bool valid() const;
};

// A 64-bit fingerprint of the set (FNV-1a, a 64-bit word at a time, over dim, N and the bit patterns
// of every coordinate and radius, column by column, and the periodic box when there is one): equal sets hash equal, so two runs can be compared frame by frame
// (report "hash", the history's determinism check) without storing the elements.
[[nodiscard]] std::uint64_t hash_elements(const Elements& elements);

// Builds a 2D set from columns (convenience for tests and benchmarks).
Elements make_elements_2d(const Eigen::ArrayXd& x, const Eigen::ArrayXd& y, const Eigen::ArrayXd& r);

}  // namespace nbscope

// nbscope core: how LAMMPS splits a box among P MPI ranks, found from which rank held each atom
// (per-rank dumps, io/dump_ranks.hpp). LAMMPS cuts the box into a uniform Px x Py x Pz grid
// (`processors * * *`, Px Py Pz = P; Pz = 1 in 2D) and numbers the subdomains with one axis varying
// fastest (its default `map cart`: z fastest, then y, then x). docs/dem.md#mpi.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <span>

#include "core/elements.hpp"

namespace nbscope {

// A box split among ranks as LAMMPS splits it.
struct Subdomains {
  std::array<int, 3> grid{1, 1, 1};   // Px, Py, Pz
  std::array<int, 3> order{2, 1, 0};  // the axes from the fastest-varying to the slowest in the rank number
  Bounds box;                         // the box split (the dump's BOX BOUNDS)
  double contained = 0;               // the fraction of the atoms looked at that lie in their rank's subdomain

  // P, the number of ranks.
  [[nodiscard]] int rank_count() const { return grid[0] * grid[1] * grid[2]; }
  // Rank `rank`'s cell of the grid (ix, iy, iz).
  [[nodiscard]] std::array<int, 3> cell_of(int rank) const;
  // Rank `rank`'s subdomain.
  [[nodiscard]] Bounds bounds_of(int rank) const;
};

// The split of `box` among `rank_count` ranks (>= 2) that best contains each atom of `elements` in its
// rank's subdomain (`ranks`: each row's): every factorisation Px Py Pz of P (Pz = 1 in 2D, an axis
// of zero extent not split) and every order of the axes; ties go to LAMMPS's own order (z fastest).
// Large frames are sampled (at most about 50,000 atoms looked at). None without atoms or ranks.
[[nodiscard]] std::optional<Subdomains> infer_subdomains(const Elements& elements, std::span<const std::int32_t> ranks, int rank_count,
                                                         const Bounds& box);

}  // namespace nbscope

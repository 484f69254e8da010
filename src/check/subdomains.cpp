// nbscope check: missing contacts across subdomain boundaries (subdomains.hpp).
#include "check/subdomains.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/pairs.hpp"

namespace nbscope {

void SubdomainTally::add(const FrameReport& report, const Elements& elements, const std::vector<std::int32_t>* ranks) {
  if (ranks == nullptr) return;
  for (const Violation& v : report.violations) {
    // A contact the code's list lacks: R has it, the recorded pairs do not.
    if (v.invariant != Invariant::AEqualsR || std::strstr(v.what, "missing") == nullptr) continue;
    const auto i = v.pair.i, j = v.pair.j;
    if (i < 0 || j < 0 || static_cast<std::size_t>(std::max(i, j)) >= ranks->size()) continue;
    ++missing_;
    const std::int32_t ri = (*ranks)[static_cast<std::size_t>(i)], rj = (*ranks)[static_cast<std::size_t>(j)];
    if (ri == rj) continue;
    if (straddling_++ == 0) {
      first_i_ = v.atom_i >= 0 ? v.atom_i : i;
      first_j_ = v.atom_j >= 0 ? v.atom_j : j;
      first_rank_i_ = ri;
      first_rank_j_ = rj;
      first_frame_ = v.frame;
    }
    longest_ = std::max(longest_, std::sqrt(centre_distance2(elements, i, j)));
  }
}

std::string SubdomainTally::text() const {
  if (straddling_ == 0) return "";
  const bool all = straddling_ == missing_;
  const std::string who = missing_ == 1   ? "the 1 missing contact straddles"
                          : all           ? "all " + std::to_string(missing_) + " missing contacts straddle"
                          : straddling_ == 1 ? "1 of " + std::to_string(missing_) + " missing contacts straddles"
                                             : std::to_string(straddling_) + " of " + std::to_string(missing_) + " missing contacts straddle";
  char buf[512];
  std::snprintf(buf, sizeof buf,
                " a subdomain boundary (first: atoms %lld of rank %d and %lld of rank %d, timestep %lld)%s; the longest spans %.6g "
                "centre to centre: each rank must see the other's atoms that far as ghosts (LAMMPS: comm_modify cutoff, the pair "
                "cut-off plus neighbor skin)",
                static_cast<long long>(first_i_), first_rank_i_, static_cast<long long>(first_j_), first_rank_j_,
                static_cast<long long>(first_frame_), all ? ": a ghost cut-off too short for the largest contacts loses exactly these" : "",
                longest_);
  return "; " + who + buf;
}

}  // namespace nbscope

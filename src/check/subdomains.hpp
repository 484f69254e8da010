// nbscope check: contacts missing across MPI subdomain boundaries. A parallel DEM code sees an atom of
// another rank only as a ghost, within its ghost cut-off (LAMMPS's comm_modify cutoff, the pair
// cut-off plus the neighbor skin): a cut-off shorter than a contact's span loses exactly the contacts
// that straddle a boundary. With per-rank dumps (io/dump_ranks.hpp) each row's rank is known, so the
// missing contacts of a run say whether they straddle one, and how far the ghosts must reach.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "check/report.hpp"
#include "core/elements.hpp"

namespace nbscope {

// The missing contacts of a run's frames, those across a subdomain boundary, and their longest span.
class SubdomainTally {
 public:
  // The frame's violations (its rows' `ranks`, null without ranks: nothing is counted).
  void add(const FrameReport& report, const Elements& elements, const std::vector<std::int32_t>* ranks);
  // "; all 12 missing contacts straddle a subdomain boundary (...)", "; 3 of 12 missing ...", or "".
  [[nodiscard]] std::string text() const;
  // Missing contacts counted, and those whose atoms were in two ranks.
  [[nodiscard]] std::int64_t missing() const { return missing_; }
  [[nodiscard]] std::int64_t straddling() const { return straddling_; }

 private:
  std::int64_t missing_ = 0, straddling_ = 0;
  double longest_ = 0;  // the longest centre-to-centre span of a straddling one
  std::int64_t first_i_ = -1, first_j_ = -1, first_frame_ = 0;
  std::int32_t first_rank_i_ = 0, first_rank_j_ = 0;
};

}  // namespace nbscope

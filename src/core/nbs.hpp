// nbscope core: `nbs`, the Munjiza-NBS (No Binary Search) detector (book pp.102-123).
//
// 2D: every element is pushed onto the y-list of its row (heads y_heads[ny], next Y[N]); then for
// each non-empty row iy the x-lists of row iy (B[0][nx]) and of row iy-1 (B[1][nx]) are built with
// one next array X[N], every element of row iy is checked against the contact mask
// {(ix,iy) after it, (ix-1,iy), (ix-1..ix+1, iy-1)}, and only the heads that were set are cleared.
// Time O(N + ny), memory ny + 2nx + 2N integers whatever the density.
#pragma once
#include <cstdint>
#include <vector>

#include "core/detector.hpp"

namespace nbscope {

class NbsDetector final : public Detector {
 public:
  // The detector's loops as the book writes them; TraceEvent::line indexes this list.
  static const std::vector<const char*>& pseudocode_2d();

  [[nodiscard]] std::string_view name() const override { return "nbs"; }
  [[nodiscard]] bool supports_dim(int dim) const override { return dim == 2; }
  void detect(const Elements& elements, const DetectOptions& options, PairList& out_pairs) override;
  void detect_traced(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                     TraceLog& out_trace) override;
  [[nodiscard]] std::size_t own_bytes() const override;
  [[nodiscard]] const Grid* last_grid() const override { return &grid_; }

 private:
  template <class Trace>
  void run_2d(const Elements& elements, const DetectOptions& options, PairList& out_pairs, Trace& trace);
  // Sizes the arrays for the current grid and N; every head is -1 afterwards.
  void prepare(std::int64_t n_elements);
  // Restores the all-heads-empty invariant after an interrupted run.
  void reset_heads();

  Grid grid_;
  std::vector<std::int32_t> y_heads_;  // ny heads of the row lists
  std::vector<std::int32_t> y_next_;   // Y[N]
  std::vector<std::int32_t> x_heads_;  // B[2][nx], flat: B[s][ix] = x_heads_[s * nx + ix]
  std::vector<std::int32_t> x_next_;   // X[N]
};

}  // namespace nbscope

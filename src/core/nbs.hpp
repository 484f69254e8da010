// nbscope core: `nbs`, the Munjiza-NBS (No Binary Search) detector (book pp.102-123).
//
// 2D: every element is pushed onto the y-list of its row (heads y_heads[ny], next Y[N]); then for
// each non-empty row iy the x-lists of row iy (B[0][nx]) and of row iy-1 (B[1][nx]) are built with
// one next array X[N], every element of row iy is checked against the contact mask
// {(ix,iy) after it, (ix-1,iy), (ix-1..ix+1, iy-1)}, and only the heads that were set are cleared.
// Time O(N + ny), memory ny + 2nx + 2N integers whatever the density.
//
// 3D (p.123, nbs3d.cpp): every element onto the z-list of its layer (heads C[nz], next Z[N]); for
// each non-empty layer iz the y-lists of layers iz and iz-1 (heads B[2][ny], next Y[N]); for each
// non-empty row (iy,iz) the x-lists of the five rows the 3D contact mask reaches, (iy,iz),
// (iy-1,iz), (iy-1,iz-1), (iy,iz-1), (iy+1,iz-1) (heads A[5][nx], next X[N]); then the mask's 13
// neighbour cells and the own cell. Time O(N + nz), memory nz + 2ny + 5nx + 3N integers.
#pragma once
#include <cstdint>
#include <vector>

#include "core/detector.hpp"

namespace nbscope {

class NbsDetector final : public Detector {
 public:
  // The detector's loops as the book writes them; TraceEvent::line indexes this list.
  static const std::vector<const char*>& pseudocode_2d();
  // The same for the 3D detector (p.123).
  static const std::vector<const char*>& pseudocode_3d();

  [[nodiscard]] std::string_view name() const override { return "nbs"; }
  [[nodiscard]] bool supports_dim(int dim) const override { return dim == 2 || dim == 3; }
  void detect(const Elements& elements, const DetectOptions& options, PairList& out_pairs) override;
  void detect_traced(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                     TraceLog& out_trace) override;
  [[nodiscard]] std::size_t own_bytes() const override;
  [[nodiscard]] const Grid* last_grid() const override { return &grid_; }
  [[nodiscard]] const std::vector<const char*>& pseudocode(int dim) const override {
    return dim == 3 ? pseudocode_3d() : pseudocode_2d();
  }

 private:
  template <class Trace>
  void run_2d(const Elements& elements, const DetectOptions& options, PairList& out_pairs, Trace& trace);
  // Sizes the arrays for the current grid and N; every head is -1 afterwards.
  void prepare(std::int64_t n_elements);
  // Restores the all-heads-empty invariant after an interrupted run.
  void reset_heads();
  // 3D (nbs3d.cpp): sizes the 3D arrays; runs untraced when trace is nullptr.
  void prepare_3d(std::int64_t n_elements);
  void detect_3d(const Elements& elements, const DetectOptions& options, PairList& out_pairs, TraceLog* trace);
  template <class Trace>
  void run_3d(const Elements& elements, const DetectOptions& options, PairList& out_pairs, Trace& trace);

  Grid grid_;
  std::vector<std::int32_t> y_heads_;  // 2D: ny heads of the row lists; 3D: B[2][ny] (B[s][iy] at s*ny+iy)
  std::vector<std::int32_t> y_next_;   // Y[N]
  std::vector<std::int32_t> x_heads_;  // 2D: B[2][nx] (B[s][ix] at s*nx+ix); 3D: A[5][nx] (A[r][ix] at r*nx+ix)
  std::vector<std::int32_t> x_next_;   // X[N]
  std::vector<std::int32_t> z_heads_;  // 3D: C[nz], heads of the layer lists; empty in 2D
  std::vector<std::int32_t> z_next_;   // 3D: Z[N]; empty in 2D
};

}  // namespace nbscope

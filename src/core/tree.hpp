// nbscope core: `tree`, binary-tree contact detection (book p.85).
//
// Space (the grid of cells of size d) is halved recursively, always across its longest side, into a
// binary tree of cells; nodes exist only where elements are. Each leaf is one cell of size d and
// holds its elements as a singly connected list: a HEAD at the leaf node plus the next array E[N],
// -1 ending a list, elements pushed at the head (eq. 3.21). Each element is then checked against the
// elements after it in its own leaf and against the leaves of the contact mask, found by a search
// from the root that only enters nodes overlapping the element's neighbourhood. Time ~ N log2 N.
//
// Arrays: child[M][2] (the lower/upper half of node m, -1 for none), HEAD[M] (-1 for internal nodes
// and empty leaves), E[N]; memory 3M + N integers for M nodes. The tree is rebuilt by every detection.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "core/detector.hpp"

namespace nbscope {

// One leaf of a tree: its node, its cell and the HEAD of its list.
struct TreeLeaf {
  std::int32_t node = -1;
  std::int32_t cell[3] = {0, 0, 0};  // (ix, iy, iz); iz = 0 in 2D
  std::int32_t head = -1;
};

// The leaves of the tree over `grid` held in `child` (2 per node) and `head` (1 per node) — the
// detector's arrays or their state in a trace — depth-first, lower halves first.
std::vector<TreeLeaf> tree_leaves(const Grid& grid, std::span<const std::int32_t> child,
                                  std::span<const std::int32_t> head);

class TreeDetector final : public DimensionalDetector<TreeDetector> {
 public:
  [[nodiscard]] std::string_view name() const override { return "tree"; }
  [[nodiscard]] bool supports_dim(int dim) const override { return dim == 2 || dim == 3; }
  // 3M + N integers: child[M][2], HEAD[M], E[N] for the M nodes of the last tree.
  [[nodiscard]] std::size_t own_bytes() const override;
  [[nodiscard]] const Grid* last_grid() const override { return &grid_; }
  [[nodiscard]] const std::vector<const char*>& pseudocode(int dim) const override;
  // Nodes of the last tree (the root included).
  [[nodiscard]] std::int32_t node_count() const { return node_count_; }

 private:
  friend DimensionalDetector<TreeDetector>;
  template <int D, class Trace>
  void build(const Elements& elements, Trace& trace, int child_id, int head_id, int next_id);
  template <int D, class Trace>
  void search(const Elements& elements, Touching touching, Trace& trace, PairCollector& pairs);
  template <int D, class Trace>
  void run(const Elements& elements, const DetectOptions& options, PairList& out_pairs, Trace& trace);
  std::int32_t new_node();

  Grid grid_;
  std::int32_t node_count_ = 0;
  std::vector<std::int32_t> child_;  // child[2m + side]
  std::vector<std::int32_t> head_;   // HEAD[m]
  std::vector<std::int32_t> next_;   // E[N]
};

// Instantiated once, in tree.cpp, where run() is defined.
extern template class DimensionalDetector<TreeDetector>;

}  // namespace nbscope

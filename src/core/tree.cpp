#include "core/tree.hpp"

#include <algorithm>
#include <array>

#include "core/cells.hpp"
#include "core/error.hpp"
#include "core/lists.hpp"

namespace nbscope {

namespace {
// Pseudocode lines (TraceEvent::line).
enum Line : std::uint8_t { kLoopBuild = 0, kDescend, kPush, kLoopLeaves, kMaskLeaf, kLoopLeafList, kTestPair };

// The cells [lo, hi) a node covers, per axis.
struct Box {
  std::int32_t lo[3] = {0, 0, 0};
  std::int32_t hi[3] = {1, 1, 1};
};

Box root_box(const Grid& g) {
  Box b;
  for (int a = 0; a < 3; ++a) b.hi[a] = static_cast<std::int32_t>(g.n[a]);
  return b;
}

// The axis a node is halved across: its longest side (the lowest axis on a tie); -1 for a leaf.
template <int D>
int split_axis(const Box& b) {
  int best = -1;
  std::int32_t longest = 1;
  for (int a = 0; a < D; ++a) {
    if (b.hi[a] - b.lo[a] > longest) {
      longest = b.hi[a] - b.lo[a];
      best = a;
    }
  }
  return best;
}

std::int32_t middle(const Box& b, int a) { return b.lo[a] + (b.hi[a] - b.lo[a]) / 2; }

// The half `side` (0 lower, 1 upper) of box b across axis a.
Box half(Box b, int a, int side) {
  const std::int32_t mid = middle(b, a);
  (side == 0 ? b.hi[a] : b.lo[a]) = mid;
  return b;
}

template <int D>
void collect_leaves(std::span<const std::int32_t> child, std::span<const std::int32_t> head, std::int32_t node,
                    const Box& box, std::vector<TreeLeaf>& out) {
  const int a = split_axis<D>(box);
  if (a < 0) {
    TreeLeaf leaf;
    leaf.node = node;
    for (int i = 0; i < 3; ++i) leaf.cell[i] = box.lo[i];
    leaf.head = head[static_cast<std::size_t>(node)];
    out.push_back(leaf);
    return;
  }
  for (int side = 0; side < 2; ++side) {
    const std::int32_t c = child[2 * static_cast<std::size_t>(node) + side];
    if (c != -1) collect_leaves<D>(child, head, c, half(box, a, side), out);
  }
}
}  // namespace

std::vector<TreeLeaf> tree_leaves(const Grid& grid, std::span<const std::int32_t> child,
                                  std::span<const std::int32_t> head) {
  std::vector<TreeLeaf> out;
  if (head.empty()) return out;
  if (grid.dim == 3) {
    collect_leaves<3>(child, head, 0, root_box(grid), out);
  } else {
    collect_leaves<2>(child, head, 0, root_box(grid), out);
  }
  return out;
}

const std::vector<const char*>& TreeDetector::pseudocode(int dim) const {
  static const std::vector<const char*> lines_2d = {
      "Loop over all discrete elements k (place them onto the binary tree)",
      "  from the root: halve the cell across its longer side and go to the half holding the centre of k "
      "(a new node when that half is empty)",
      "  at the leaf (one cell of size d) add the discrete element k onto its list: E[k] = HEAD; HEAD = k",
      "Loop over all leaves of the tree (the cells holding discrete elements)",
      "  search the tree, from the lowest node holding the leaf's neighbourhood, for the leaves of the contact "
      "mask: own cell, (ix-1,iy), (ix-1,iy-1), (ix,iy-1), (ix+1,iy-1)",
      "  Loop over all discrete elements k of the leaf's list (k = HEAD and k = E[k] until k = -1)",
      "    check k against each discrete element of the mask leaves' lists (own leaf: those after k)",
  };
  static const std::vector<const char*> lines_3d = {
      "Loop over all discrete elements k (place them onto the binary tree)",
      "  from the root: halve the cell across its longest side and go to the half holding the centre of k "
      "(a new node when that half is empty)",
      "  at the leaf (one cell of size d) add the discrete element k onto its list: E[k] = HEAD; HEAD = k",
      "Loop over all leaves of the tree (the cells holding discrete elements)",
      "  search the tree, from the lowest node holding the leaf's neighbourhood, for the leaves of the contact "
      "mask: own cell, (ix-1,iy,iz), (ix-1..ix+1,iy-1,iz), (ix-1..ix+1,iy-1..iy+1,iz-1)",
      "  Loop over all discrete elements k of the leaf's list (k = HEAD and k = E[k] until k = -1)",
      "    check k against each discrete element of the mask leaves' lists (own leaf: those after k)",
  };
  return dim == 3 ? lines_3d : lines_2d;
}

std::size_t TreeDetector::own_bytes() const {
  return (child_.size() + head_.size() + next_.size()) * sizeof(std::int32_t);
}

std::int32_t TreeDetector::new_node() {
  if (static_cast<std::size_t>(node_count_) == head_.size()) {
    head_.push_back(-1);
    child_.push_back(-1);
    child_.push_back(-1);
  }
  return node_count_++;
}

template <int D, class Trace>
void TreeDetector::build(const Elements& e, Trace& trace, int child_id, int head_id, int next_id) {
  const auto n = static_cast<ElementId>(e.size());
  const Grid& g = grid_;
  const Box root = root_box(g);
  node_count_ = 0;
  new_node();  // the root
  trace.phase(kLoopBuild, phase_label::kBuildTree, -1);
  for (ElementId k = 0; k < n; ++k) {
    std::int32_t c[3] = {g.cell(e.x[k], 0), g.cell(e.y[k], 1), D == 3 ? g.cell(e.z[k], 2) : 0};
    std::int32_t node = 0;
    Box box = root;
    for (int a = split_axis<D>(box); a >= 0; a = split_axis<D>(box)) {
      const int side = c[a] >= middle(box, a) ? 1 : 0;
      const std::size_t slot = 2 * static_cast<std::size_t>(node) + side;
      if (child_[slot] == -1) {
        const std::int32_t m = new_node();
        trace.set(kDescend, "tree node", child_id, static_cast<std::int64_t>(slot), -1, m, k);
        child_[slot] = m;
      }
      node = child_[slot];
      box = half(box, a, side);
    }
    const ListArrays leaf{head_.data(), next_.data(), head_id, next_id, "leaf list"};
    push_front(trace, kPush, leaf, node, k, c[0], c[1], D == 3 ? c[2] : -1);
  }
}

template <int D, class Trace>
void TreeDetector::search(const Elements& e, Touching touching, Trace& trace, PairCollector& pairs) {
  const Grid& g = grid_;
  const std::int32_t* const child = child_.data();
  const std::int32_t* const head = head_.data();
  const std::int32_t* const next = next_.data();
  struct Frame {
    std::int32_t node;
    std::int32_t depth;
    Box box;
  };
  // Depth <= 3 * 24 levels (kMaxCellsPerSide); a depth-first stack holds one pending sibling per level.
  constexpr std::size_t kMaxDepth = 80;
  std::array<Frame, kMaxDepth> path;       // path[d]: the ancestor at depth d of the current node
  std::array<Frame, 2 * kMaxDepth> walk;   // the depth-first walk over all leaves
  std::array<Frame, 2 * kMaxDepth> query;  // the search for one leaf's neighbours
  struct MaskLeaf {
    std::int32_t head;
    std::int32_t cell[3];
  };
  std::array<MaskLeaf, 13> mask;  // the mask leaves of the current leaf (never the own leaf)

  trace.phase(kLoopLeaves, phase_label::kContacts, -1);
  std::size_t top = 0;
  walk[top++] = Frame{0, 0, root_box(g)};
  while (top > 0) {
    const Frame f = walk[--top];
    path[static_cast<std::size_t>(f.depth)] = f;
    const int a = split_axis<D>(f.box);
    if (a >= 0) {
      for (int side = 1; side >= 0; --side) {  // upper half pushed first: the lower is walked first
        const std::int32_t ch = child[2 * static_cast<std::size_t>(f.node) + side];
        if (ch != -1) walk[top++] = Frame{ch, f.depth + 1, half(f.box, a, side)};
      }
      continue;
    }
    // A leaf: its cell c and the neighbourhood q (+-1 cell, only the lower half on the last axis).
    const std::int32_t* c = f.box.lo;
    std::int32_t qlo[3] = {0, 0, 0}, qhi[3] = {0, 0, 0};  // inclusive, clipped to the grid
    for (int i = 0; i < D; ++i) {
      qlo[i] = std::max(c[i] - 1, 0);
      qhi[i] = std::min(i == D - 1 ? c[i] : c[i] + 1, static_cast<std::int32_t>(g.n[i] - 1));
    }
    // Search from the lowest ancestor whose cells hold the whole neighbourhood, not from the root.
    std::int32_t from = f.depth;
    for (; from > 0; --from) {
      const Box& b = path[static_cast<std::size_t>(from)].box;
      bool holds = true;
      for (int i = 0; i < D; ++i) holds = holds && b.lo[i] <= qlo[i] && b.hi[i] - 1 >= qhi[i];
      if (holds) break;
    }
    std::size_t found = 0, qtop = 0;
    query[qtop++] = path[static_cast<std::size_t>(from)];
    while (qtop > 0) {
      const Frame q = query[--qtop];
      const int qa = split_axis<D>(q.box);
      if (qa < 0) {
        const std::int32_t* m = q.box.lo;
        if (in_half_mask(m[0] - c[0], m[1] - c[1], m[2] - c[2])) mask[found++] = MaskLeaf{head[q.node], {m[0], m[1], m[2]}};
        continue;
      }
      for (int side = 1; side >= 0; --side) {
        const std::int32_t ch = child[2 * static_cast<std::size_t>(q.node) + side];
        if (ch == -1) continue;
        const Box b = half(q.box, qa, side);
        bool overlaps = true;
        for (int i = 0; i < D; ++i) overlaps = overlaps && b.lo[i] <= qhi[i] && b.hi[i] - 1 >= qlo[i];
        if (overlaps) query[qtop++] = Frame{ch, q.depth + 1, b};
      }
    }
    // Every element of the leaf against the rest of its own list and the mask leaves' lists.
    for (std::int32_t k = head[f.node]; k != -1; k = next[k]) {
      trace.visit_cell(kMaskLeaf, k, c[0], c[1], D == 3 ? c[2] : -1);
      test_list(trace, kTestPair, e, touching, k, next[k], next, pairs);
      for (std::size_t i = 0; i < found; ++i) {
        trace.visit_cell(kMaskLeaf, k, mask[i].cell[0], mask[i].cell[1], D == 3 ? mask[i].cell[2] : -1);
        test_list(trace, kTestPair, e, touching, k, mask[i].head, next, pairs);
      }
    }
  }
}

template <int D, class Trace>
void TreeDetector::run(const Elements& e, const DetectOptions& options, PairList& out_pairs, Trace& trace) {
  if (e.dim != D) throw Error("tree: internal: dimension mismatch");
  refuse_periodic(e, "tree");
  grid_ = make_grid(e, options.grid);
  next_.resize(static_cast<std::size_t>(e.size()));
  PairCollector pairs(out_pairs, options.max_pairs);
  if constexpr (Trace::enabled) {
    // The arrays are declared with their final size, so build the tree once to count its nodes,
    // then start again from empty arrays and record the build.
    NullTrace count;
    child_.clear();
    head_.clear();
    build<D>(e, count, -1, -1, -1);
    const std::size_t m = static_cast<std::size_t>(node_count_);
    child_.assign(2 * m, -1);
    head_.assign(m, -1);
    std::fill(next_.begin(), next_.end(), -1);
    const int child_id = trace.declare_array("child", {static_cast<std::int64_t>(m), 2}, child_);
    const int head_id = trace.declare_array("HEAD", {static_cast<std::int64_t>(m)}, head_);
    const int next_id = trace.declare_array("E", {e.size()}, next_);
    build<D>(e, trace, child_id, head_id, next_id);
  } else {
    child_.clear();
    head_.clear();
    build<D>(e, trace, -1, -1, -1);
  }
  search<D>(e, options.touching, trace, pairs);
}

template class DimensionalDetector<TreeDetector>;

}  // namespace nbscope

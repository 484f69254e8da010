// nbscope physics: `box2d`, Box2D's b2DynamicTree used as a contact detector: one proxy per element
// kept between detections (moved, as a physics engine moves them), each element's tight AABB
// queried against the tree, then the exact circle test of core (docs/architecture.md "Contact").
//
// Proxies are inserted and queried in Morton (Z-curve) order of the element centres, not in the
// input's order: Box2D's incremental insertion builds a much looser tree from randomly ordered
// boxes (area ratio 2,291 vs 1,314 at 200k loose elements; 5,791 vs 2,657 at 800k), and queries in
// random order miss the cache on every node. In input order the queries grew as N^2.2 (200k:
// 1.9 s, 800k: 75 s); in Morton order 0.14 s and 1.2 s (docs/algorithms.md, box2d).
//
// Registered with core's registry by register_physics_detectors(), which the app calls at
// start-up, so core never sees Box2D.
#pragma once
#include <box2d/b2_dynamic_tree.h>

#include <cstdint>
#include <vector>

#include "core/detector.hpp"

namespace nbscope {

class Box2dDetector final : public Detector {
 public:
  Box2dDetector();
  ~Box2dDetector() override;
  [[nodiscard]] std::string_view name() const override { return "box2d"; }
  [[nodiscard]] bool supports_dim(int dim) const override { return dim == 2; }
  void detect(const Elements& elements, const DetectOptions& options, PairList& out_pairs) override;
  // No book operations to trace: records nothing and detects as detect().
  void detect_traced(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                     TraceLog& out_trace) override;
  // The tree's nodes (2N-1 for N proxies) and the proxy ids.
  [[nodiscard]] std::size_t own_bytes() const override;

 private:
  // Creates or destroys proxies so there is exactly one per element (ids 0..n-1 as user data);
  // new ones are inserted in order_'s order.
  void fit_proxies(std::int64_t n);
  // order_: the elements sorted by the Morton code of their centres over the elements' bounds.
  void sort_by_morton(const Elements& e);

  b2DynamicTree tree_;
  std::vector<std::int32_t> proxies_;  // proxy id of element k
  std::vector<b2AABB> boxes_;          // tight AABB of element k, rounded outwards to float
  std::vector<std::int32_t> order_;    // elements in Morton order: insertion and query order
  std::vector<std::uint64_t> keys_;    // scratch of sort_by_morton: (code << 32) | element
};

// Adds physics' detectors ("box2d") to core's registry; safe to call more than once.
void register_physics_detectors();

}  // namespace nbscope

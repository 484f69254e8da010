#include "physics/box2d_detector.hpp"

#include <cmath>

#include "core/error.hpp"

namespace nbscope {

namespace {

// Largest coordinate the float tree can hold with room to spare.
constexpr double kMaxFloatCoordinate = 1e30;

// `v` rounded to a float no larger (down) or no smaller (up) than v, so the float box holds the
// double one and the candidates are a superset of the contacts.
float float_down(double v) {
  float f = static_cast<float>(v);
  if (static_cast<double>(f) > v) f = std::nextafter(f, -INFINITY);
  return f;
}
float float_up(double v) {
  float f = static_cast<float>(v);
  if (static_cast<double>(f) < v) f = std::nextafter(f, INFINITY);
  return f;
}

}  // namespace

Box2dDetector::Box2dDetector() = default;

Box2dDetector::~Box2dDetector() {
  for (const std::int32_t id : proxies_) tree_.DestroyProxy(id);
}

std::size_t Box2dDetector::own_bytes() const {
  const std::size_t n = proxies_.size();
  return (n == 0 ? 0 : (2 * n - 1) * sizeof(b2TreeNode)) + n * (sizeof(std::int32_t) + sizeof(b2AABB));
}

void Box2dDetector::fit_proxies(std::int64_t n) {
  const auto want = static_cast<std::size_t>(n);
  while (proxies_.size() > want) {
    tree_.DestroyProxy(proxies_.back());
    proxies_.pop_back();
  }
  while (proxies_.size() < want) {
    const std::size_t k = proxies_.size();
    // Element ids travel as the proxy's user data.
    proxies_.push_back(tree_.CreateProxy(boxes_[k], reinterpret_cast<void*>(static_cast<std::uintptr_t>(k))));
  }
}

void Box2dDetector::detect(const Elements& e, const DetectOptions& options, PairList& out_pairs) {
  if (e.dim != 2) throw Error("box2d: only 2D elements are supported by this detector");
  const std::int64_t n = e.size();
  boxes_.resize(static_cast<std::size_t>(n));
  for (std::int64_t k = 0; k < n; ++k) {
    const double x = e.x[k], y = e.y[k], r = e.r[k];
    if (!(std::abs(x) + r < kMaxFloatCoordinate && std::abs(y) + r < kMaxFloatCoordinate))
      throw Error("box2d: element " + std::to_string(k) + " lies beyond Box2D's float range");
    b2AABB& box = boxes_[static_cast<std::size_t>(k)];
    box.lowerBound.Set(float_down(x - r), float_down(y - r));
    box.upperBound.Set(float_up(x + r), float_up(y + r));
  }
  const std::size_t kept = std::min(proxies_.size(), static_cast<std::size_t>(n));
  fit_proxies(n);
  // Move the proxies that existed before; Box2D re-inserts only those that left their fat AABB.
  for (std::size_t k = 0; k < kept; ++k) tree_.MoveProxy(proxies_[k], boxes_[k], b2Vec2(0, 0));

  PairCollector pairs(out_pairs, options.max_pairs);
  struct Query {
    const b2DynamicTree* tree;
    const Elements* e;
    PairCollector* pairs;
    ElementId i;
    bool QueryCallback(std::int32_t proxy) {
      const auto j = static_cast<ElementId>(reinterpret_cast<std::uintptr_t>(tree->GetUserData(proxy)));
      if (j > i && in_contact(*e, i, j)) pairs->add(i, j);
      return true;
    }
  } query{&tree_, &e, &pairs, 0};
  for (std::int64_t k = 0; k < n; ++k) {
    query.i = static_cast<ElementId>(k);
    tree_.Query(&query, boxes_[static_cast<std::size_t>(k)]);
  }
}

void Box2dDetector::detect_traced(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                                  TraceLog& out_trace) {
  out_trace.reset();
  detect(elements, options, out_pairs);
}

void register_physics_detectors() {
  register_detector({.name = "box2d",
                     .summary = "Box2D's b2DynamicTree queried with tight AABBs, then the exact circle test",
                     .dim2 = true, .dim3 = false, .traces = false, .has_lists = false,
                     .make = [] { return std::make_unique<Box2dDetector>(); }});
}

}  // namespace nbscope

#include "physics/box2d_detector.hpp"

#include <algorithm>
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
  const std::size_t had = proxies_.size();
  proxies_.resize(want, -1);
  for (const std::int32_t k : order_) {
    const auto i = static_cast<std::size_t>(k);
    // Element ids travel as the proxy's user data.
    if (i >= had) proxies_[i] = tree_.CreateProxy(boxes_[i], reinterpret_cast<void*>(static_cast<std::uintptr_t>(i)));
  }
}

void Box2dDetector::sort_by_morton(const Elements& e) {
  const std::int64_t n = e.size();
  keys_.resize(static_cast<std::size_t>(n));
  const Bounds b = e.centre_bounds();
  const double sx = b.max[0] > b.min[0] ? 65535.0 / (b.max[0] - b.min[0]) : 0.0;
  const double sy = b.max[1] > b.min[1] ? 65535.0 / (b.max[1] - b.min[1]) : 0.0;
  // 16 bits a coordinate, interleaved: x in the even bits, y in the odd ones.
  const auto spread = [](std::uint64_t v) {
    v = (v | (v << 8)) & 0x00FF00FFull;
    v = (v | (v << 4)) & 0x0F0F0F0Full;
    v = (v | (v << 2)) & 0x33333333ull;
    return (v | (v << 1)) & 0x55555555ull;
  };
  // A spread of a few denormals makes the scale infinite: clamp before the cast, which would be undefined.
  const auto quantise = [](double t) -> std::uint64_t { return t > 0.0 ? static_cast<std::uint64_t>(std::min(t, 65535.0)) : 0u; };
  for (std::int64_t k = 0; k < n; ++k) {
    const std::uint64_t qx = quantise((e.x[k] - b.min[0]) * sx), qy = quantise((e.y[k] - b.min[1]) * sy);
    keys_[static_cast<std::size_t>(k)] = ((spread(qx) | (spread(qy) << 1)) << 32) | static_cast<std::uint64_t>(k);
  }
  std::sort(keys_.begin(), keys_.end());
  order_.resize(keys_.size());
  for (std::size_t k = 0; k < keys_.size(); ++k) order_[k] = static_cast<std::int32_t>(keys_[k] & 0xFFFFFFFFull);
}

void Box2dDetector::detect(const Elements& e, const DetectOptions& options, PairList& out_pairs) {
  if (e.dim != 2) throw Error("box2d: only 2D elements are supported by this detector");
  refuse_periodic(e, "box2d");
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
  sort_by_morton(e);
  fit_proxies(n);
  // Move the proxies that existed before; Box2D re-inserts only those that left their fat AABB.
  for (const std::int32_t k : order_)
    if (static_cast<std::size_t>(k) < kept) tree_.MoveProxy(proxies_[static_cast<std::size_t>(k)], boxes_[static_cast<std::size_t>(k)], b2Vec2(0, 0));

  PairCollector pairs(out_pairs, options.max_pairs);
  struct Query {
    const b2DynamicTree* tree;
    const Elements* e;
    PairCollector* pairs;
    Touching touching;
    ElementId i;
    bool QueryCallback(std::int32_t proxy) {
      const auto j = static_cast<ElementId>(reinterpret_cast<std::uintptr_t>(tree->GetUserData(proxy)));
      if (j > i && in_contact(*e, i, j, touching)) pairs->add(i, j);
      return true;
    }
  } query{&tree_, &e, &pairs, options.touching, 0};
  for (const std::int32_t k : order_) {
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

// nbscope render: where labels go — the size of a label in ImGui's default font, and the label
// space that keeps every label of a frame clear of the others and of the panels. The legend's box
// (its corner is fixed) is reserved first, then the grid's title and axis numbers are placed and
// their bands reserved, then the lists' rail numbers, then element ids, so an id never sits among
// the axis numbers or covers the title.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

#include "render/camera.hpp"
#include "render/draw_sink.hpp"

namespace nbscope::render {

// A rectangle of the window in pixels (origin top left, y down), e.g. a panel's window.
struct PixelRect {
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// ImGui's default font, as the renderer draws labels: 7 px a character, 13 px a line.
inline constexpr double kCharPx = 7.0;
inline constexpr double kLinePx = 13.0;
// Width in pixels of a label of `chars` characters.
inline double label_width(std::size_t chars) { return kCharPx * static_cast<double>(chars) + 2.0; }

// Screen rectangles of the labels placed so far, bucketed so that a new label is checked only
// against its neighbours. The grid's title and axis numbers are placed first, then the ids, so an
// id never covers them and overlapping bounding circles (a wall of boxes) never pile ids up.
class LabelSpace {
 public:
  LabelSpace(const WorldRect& view, double ppm) : view_(view), ppm_(ppm) {}
  // True (and the rectangle is taken) when a w x h px label centred on world point `at` overlaps none.
  bool take(Vec2 at, double w, double h) {
    const double cx = (at.x() - view_.min.x()) * ppm_, cy = (view_.max.y() - at.y()) * ppm_;
    const Box b{cx - 0.5 * w, cy - 0.5 * h, cx + 0.5 * w, cy + 0.5 * h};
    if (overlaps(b)) return false;
    insert(b);
    return true;
  }
  // Takes a rectangle in pixels (a panel's window) so that no label is placed under it.
  void reserve(const PixelRect& r) { insert({r.x0, r.y0, r.x1, r.y1}); }
  // Takes the world rectangle [lo, hi] (an axis' band of numbers, the legend): no label goes there.
  void reserve_world(Vec2 lo, Vec2 hi) {
    insert({(lo.x() - view_.min.x()) * ppm_, (view_.max.y() - hi.y()) * ppm_, (hi.x() - view_.min.x()) * ppm_,
            (view_.max.y() - lo.y()) * ppm_});
  }
  // take() for a text, drawn when it got its place.
  bool text(Vec2 at, const char* text, Rgba colour, DrawSink& sink) {
    if (!take(at, label_width(std::strlen(text)), kLinePx)) return false;
    sink.text(at, text, colour);
    return true;
  }

 private:
  struct Box {
    double x0, y0, x1, y1;
  };
  // Calls f(bucket key) for every bucket `b` touches.
  template <class F>
  static void for_buckets(const Box& b, F&& f) {
    for (auto by = bucket(b.y0); by <= bucket(b.y1); ++by)
      for (auto bx = bucket(b.x0); bx <= bucket(b.x1); ++bx) f(key(bx, by));
  }
  bool overlaps(const Box& b) const {
    bool hit = false;
    for_buckets(b, [&](std::uint64_t k) {
      const auto it = buckets_.find(k);
      if (hit || it == buckets_.end()) return;
      for (const std::size_t i : it->second)
        hit = hit || (boxes_[i].x0 < b.x1 && b.x0 < boxes_[i].x1 && boxes_[i].y0 < b.y1 && b.y0 < boxes_[i].y1);
    });
    return hit;
  }
  // Boxes are clipped to the viewport (a margin beyond it): a reserved band reaching far outside the
  // view would otherwise fill buckets no label can reach.
  void insert(Box b) {
    const double w = (view_.max.x() - view_.min.x()) * ppm_, h = (view_.max.y() - view_.min.y()) * ppm_;
    b = {std::max(b.x0, -kBucketPx), std::max(b.y0, -kBucketPx), std::min(b.x1, w + kBucketPx), std::min(b.y1, h + kBucketPx)};
    if (!(b.x0 < b.x1 && b.y0 < b.y1)) return;
    for_buckets(b, [&](std::uint64_t k) { buckets_[k].push_back(boxes_.size()); });
    boxes_.push_back(b);
  }
  static constexpr double kBucketPx = 32.0;
  static std::int64_t bucket(double px) { return static_cast<std::int64_t>(std::floor(px / kBucketPx)); }
  static std::uint64_t key(std::int64_t bx, std::int64_t by) {
    return (static_cast<std::uint64_t>(bx) << 32) ^ static_cast<std::uint32_t>(by);
  }
  WorldRect view_;
  double ppm_;
  std::vector<Box> boxes_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> buckets_;
};


// True when a w x h px label centred on `at` lies inside `free` (the view less the panels).
inline bool label_inside(const WorldRect& free, Vec2 at, double w, double h, double ppm) {
  const double hw = 0.5 * w / ppm, hh = 0.5 * h / ppm;
  return at.x() - hw >= free.min.x() && at.x() + hw <= free.max.x() && at.y() - hh >= free.min.y() &&
         at.y() + hh <= free.max.y();
}

}  // namespace nbscope::render

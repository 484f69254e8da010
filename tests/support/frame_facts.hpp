// nbscope tests: everything a FrameLoop's frame shows and checks, captured to compare two frames
// that must be the same bit for bit (a live frame and the same frame shown again from the history;
// a plain step and an overlapped one).
#pragma once
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "app/frame_loop.hpp"

namespace nbscope::testframes {

struct FrameFacts {
  std::int64_t frame = 0;
  double time = 0;
  std::uint64_t hash = 0;
  Elements elements;
  std::vector<BodyShape> shapes;
  std::int64_t bodies = 0;
  PairList pairs, reference, f, t, g;
  std::vector<CellIndex> cells;
  std::array<std::int64_t, kInvariantCount> broken{};
  FrameCounts counts;
  std::int64_t violations = 0;
  bool checked = false;
};

// True when both sets hold the same elements, to the bit.
inline bool same_elements(const Elements& a, const Elements& b) {
  return a.size() == b.size() && (a.x == b.x).all() && (a.y == b.y).all() && (a.r == b.r).all();
}

// The facts of the loop's current frame.
inline FrameFacts facts_of(const FrameLoop& loop) {
  FrameFacts x;
  x.frame = loop.frame();
  x.time = loop.time();
  x.hash = loop.report().hash;
  x.elements = loop.elements();
  loop.body_shapes(x.shapes);
  x.bodies = loop.body_count();
  x.pairs = loop.pairs();
  x.reference = loop.reference_pairs();
  x.f = loop.box2d_pairs();
  x.t = loop.touching_pairs();
  x.g = loop.tight_aabb_pairs();
  x.cells = loop.cells();
  x.broken = loop.report().broken;
  x.counts = loop.report().counts;
  x.violations = loop.report().violation_count();
  x.checked = loop.report().checked;
  return x;
}

// Every fact of `a` equals `b`'s, to the bit.
inline void expect_same_frame(const FrameFacts& a, const FrameFacts& b) {
  SCOPED_TRACE("frame " + std::to_string(a.frame));
  EXPECT_EQ(a.frame, b.frame);
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.hash, b.hash);
  EXPECT_TRUE(same_elements(a.elements, b.elements));
  ASSERT_EQ(a.shapes.size(), b.shapes.size());
  for (std::size_t k = 0; k < a.shapes.size(); ++k) {
    const BodyShape& p = a.shapes[k];
    const BodyShape& q = b.shapes[k];
    EXPECT_TRUE(p.centre.x == q.centre.x && p.centre.y == q.centre.y && p.angle == q.angle &&
                p.vertex_count == q.vertex_count && p.element == q.element)
        << "shape " << k;
    for (std::size_t v = 0; v < static_cast<std::size_t>(p.vertex_count); ++v)
      EXPECT_TRUE(p.vertices[v].x == q.vertices[v].x && p.vertices[v].y == q.vertices[v].y) << "shape " << k << " vertex " << v;
  }
  EXPECT_EQ(a.bodies, b.bodies);
  EXPECT_EQ(a.pairs, b.pairs);
  EXPECT_EQ(a.reference, b.reference);
  EXPECT_EQ(a.f, b.f);
  EXPECT_EQ(a.t, b.t);
  EXPECT_EQ(a.g, b.g);
  EXPECT_EQ(a.cells, b.cells);
  EXPECT_EQ(a.broken, b.broken);
  EXPECT_EQ(a.counts.a_in_scope, b.counts.a_in_scope);
  EXPECT_EQ(a.counts.beyond_aabb, b.counts.beyond_aabb);
  EXPECT_EQ(a.counts.no_dynamic, b.counts.no_dynamic);
  EXPECT_EQ(a.violations, b.violations);
  EXPECT_EQ(a.checked, b.checked);
}

}  // namespace nbscope::testframes

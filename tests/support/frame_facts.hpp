// nbscope tests: everything a FrameLoop's frame shows and checks, captured to compare two frames
// that must be the same bit for bit (a live frame and the same frame shown again from the history;
// a plain step and an overlapped one). What the pipeline found is the product's FrameResult
// (check/frame_result.hpp); the frame source's side (elements, shapes, bodies) is read beside it.
#pragma once
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/frame_loop.hpp"
#include "check/frame_result.hpp"

namespace nbscope::testframes {

struct FrameFacts {
  FrameResult result;  // frame, time, hash, the lanes (pairs, cells, report), R, F, T, G
  Elements elements;
  std::vector<BodyShape> shapes;
  std::int64_t bodies = 0;
};

// True when both sets hold the same elements, to the bit.
inline bool same_elements(const Elements& a, const Elements& b) {
  return a.size() == b.size() && (a.x == b.x).all() && (a.y == b.y).all() && (a.r == b.r).all();
}

// The facts of the loop's current frame.
inline FrameFacts facts_of(const FrameLoop& loop) {
  FrameFacts x;
  x.result = loop.result();
  x.elements = loop.source().elements();
  loop.source().body_shapes(x.shapes);
  x.bodies = loop.source().body_count();
  return x;
}

// Every fact of `a` equals `b`'s, to the bit.
inline void expect_same_frame(const FrameFacts& a, const FrameFacts& b) {
  const FrameResult& p = a.result;
  const FrameResult& q = b.result;
  SCOPED_TRACE("frame " + std::to_string(p.frame));
  EXPECT_EQ(p.frame, q.frame);
  EXPECT_EQ(p.time, q.time);
  EXPECT_EQ(p.hash, q.hash);
  EXPECT_EQ(p.report().hash, q.report().hash);
  EXPECT_TRUE(same_elements(a.elements, b.elements));
  ASSERT_EQ(a.shapes.size(), b.shapes.size());
  for (std::size_t k = 0; k < a.shapes.size(); ++k) {
    const BodyShape& s = a.shapes[k];
    const BodyShape& t = b.shapes[k];
    EXPECT_TRUE(s.centre.x == t.centre.x && s.centre.y == t.centre.y && s.angle == t.angle &&
                s.vertex_count == t.vertex_count && s.element == t.element)
        << "shape " << k;
    for (std::size_t v = 0; v < static_cast<std::size_t>(s.vertex_count); ++v)
      EXPECT_TRUE(s.vertices[v].x == t.vertices[v].x && s.vertices[v].y == t.vertices[v].y) << "shape " << k << " vertex " << v;
  }
  EXPECT_EQ(a.bodies, b.bodies);
  EXPECT_EQ(p.selected().pairs, q.selected().pairs);
  EXPECT_EQ(p.reference, q.reference);
  EXPECT_EQ(p.box2d, q.box2d);
  EXPECT_EQ(p.touching, q.touching);
  EXPECT_EQ(p.tight_aabb, q.tight_aabb);
  EXPECT_EQ(p.selected().cells, q.selected().cells);
  const FrameReport& r = p.report();
  const FrameReport& s = q.report();
  EXPECT_EQ(r.broken, s.broken);
  EXPECT_EQ(r.counts.a_in_scope, s.counts.a_in_scope);
  EXPECT_EQ(r.counts.beyond_aabb, s.counts.beyond_aabb);
  EXPECT_EQ(r.counts.no_dynamic, s.counts.no_dynamic);
  EXPECT_EQ(r.violation_count(), s.violation_count());
  EXPECT_EQ(r.checked, s.checked);
}

}  // namespace nbscope::testframes

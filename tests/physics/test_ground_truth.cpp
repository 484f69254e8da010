// The check's fast set computations against the straightforward ones: the linear pair sort against
// std::sort, and a world's G, T, F and A-in-F scope against world.QueryAABB per fixture, a sorted
// walk of the contact list and Box2D's filters read from the bodies, on random scenes with circles,
// boxes and polygons (the AABB-pair grid behind G: test_aabb_pairs.cpp).
#include <gtest/gtest.h>

#include <box2d/box2d.h>

#include <algorithm>
#include <random>

#include "physics/kept_frame.hpp"
#include "physics/world.hpp"
#include "support/physics_context.hpp"

namespace nbscope {
namespace {

using testphysics::fixtures_of;
using testphysics::PhysicsTestContext;
using testphysics::tight_aabb;

// ---- the linear pair sort --------------------------------------------------------------------

// The linear pair sort gives std::sort's order, duplicates and out-of-range ids included.
TEST(PairSorter, SortsAsStdSort) {
  PairSorter sorter;
  for (std::uint32_t seed = 0; seed < 20; ++seed) {
    std::mt19937 rng(seed);
    const std::size_t n = 1 + seed * 37 % 500;
    PairList pairs;
    const std::size_t count = seed * 113 % 3000;
    for (std::size_t k = 0; k < count; ++k) {
      // Some elements with many partners (runs longer than the insertion sort's), and duplicates.
      const auto i = static_cast<ElementId>(k % 5 == 0 ? 0 : rng() % n);
      const auto j = static_cast<ElementId>(rng() % (n + 1));
      pairs.push_back({i, j});
    }
    if (seed == 7) pairs.push_back({static_cast<ElementId>(n), 0});  // out of range: std::sort
    if (seed == 8) pairs.push_back({-1, 0});
    PairList expected = pairs;
    std::sort(expected.begin(), expected.end());
    sorter.sort(pairs, n);
    ASSERT_EQ(pairs, expected) << "seed " << seed;
  }
}

// ---- a world's sets against the straightforward way -----------------------------------------

// A random jumble: circles, boxes, triangles, a compound body, static tiles touching edge to edge.
std::string jumble(int seed) {
  const std::string s = std::to_string(seed);
  return R"({"gravity": [0, -10], "bodies": [
    {"position": [0, 6], "fixtures": [{"shape": "circle", "radius": 0.4, "offset": [-0.3, 0]},
                                      {"shape": "box", "half_extents": [0.3, 0.2], "offset": [0.3, 0]}]}],
  "generators": [
    {"kind": "grid", "columns": 16, "rows": 1, "origin": [-8, -0.5], "spacing": [1, 0],
     "body": {"type": "static", "shape": "box", "half_extents": [0.5, 0.5]}},
    {"kind": "random_box", "count": 120, "seed": )" + s + R"(, "min": [-6, 0.5], "max": [6, 8], "radius": [0.2, 0.6], "body": {"shape": "circle"}},
    {"kind": "pile", "count": 40, "columns": 8, "position": [0, 9], "spacing": 0.5, "jitter": 0, "seed": )" + s + R"(,
     "body": {"shape": "circle", "radius": 0.25}},
    {"kind": "random_box", "count": 40, "seed": )" + std::to_string(seed + 100) + R"(, "min": [-6, 0.5], "max": [6, 8], "random_angle": true,
     "body": {"shape": "box", "half_extents": [0.4, 0.2]}},
    {"kind": "random_box", "count": 40, "seed": )" + std::to_string(seed + 200) + R"(, "min": [-6, 0.5], "max": [6, 8], "random_angle": true,
     "body": {"shape": "polygon", "vertices": [[-0.3, -0.3], [0.4, -0.2], [0, 0.5]]}}]})";
}

// G and T the straightforward way: world.QueryAABB with each fixture's tight AABB, keeping the
// tight overlaps, then each i's partners sorted.
void ground_truth_by_query(const PhysicsWorld& w, PairList& g, PairList& t) {
  const std::vector<const b2Fixture*> fixtures = fixtures_of(w);
  struct Query final : b2QueryCallback {
    std::vector<ElementId> hits;
    bool ReportFixture(b2Fixture* f) override {
      hits.push_back(static_cast<ElementId>(f->GetUserData().pointer));
      return true;
    }
  } query;
  const Elements& e = w.elements();
  g.clear();
  t.clear();
  for (std::size_t i = 0; i < fixtures.size(); ++i) {
    query.hits.clear();
    const b2AABB bi = tight_aabb(fixtures[i]);
    w.world().QueryAABB(&query, bi);
    std::sort(query.hits.begin(), query.hits.end());
    for (const ElementId j : query.hits) {
      const b2Fixture* a = fixtures[i];
      const b2Fixture* b = fixtures[static_cast<std::size_t>(j)];
      if (j <= static_cast<ElementId>(i) || !b2TestOverlap(bi, tight_aabb(b))) continue;
      const Pair p{static_cast<ElementId>(i), j};
      g.push_back(p);
      bool touch = false;
      if (a->GetType() == b2Shape::e_circle && b->GetType() == b2Shape::e_circle) {
        const double dx = e.x[p.i] - e.x[p.j], dy = e.y[p.i] - e.y[p.j];
        const double rr = static_cast<double>(a->GetShape()->m_radius) + static_cast<double>(b->GetShape()->m_radius);
        touch = dx * dx + dy * dy <= rr * rr;
      } else {
        touch = b2TestOverlap(a->GetShape(), 0, b->GetShape(), 0, a->GetBody()->GetTransform(), b->GetBody()->GetTransform());
      }
      if (touch) t.push_back(p);
    }
  }
}

// A-in-F's scope the straightforward way: Box2D's filters read from the fixtures and bodies.
PairList scope_by_bodies(const PhysicsWorld& w, const PairList& pairs, Box2dScope& why) {
  const std::vector<const b2Fixture*> fixtures = fixtures_of(w);
  b2ContactFilter* filter = const_cast<b2World&>(w.world()).GetContactManager().m_contactFilter;
  PairList out;
  why = {};
  for (const Pair& p : pairs) {
    auto* fa = const_cast<b2Fixture*>(fixtures[static_cast<std::size_t>(p.i)]);
    auto* fb = const_cast<b2Fixture*>(fixtures[static_cast<std::size_t>(p.j)]);
    const b2Body* ba = fa->GetBody();
    const b2Body* bb = fb->GetBody();
    bool joined = false;
    for (const b2JointEdge* je = bb->GetJointList(); je != nullptr; je = je->next)
      if (je->other == ba && !je->joint->GetCollideConnected()) joined = true;
    if (ba == bb) {
      ++why.same_body;
    } else if (ba->GetType() != b2_dynamicBody && bb->GetType() != b2_dynamicBody) {
      ++why.no_dynamic;
    } else if (joined) {
      ++why.joint;
    } else if (filter != nullptr && !filter->ShouldCollide(fa, fb)) {
      ++why.fixture_filter;
    } else if (!(fa->GetType() == b2Shape::e_circle && fb->GetType() == b2Shape::e_circle) &&
               !b2TestOverlap(tight_aabb(fa), tight_aabb(fb))) {
      ++why.beyond_aabb;
    } else {
      out.push_back(p);
    }
  }
  return out;
}

// G, T, F and the scope (with its reasons) equal the straightforward way's on random worlds, drags too.
TEST(WorldSets, EqualTheStraightforwardWayOnRandomWorlds) {
  for (int seed = 1; seed <= 6; ++seed) {
    PhysicsTestContext c(jumble(seed));
    PhysicsWorld& w = c.world();
    for (int frame = 0; frame < 40; ++frame) {
      if (frame == 10) (void)w.begin_drag(w.elements().x[30], w.elements().y[30]);  // a mouse joint: the joint path
      w.step();
      if (frame % 13 != 12) continue;
      PairList g, t, g0, t0;
      w.ground_truth(g, t);
      ground_truth_by_query(w, g0, t0);
      ASSERT_EQ(g, g0) << "seed " << seed << " frame " << w.frame();
      ASSERT_EQ(t, t0) << "seed " << seed << " frame " << w.frame();
      EXPECT_GT(t.size(), 50u);

      // F: the contact list walked and sorted with std::sort.
      PairList f, f0;
      w.contact_pairs(f);
      for (const b2Contact* c = w.world().GetContactList(); c != nullptr; c = c->GetNext()) {
        const auto a = static_cast<ElementId>(const_cast<b2Fixture*>(c->GetFixtureA())->GetUserData().pointer);
        const auto b = static_cast<ElementId>(const_cast<b2Fixture*>(c->GetFixtureB())->GetUserData().pointer);
        f0.push_back({std::min(a, b), std::max(a, b)});
      }
      std::sort(f0.begin(), f0.end());
      ASSERT_EQ(f, f0);

      // The scope of A-in-F on every pair of bounding circles that meet (brute force) and G.
      PairList circles;
      const Elements& e = w.elements();
      for (ElementId i = 0; i < e.size(); ++i)
        for (ElementId j = i + 1; j < e.size(); ++j)
          if (in_contact(e, i, j, Touching::inclusive)) circles.push_back({i, j});
      for (const PairList* pairs : {&circles, &g}) {
        PairList scope;
        Box2dScope why, why0;
        w.in_box2d_scope(*pairs, scope, why);
        EXPECT_EQ(scope, scope_by_bodies(w, *pairs, why0));
        EXPECT_EQ(why.same_body, why0.same_body);
        EXPECT_EQ(why.no_dynamic, why0.no_dynamic);
        EXPECT_EQ(why.joint, why0.joint);
        EXPECT_EQ(why.fixture_filter, why0.fixture_filter);
        EXPECT_EQ(why.beyond_aabb, why0.beyond_aabb);
        EXPECT_GT(why.same_body, 0u);
        EXPECT_GT(why.no_dynamic, 0u);
      }

      // A kept frame rebuilt from the history finds the same sets.
      const KeptWorldFrame kept(w, c.capture());
      PairList g1, t1;
      kept.ground_truth(g1, t1);
      EXPECT_EQ(g1, g);
      EXPECT_EQ(t1, t);
    }
  }
}

}  // namespace
}  // namespace nbscope

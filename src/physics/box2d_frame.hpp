// nbscope physics: Box2D's side of one frame, as the cross-check and the drawing read it. The live
// world (PhysicsWorld) is one; a frame rebuilt from the history (KeptWorldFrame) is another, so a
// past frame is checked and drawn by the same code as the live one.
//
// Index: Box2dScope (why pairs are out of A-in-F) | BodyPose, WorldState (what the history keeps
// of a frame) | Box2dFrame (the interface).
#pragma once
#include <cstdint>
#include <vector>

#include "core/elements.hpp"
#include "core/pairs.hpp"
#include "physics/shapes.hpp"

namespace nbscope {

// Which pairs of A the A ⊆ F invariant applies to, and why the others are left out.
struct Box2dScope {
  std::size_t same_body = 0;       // two fixtures of one body: Box2D never pairs them
  std::size_t no_dynamic = 0;      // neither body dynamic (static/kinematic only): b2Body::ShouldCollide
  std::size_t joint = 0;           // bodies joined with collideConnected = false
  std::size_t fixture_filter = 0;  // refused by the world's b2ContactFilter (category/mask/group)
  std::size_t beyond_aabb = 0;     // a polygon's bounding circle meets, its shapes' tight AABBs do not
};

// One body's transform, exactly as Box2D holds it (b2Transform: position, then sin and cos).
struct BodyPose {
  float x = 0, y = 0, s = 0, c = 1;
};

// What the history keeps of one frame of a world: every body's transform and Box2D's contact list.
// With the world's fixed geometry (shapes, bounding circles) that rebuilds the frame's elements,
// shapes, tight AABBs and every check set bit for bit (KeptWorldFrame).
struct WorldState {
  std::int64_t frame = 0;
  double time = 0;
  std::int32_t fixtures = 0;     // elements that existed at this frame (emitters add later ones)
  std::vector<BodyPose> poses;   // one per body that existed at this frame
  PackedPairs contacts;          // F: Box2D's contact list after this frame's step

  // Bytes this state holds.
  [[nodiscard]] std::size_t bytes() const { return sizeof(*this) + poses.capacity() * sizeof(BodyPose) + contacts.bytes(); }
};

// Box2D's side of one frame.
class Box2dFrame {
 public:
  virtual ~Box2dFrame() = default;
  // The frame's number (steps since the scene started) and simulated time in seconds.
  [[nodiscard]] virtual std::int64_t frame() const = 0;
  [[nodiscard]] virtual double time() const = 0;
  // The frame's elements: element k is fixture k's bounding circle.
  [[nodiscard]] virtual const Elements& elements() const = 0;
  // Bodies that exist at this frame.
  [[nodiscard]] virtual std::int64_t body_count() const = 0;
  // F: Box2D's contact list after the frame's step (fat-AABB pairs past Box2D's filters), sorted.
  virtual void contact_pairs(PairList& out) const = 0;
  // G: pairs of fixtures whose tight AABBs overlap (no filters); T ⊆ G: shapes touching. Both sorted.
  virtual void ground_truth(PairList& tight_aabb_pairs, PairList& touching) const = 0;
  // The pairs of `pairs` (sorted, i < j) that Box2D's contact list must hold, and why the others are not.
  virtual void in_box2d_scope(const PairList& pairs, PairList& out, Box2dScope& why_not) const = 0;
  // Every fixture at this frame, in world coordinates, for drawing (clears `out` first).
  virtual void shapes(std::vector<BodyShape>& out) const = 0;
};

}  // namespace nbscope

// nbscope physics: a Box2D 2.4.1 world built from a Scene, stepped frame by frame, handing out the
// frame's elements (one bounding circle per fixture) and Box2D's side of the cross-check.
//
// Index: element geometry | PhysicsWorld (build, step, elements, Box2D's pair sets, scope of A ⊆ F,
// shapes for drawing, mouse drag).
//
// This header includes Box2D; only physics, check and the frame loop's .cpp include it.
#pragma once
#include <box2d/box2d.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/elements.hpp"
#include "core/pairs.hpp"
#include "physics/aabb_pairs.hpp"
#include "physics/box2d_frame.hpp"
#include "physics/generators.hpp"
#include "physics/memory_budget.hpp"
#include "physics/scene.hpp"
#include "physics/shapes.hpp"
#include "physics/world_limits.hpp"

namespace nbscope {

// A polygon's bounding circle is enlarged by this much beyond its skin, so that Box2D's float GJK
// (which calls shapes within ~1e-6 m "overlapping", and rounds world vertices to float) never finds
// two shapes touching whose bounding circles do not meet. Circles are exact.
inline constexpr double kPolygonCircleMargin = 1e-3;

class PhysicsWorld final : public Box2dFrame {
 public:
  // Builds the world: gravity, every initial body (scene bodies, then generated ones), sleeping
  // off (bodies must never skip the broadphase). Throws Error naming the scene field when Box2D
  // would change a shape (e.g. merge polygon vertices).
  explicit PhysicsWorld(const Scene& scene);
  ~PhysicsWorld();
  PhysicsWorld(const PhysicsWorld&) = delete;
  PhysicsWorld& operator=(const PhysicsWorld&) = delete;

  // One frame: emitters add the bodies due, then sub_steps Box2D steps of time_step/sub_steps;
  // then the elements and tight AABBs are recomputed at the new transforms.
  // Throws Error "path: frame K: ..." (physics/world_limits.hpp), leaving the last frame as it was
  // (elements, shapes, contacts) and every later step() refusing with the same message:
  //   before Box2D steps, when the contacts it would create are estimated past max_contacts (the
  //   scene's, or set_max_contacts) or past what the memory this process can get holds
  //   (physics/memory_budget.hpp; ~bytes_per_contact() each), and after any sub-step that made
  //   more than either;
  //   and, with one line and exit 2 (physics/box2d_memory.hpp), when an allocation inside Box2D fails;
  //   after the step, when a body's position, angle or velocity is not finite, or a body is beyond
  //   kMaxWorldCoordinate.
  void step();
  // Overrides the scene's max_contacts (the --max-contacts flag).
  void set_max_contacts(std::int64_t limit) { max_contacts_ = limit; }
  [[nodiscard]] std::int64_t max_contacts() const { return max_contacts_; }
  // The contacts the last estimate counted (before the last step, or 0), and Box2D's contact count
  // now. Both safe to read from another thread while step() runs (the slow-frame note).
  [[nodiscard]] std::int64_t estimated_contacts() const { return estimated_contacts_.load(std::memory_order_relaxed); }
  [[nodiscard]] std::int64_t bodies_now() const { return bodies_now_.load(std::memory_order_relaxed); }
  // Pairs of fixtures, of different bodies and at least one dynamic, whose boxes overlap, where the
  // boxes are the fat AABBs Box2D holds now grown to cover where each body's velocity takes its
  // fixtures in the next sub-step (b2_aabbMultiplier times that far ahead, as Box2D's MoveProxy
  // does): about the contacts Box2D's next step creates.
  [[nodiscard]] std::int64_t estimate_contacts() const;
  // "body 17 (generators[0] #12)", "body 3 (bodies[3])": the body as the scene file makes it.
  [[nodiscard]] std::string body_name(std::size_t body) const;
  // Frames stepped since construction, and the simulated time in seconds.
  [[nodiscard]] std::int64_t frame() const override { return frame_; }
  [[nodiscard]] double time() const override { return time_; }
  [[nodiscard]] const Scene& scene() const { return scene_; }

  // The frame's elements: element k is fixture k's bounding circle (circle: centre and radius;
  // polygon: centroid and farthest vertex + skin + kPolygonCircleMargin), at the current transforms.
  [[nodiscard]] const Elements& elements() const override { return elements_; }
  // Element -> (body, fixture), same indexing as elements().
  [[nodiscard]] const std::vector<ElementSource>& sources() const { return sources_; }
  [[nodiscard]] std::int64_t body_count() const override { return static_cast<std::int64_t>(bodies_.size()); }

  // F: Box2D's contact list after the last step (fat-AABB pairs that passed Box2D's filters),
  // as sorted element pairs. Empty before the first step (Box2D finds contacts inside Step).
  void contact_pairs(PairList& out) const override;
  // G: every pair of fixtures whose tight AABBs (shape->ComputeAABB at the current transforms)
  // overlap (b2TestOverlap, inclusive), no filters applied, found with a grid of its own over the
  // tight AABBs (physics/aabb_pairs.hpp; the same set world.QueryAABB gives); and T ⊆ G: the pairs
  // whose shapes touch now (circles: |c1-c2| <= r1+r2 in double as the elements; otherwise
  // b2TestOverlap). Both sorted.
  void ground_truth(PairList& tight_aabb_pairs, PairList& touching) const override;
  // The pairs of `pairs` (sorted, i < j) that Box2D's contact list must hold: Box2D's filters
  // applied (same body, no dynamic body, joints, contact filter) and the shapes' tight AABBs
  // overlapping. Counts what was left out and why.
  void in_box2d_scope(const PairList& pairs, PairList& out, Box2dScope& why_not) const override;
  // The largest bounding-circle radius of the bodies the emitters will add (0 without emitters);
  // `out_where` names the emitter ("file:line: generators[k]: ").
  double largest_emitted_radius(std::string& out_where) const;
  // True when the tight AABBs of two elements' fixtures overlap (inclusive, in float as Box2D).
  [[nodiscard]] bool tight_aabbs_overlap(ElementId a, ElementId b) const;

  // Every fixture at the current transforms, for drawing (appends to `out` after clearing it).
  void shapes(std::vector<BodyShape>& out) const override;

  // What the history keeps of this frame (every body's transform, Box2D's contact list) into `out`;
  // `contacts`, when given, is this frame's contact_pairs() already computed (by the check).
  void capture(WorldState& out, const PairList* contacts = nullptr) const;
  // Element k's centre at a kept frame (k must exist at that frame), as elements() had it then.
  void element_centre(const WorldState& state, ElementId k, double& x, double& y) const;
  // The same from what a snapshot keeps of the world (LiveWorld's, while the worker steps it):
  // the element's body and its centre in body coordinates.
  static void element_centre(const WorldState& state, const ElementSource& source, b2Vec2 local_centre, double& x, double& y);
  // Each element's bounding-circle centre in body coordinates, same indexing as elements().
  [[nodiscard]] const std::vector<b2Vec2>& local_centres() const { return local_centres_; }

  // Picks the dynamic body under (x, y) and pulls it there with a b2MouseJoint; false if none.
  bool begin_drag(double x, double y);
  // Moves the drag target.
  void drag_to(double x, double y);
  // Releases the body (no effect when not dragging).
  void end_drag();
  [[nodiscard]] bool dragging() const { return mouse_joint_ != nullptr; }

  // The Box2D world itself, for the box2d-side tests and the benchmark.
  [[nodiscard]] const b2World& world() const { return *world_; }

 private:
  friend class KeptWorldFrame;  // rebuilds a past frame with the geometry helpers below

  // Where a body comes from: bodies[ordinal] (generator -1) or generators[generator] #ordinal.
  struct BodyOrigin {
    std::int32_t generator = -1;
    std::int64_t ordinal = 0;
  };
  void add_body(const BodySpec& spec, BodyOrigin origin);
  // "scene.json: frame 3: ", for the frame step() makes.
  [[nodiscard]] std::string frame_prefix() const;
  // The limits of step(), each throwing (and remembering) its Error.
  void refuse(const std::string& what);
  void check_contact_estimate();
  // Reads the memory budget again and derives memory_contact_limit_ from it.
  void update_memory_limit();
  // "this process can get about 3.1 GB for them (MemAvailable; ...)": the memory limit's words.
  [[nodiscard]] std::string memory_text() const;
  // True when the contacts may jump this frame: new bodies, Box2D's count past a quarter of the
  // limit, or bodies fast enough to stretch their fat AABBs over many others.
  [[nodiscard]] bool estimate_needed() const;
  // The emitters' pile: refused early when the contacts grow about as the square of the bodies
  // (bodies poured onto each other that Box2D cannot part) and the bodies still to come would
  // take them past the limit. `contacts` is this frame's estimate.
  void check_emitter_growth(std::int64_t contacts);
  void check_contact_count(int sub_step);
  void check_bodies();
  void update_geometry();
  // Elements and tight AABBs of the first `fixtures` fixtures with bodies at `poses` (live and kept
  // frames alike, so both compute the same bits).
  void geometry_at(const std::vector<b2Transform>& poses, std::size_t fixtures, Elements& out_elements,
                   std::vector<b2AABB>& out_aabbs) const;
  // True when fixtures a and b touch with their bodies at `poses` (the elements give circle centres).
  [[nodiscard]] bool touching_at(ElementId a, ElementId b, const std::vector<b2Transform>& poses,
                                 const Elements& elements) const;
  // T: the pairs of `tight_aabb_pairs` (G, sorted) whose fixtures touch at `poses`, into `out`.
  void touching_of(const PairList& tight_aabb_pairs, const std::vector<b2Transform>& poses, const Elements& elements,
                   PairList& out) const;
  // in_box2d_scope() with the tight AABBs of some frame.
  void scope_at(const PairList& pairs, const std::vector<b2AABB>& aabbs, PairList& out, Box2dScope& why_not) const;
  // shapes() of the first `fixtures` fixtures with bodies at `poses`.
  void shapes_at(const std::vector<b2Transform>& poses, std::size_t fixtures, std::vector<BodyShape>& out) const;

  Scene scene_;
  std::unique_ptr<b2World> world_;
  b2Body* ground_ = nullptr;             // anchor of the mouse joint; has no fixtures
  b2MouseJoint* mouse_joint_ = nullptr;
  std::vector<Emitter> emitters_;
  std::vector<std::int32_t> emitter_generators_;  // per emitter: its index in scene_.generators
  std::vector<BodySpec> pending_;        // emitted bodies waiting to be created
  std::vector<b2Body*> bodies_;
  std::vector<BodyOrigin> origins_;      // per body
  std::int64_t max_contacts_ = kDefaultMaxContacts;
  // The contacts the memory this process can get holds (physics/memory_budget.hpp), as of the last
  // estimate: the limit below max_contacts_ that no flag raises.
  std::int64_t memory_contact_limit_ = kMaxMaxContacts;
  MemoryBudget memory_;                  // the budget it was derived from
  std::int64_t growth_bodies_ = 0, growth_contacts_ = 0;  // check_emitter_growth()'s last checkpoint
  std::string broken_;                   // the Error that stopped the world ("" while it runs)
  bool estimate_due_ = true;             // bodies were added since the last estimate
  std::atomic<std::int64_t> estimated_contacts_{0};
  std::atomic<std::int64_t> bodies_now_{0};
  std::vector<b2Fixture*> fixtures_;     // indexed by element id
  std::vector<b2Vec2> local_centres_;    // bounding-circle centre in body coordinates
  std::vector<double> radii_;            // bounding-circle radius
  std::vector<b2AABB> aabbs_;            // tight AABBs at the current transforms
  std::vector<b2Transform> poses_;       // every body's transform, as of the last update_geometry()
  std::vector<ElementSource> sources_;
  std::vector<std::uint8_t> circle_;     // per fixture: a circle (else a polygon)
  std::vector<std::uint8_t> dynamic_;    // per body: a dynamic body (types never change here)
  bool default_filters_ = true;          // every fixture has Box2D's default filter data
  mutable PairSorter contact_sorter_;    // scratch of contact_pairs()
  mutable std::vector<std::uintptr_t> contact_order_, contact_order_next_;  // contacts in the last walk's order
  mutable AabbPairFinder aabb_pairs_;    // scratch of ground_truth()
  Elements elements_;
  std::int64_t frame_ = 0;
  double time_ = 0;
};

}  // namespace nbscope

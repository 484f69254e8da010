// nbscope check: the cross-checks of one frame (docs/architecture.md "Invariants").
//
// Sets: A = the chosen algorithm's pairs; R = the reference's (brute force up to
// CheckOptions::brute_limit elements, above it and for brute itself another detector: sort, or nbs
// when the algorithm is sort); F = Box2D's contact list; G = pairs whose tight AABBs overlap
// (b2TestOverlap, inclusive: the set world.QueryAABB gives, found with physics/aabb_pairs.hpp's grid);
// T ⊆ G = shapes touching now. Invariants, each violation with frame, pair, both cells:
//   A==R           A equals R (missing and extra pairs both reported);
//   A-in-F         the pairs of A in Box2D's scope are in F — Box2D's filters (same body, no dynamic
//                  body, joints without collideConnected, the contact filter) are applied to A first,
//                  and pairs with a polygon whose shapes' tight AABBs do not overlap are left out,
//                  since a polygon's bounding circle reaches beyond its AABB where Box2D never looks
//                  (two circles always stay: a wrong circle pair is far from Box2D's fat AABBs);
//   T-in-A         T ⊆ A;
//   AABB-in-cells  every pair of G lies in the same or neighbouring cells of the detector's
//                  integerisation (pairs whose elements' exact boxes do not overlap — Box2D's float
//                  AABBs touching by rounding — are counted, not flagged);
//   cells          a detector that integerises by itself (a plugin's own_cells()) gives every
//                  element the grid's cell (eq. 3.76); each other element is a violation (k, k).
//                  And the lists it walks hold only their cell's elements (a plugin's
//                  walk_check()): each element tested from another cell's list is a violation
//                  (stray, finder), cells the list's (where the detector had it) and the finder's.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "check/report.hpp"
#include "core/contracts.hpp"
#include "core/detector.hpp"
#include "physics/box2d_frame.hpp"

namespace nbscope {

struct CheckOptions {
  // Up to this many elements R is brute force (O(N^2)); above it, another detector.
  std::int64_t brute_limit = 2000;
};

// What one frame's check looks at.
struct CheckInput {
  std::string_view algorithm;                   // name of the detector under test
  const PairList* pairs = nullptr;              // A, sorted
  const std::vector<CellIndex>* cells = nullptr;  // the detector's cell of every element
  // The grid's cell of every element, when the detector integerised its own (`cells` are then the
  // detector's); null when `cells` are the grid's, which holds `cells` by construction.
  const std::vector<CellIndex>* grid_cells = nullptr;
  const WalkCheck* walks = nullptr;             // the detector's walk check, or null when not checked
  bool contract_checked = false;                // the detection's contracts were checked (a trace, or a misbehaviour)
  const BrokenContract* contract = nullptr;     // its first broken contract, or null
  bool drop_box2d_contact = false;              // the drop-box2d-contact fault (check/faults.hpp)
  bool recorded = false;  // A is a recording's own pairs, not a detector's: violations of A say so in their words
  // The recorded pairs' precision band (FrameInput::precision): a disagreement of A and R whose gap is
  // within it, or an exact tie, is a BoundaryPair, not a violation. Negative: no band (a detector's pairs).
  double precision = -1;
};

// A pair of `elements` on which a file's pairs and R disagree, when the data cannot decide it: its gap
// within `precision` of touching, or an exact tie the two touching conventions decide differently
// (`in_r`: R has it). nullopt for any other pair (a violation), or one naming no two elements.
[[nodiscard]] std::optional<BoundaryPair> boundary_pair(const Elements& elements, std::int64_t i, std::int64_t j, double precision, bool in_r);

class FrameChecker {
 public:
  explicit FrameChecker(CheckOptions options = {});
  ~FrameChecker();

  // The reference detector for n elements when testing `algorithm` (see the header comment); of a
  // periodic frame, brute or nbs (the detectors that measure by the minimum image).
  [[nodiscard]] std::string reference_for(std::int64_t n, std::string_view algorithm, bool periodic = false) const;
  // How the reference is chosen, in words, for reports.
  [[nodiscard]] std::string reference_policy() const;
  // Which pairs A-in-F applies to, in words, for reports.
  [[nodiscard]] static std::string scope_note();

  // Computes what does not depend on the algorithm under test, once per frame: F, G and T (R is
  // computed by the first check() that needs it, and shared by later ones of the frame). `world` is
  // the live world or a kept past frame (physics/kept_frame.hpp); it must outlive the frame's checks.
  // With `algorithm` (the one the frame's first check() will test), R is computed at the same time
  // as F, G and T, on a second thread (for frames of at least kParallelReferenceFrom elements),
  // so that the check costs about the longer of the two instead of their sum.
  void begin_frame(const Box2dFrame& world, const DetectOptions& options, std::string_view algorithm = {});
  // Frames from this many elements compute R beside F, G and T (below it a thread costs more than it saves).
  static constexpr std::int64_t kParallelReferenceFrom = 5000;
  // A frame without a Box2D world (recorded frames): only A==R can be checked; check() marks the
  // report's box2d_checks false and leaves F, G and T empty. `elements` must outlive the frame's checks.
  void begin_frame(const Elements& elements, std::int64_t frame, const DetectOptions& options);
  // Runs every invariant for one algorithm's pairs into `out` (counts, broken, violations, and
  // check_timings: the first check() of a frame also gets begin_frame()'s sets; out.timings untouched).
  // begin_frame() must have been called for this frame; several algorithms may be checked against one frame.
  void check(const CheckInput& in, FrameReport& out);

  // The sets of the frame, sorted: R (of the last check()), F, T, G.
  [[nodiscard]] const PairList& reference_pairs() const;
  [[nodiscard]] const PairList& box2d_pairs() const { return f_; }
  [[nodiscard]] const PairList& touching_pairs() const { return t_; }
  [[nodiscard]] const PairList& tight_aabb_pairs() const { return g_; }
  // Hands F, T and G over to the caller once every check of the frame is done (swapped, not copied:
  // the checker refills the caller's old lists next frame, so no memory is allocated per frame).
  void take_sets(PairList& f, PairList& t, PairList& g) {
    f.swap(f_);
    t.swap(t_);
    g.swap(g_);
  }

 private:
  Detector& reference(const std::string& name);
  // Index in frame_references_ of R of this frame from detector `name`, computed once per frame.
  std::size_t reference_of(const std::string& name);
  // Claims the slot of R from detector `name` for this frame, uncomputed; returns its index.
  std::size_t claim_reference(const std::string& name);
  // Computes the claimed R in slot `index`: detection, then sorting.
  void compute_reference(std::size_t index);
  // A new frame: no R yet; the shared sets' times go to the next check().
  void start_frame(std::int64_t frame, const Elements& elements, const DetectOptions& options);

  struct FrameReference {
    std::string name;
    PairList pairs;
  };
  static constexpr std::size_t kNoReference = static_cast<std::size_t>(-1);

  CheckOptions options_;
  const Box2dFrame* world_ = nullptr;                  // of the current frame; null for recorded frames
  const Elements* elements_ = nullptr;                 // of the current frame
  std::int64_t frame_ = 0;
  DetectOptions detect_options_;
  std::vector<std::unique_ptr<Detector>> references_;  // kept: box2d keeps its tree between frames
  std::vector<FrameReference> frame_references_;       // R per reference; the first frame_reference_count_ are this frame's
  std::size_t frame_reference_count_ = 0;
  std::size_t r_ = kNoReference;                       // R of the last check(), in frame_references_
  CheckTimings shared_;                                // F, G/T of begin_frame(), for the frame's first check()
  PairSorter sorter_;
  PairList f_, t_, g_, scope_, f_faulty_, a_valid_;
};

}  // namespace nbscope

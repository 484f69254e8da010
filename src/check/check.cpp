#include "check/check.hpp"

#include "core/pairs.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>

#include "physics/box2d_detector.hpp"

namespace nbscope {

namespace {
// The detectors the reference policy names (docs/architecture.md "Reference policy"): each is chosen for what
// it is, not for a capability another detector could share.
constexpr std::string_view kBrute = "brute";  // the reference up to --brute-limit elements
constexpr std::string_view kSort = "sort";    // the plainest cell method, above the limit
constexpr std::string_view kNbs = "nbs";      // the reference of sort itself
constexpr std::string_view kBox2d = "box2d";  // the last resort, physics' own

using Clock = std::chrono::steady_clock;

// Milliseconds since `t`, and `t` moved to now: the parts of a check timed one after another.
double lap(Clock::time_point& t) {
  const Clock::time_point now = Clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - t).count();
  t = now;
  return ms;
}

}  // namespace

std::optional<BoundaryPair> boundary_pair(const Elements& e, std::int64_t i, std::int64_t j, double precision, bool in_r) {
  if (i < 0 || j < 0 || i >= e.size() || j >= e.size() || i == j) return std::nullopt;
  const auto a = static_cast<ElementId>(i), b = static_cast<ElementId>(j);
  const double gap = contact_gap(e, a, b);
  const bool tie = in_contact(e, a, b, Touching::inclusive) && !in_contact(e, a, b, Touching::strict);
  if (!tie && !(std::abs(gap) <= precision)) return std::nullopt;
  return BoundaryPair{Pair{a, b}, gap, tie ? 0.0 : precision, tie, in_r};
}

FrameChecker::FrameChecker(CheckOptions options) : options_(options) {}
FrameChecker::~FrameChecker() = default;

std::string FrameChecker::reference_for(std::int64_t n, std::string_view algorithm, bool periodic) const {
  // A periodic frame: only brute and nbs measure by the minimum image; each is the other's reference.
  if (periodic) return std::string(algorithm != kBrute && (n <= options_.brute_limit || algorithm == kNbs) ? kBrute : kNbs);
  if (algorithm != kBrute && n <= options_.brute_limit) return std::string(kBrute);
  // Above the limit: sort (the plainest cell method: sort by cell key, scan neighbour cells), or nbs
  // when sort is the one under test; box2d if the registry has no sort.
  static const bool have_sort = [] {
    for (const DetectorInfo& d : detector_infos())
      if (d.name == kSort) return true;
    return false;
  }();
  if (algorithm != kSort && have_sort) return std::string(kSort);
  return std::string(algorithm != kNbs ? kNbs : kBox2d);
}

std::string FrameChecker::reference_policy() const {
  return "brute force up to " + std::to_string(options_.brute_limit) +
         " elements; above that (and for brute itself) sort, or nbs when the algorithm under test is sort";
}

std::string FrameChecker::scope_note() {
  return "Box2D's filters are applied to A before comparing with F: pairs of fixtures of the same body, pairs with no "
         "dynamic body, pairs of bodies joined without collideConnected and pairs the contact filter refuses are left "
         "out; so are pairs with a polygon whose shapes' tight AABBs do not overlap (a polygon's bounding circle reaches "
         "beyond its AABB, where Box2D's broadphase never looks; two circles are always kept, since their bounding "
         "circles are the shapes). Each reason is counted per frame.";
}

Detector& FrameChecker::reference(const std::string& name) {
  for (const auto& d : references_)
    if (d->name() == name) return *d;
  // box2d is physics' own; make it directly so the check does not depend on registration order.
  references_.push_back(name == kBox2d ? std::make_unique<Box2dDetector>() : make_detector(name));
  return *references_.back();
}

std::size_t FrameChecker::claim_reference(const std::string& name) {
  // Last frames' entries are reused: their pair lists keep their capacity.
  if (frame_reference_count_ == frame_references_.size()) frame_references_.emplace_back();
  frame_references_[frame_reference_count_].name = name;
  reference(name);  // made here, not on the thread that computes it
  return frame_reference_count_++;
}

void FrameChecker::compute_reference(std::size_t index) {
  FrameReference& r = frame_references_[index];
  reference(r.name).detect(*elements_, detect_options_, r.pairs);
  sorter_.sort(r.pairs, static_cast<std::size_t>(elements_->size()));
}

std::size_t FrameChecker::reference_of(const std::string& name) {
  for (std::size_t k = 0; k < frame_reference_count_; ++k)
    if (frame_references_[k].name == name) return k;
  const std::size_t index = claim_reference(name);
  try {
    compute_reference(index);
  } catch (...) {
    --frame_reference_count_;  // not computed: a later check() tries again, or reports the same error
    throw;
  }
  return index;
}

const PairList& FrameChecker::reference_pairs() const {
  static const PairList none;
  return r_ == kNoReference ? none : frame_references_[r_].pairs;
}

void FrameChecker::start_frame(std::int64_t frame, const Elements& elements, const DetectOptions& options) {
  elements_ = &elements;
  frame_ = frame;
  detect_options_ = options;
  detect_options_.threads = 1;  // R (nbs when sort is tested) on the serial loops: independent of the bands
  frame_reference_count_ = 0;
  r_ = kNoReference;
  shared_ = {};
}

void FrameChecker::begin_frame(const Box2dFrame& world, const DetectOptions& options, std::string_view algorithm) {
  world_ = &world;
  start_frame(world.frame(), world.elements(), options);
  // R on a second thread while this one walks Box2D's world for F, G and T: they share nothing
  // but the (unchanging) elements, and the thread is joined before this returns.
  std::future<double> r_ms;
  if (!algorithm.empty() && elements_->size() >= kParallelReferenceFrom) {
    const std::size_t index = claim_reference(reference_for(elements_->size(), algorithm, elements_->box.any()));
    r_ms = std::async(std::launch::async, [this, index] {
      Clock::time_point t = Clock::now();
      compute_reference(index);
      return lap(t);
    });
  }
  Clock::time_point t = Clock::now();
  try {
    world.contact_pairs(f_);
    shared_.f_ms = lap(t);
    world.ground_truth(g_, t_);
    shared_.g_t_ms = lap(t);
  } catch (...) {
    if (r_ms.valid()) r_ms.wait();  // never leave the thread writing into this checker
    throw;
  }
  if (r_ms.valid()) {
    try {
      shared_.r_ms = r_ms.get();
    } catch (...) {
      frame_reference_count_ = 0;  // R was not computed: check() computes it again, and reports the error there
    }
  }
}

void FrameChecker::begin_frame(const Elements& elements, std::int64_t frame, const DetectOptions& options) {
  world_ = nullptr;
  start_frame(frame, elements, options);
  f_.clear();
  g_.clear();
  t_.clear();
}

void FrameChecker::check(const CheckInput& in, FrameReport& out) {
  const Elements& e = *elements_;
  const std::vector<CellIndex>& cells = *in.cells;
  const auto n = static_cast<ElementId>(e.size());
  const std::int64_t frame = frame_;

  out.frame = frame;
  out.dim = e.dim;
  out.checked = true;
  out.box2d_checks = world_ != nullptr;
  out.box2d_stepped = world_ != nullptr && frame > 0;
  out.broken = {};
  out.violations.clear();
  out.counts = {};
  out.counts.elements = n;
  out.counts.bodies = world_ != nullptr ? world_->body_count() : 0;
  out.check_timings = shared_;  // the shared sets count once, for the frame's first check
  shared_ = {};
  CheckTimings& ms = out.check_timings;
  const auto invariant_ms = [&](Invariant inv) -> double& { return ms.invariant_ms[static_cast<std::size_t>(inv)]; };
  Clock::time_point t = Clock::now();

  const auto cell_of = [&](ElementId k) {
    return k >= 0 && static_cast<std::size_t>(k) < cells.size() ? cells[static_cast<std::size_t>(k)] : CellIndex{-1, -1};
  };
  const auto report = [&](Invariant inv, const Pair& p, const char* what) {
    ++out.broken[static_cast<std::size_t>(inv)];
    if (out.violations.size() >= kMaxListedViolationsPerFrame) return;
    out.violations.push_back({frame, inv, p, cell_of(p.i), cell_of(p.j), what});
    if (p.i >= 0 && p.j >= 0 && p.i < n && p.j < n && p.i != p.j) out.violations.back().gap = contact_gap(e, p.i, p.j);
  };

  // A itself must be well formed before any set algebra: 0 <= i < j < n, each pair once, sorted. A
  // correct A is used as it is; otherwise the well-formed pairs are copied and each other one is
  // reported for what is wrong with it (a recording's own pairs are the user's: their words say so).
  const auto fault_of = [n](const Pair& p, const Pair* before) -> int {
    if (p.i < 0 || p.j < 0 || p.i >= n || p.j >= n) return 1;
    if (p.i == p.j) return 2;
    if (p.i > p.j) return 3;
    if (before != nullptr && !(*before < p)) return *before == p ? 4 : 3;
    return 0;
  };
  static constexpr const char* kDetectorWhat[] = {"", "not an element of this frame (i or j outside 0..N-1)",
                                                  "an element paired with itself in A", "out of order in A (not i < j, or not sorted)",
                                                  "given twice in A"};
  static constexpr const char* kRecordedWhat[] = {"", "not an element of this frame (i or j outside 0..N-1)",
                                                  "an element paired with itself in the recorded pairs",
                                                  "out of order in the recorded pairs (not sorted)", "given twice in the recorded pairs"};
  const char* const* what_of = in.recorded ? kRecordedWhat : kDetectorWhat;
  const PairList* a_pairs = in.pairs;
  for (std::size_t k = 0; k < in.pairs->size(); ++k) {
    if (fault_of((*in.pairs)[k], k > 0 ? &(*in.pairs)[k - 1] : nullptr) == 0) continue;
    a_valid_.clear();
    for (const Pair& p : *in.pairs) {
      if (const int fault = fault_of(p, a_valid_.empty() ? nullptr : &a_valid_.back()); fault != 0) {
        report(Invariant::AEqualsR, p, what_of[fault]);
        continue;
      }
      a_valid_.push_back(p);
    }
    a_pairs = &a_valid_;
    break;
  }
  const PairList& a = *a_pairs;
  out.counts.a = static_cast<std::int64_t>(a.size());
  invariant_ms(Invariant::AEqualsR) += lap(t);

  // A == R.
  out.reference = reference_for(n, in.algorithm, e.box.any());
  r_ = reference_of(out.reference);
  const PairList& r = frame_references_[r_].pairs;
  ms.r_ms += lap(t);
  out.counts.r = static_cast<std::int64_t>(r.size());
  const char* missing = in.recorded ? "in contact (in R) but missing from the recorded pairs" : "missing from A (in R)";
  const char* extra = in.recorded ? "in the recorded pairs but not in contact (not in R)" : "extra in A (not in R)";
  // Recorded pairs come from a file: a pair decided only by digits the file did not print, or an
  // exact tie the other convention decides the other way, is at the boundary, not a violation.
  const auto at_boundary = [&](const Pair& p, bool in_r) {
    if (in.precision < 0) return false;
    const std::optional<BoundaryPair> b = boundary_pair(e, p.i, p.j, in.precision, in_r);
    if (!b) return false;
    ++(b->tie ? out.counts.ties : out.counts.boundary);
    if (out.boundary.size() < kMaxListedBoundaryPerFrame) out.boundary.push_back(*b);
    return true;
  };
  out.boundary.clear();
  for_each_missing(r, a, [&](const Pair& p) {
    if (!at_boundary(p, true)) report(Invariant::AEqualsR, p, missing);
  });
  for_each_missing(a, r, [&](const Pair& p) {
    if (at_boundary(p, false)) return;
    report(Invariant::AEqualsR, p, extra);
    if (!in.recorded) return;
    // A simulation's listed pair apart: many of them is a neighbour list given as contacts (the hint).
    ++out.counts.apart;
    out.counts.apart_gap_max = std::max(out.counts.apart_gap_max, contact_gap(e, p.i, p.j));
  });
  invariant_ms(Invariant::AEqualsR) += lap(t);

  out.cells_checked = in.grid_cells != nullptr || in.walks != nullptr;
  // cells: the detector's own integerisation equals the grid's, element by element.
  if (in.grid_cells != nullptr) {
    const std::vector<CellIndex>& grid = *in.grid_cells;
    for (ElementId k = 0; k < n; ++k) {
      const CellIndex own = cell_of(k);
      const CellIndex want = static_cast<std::size_t>(k) < grid.size() ? grid[static_cast<std::size_t>(k)] : CellIndex{-1, -1};
      if (own.ix == want.ix && own.iy == want.iy) continue;  // a plugin's own cells are (ix, iy) (its ABI), also in 3D
      ++out.broken[static_cast<std::size_t>(Invariant::Cells)];
      if (out.violations.size() < kMaxListedViolationsPerFrame)
        out.violations.push_back({frame, Invariant::Cells, Pair{k, k}, own, want, "on the list of another cell (the detector's cell, not the grid's)"});
    }
  }
  // cells: the lists the detector walked hold only their cell's elements.
  if (in.walks != nullptr) {
    out.broken[static_cast<std::size_t>(Invariant::Cells)] += in.walks->count;
    for (const StrayTest& s : in.walks->first) {
      if (out.violations.size() >= kMaxListedViolationsPerFrame) break;
      out.violations.push_back({frame, Invariant::Cells, Pair{s.stray, s.finder}, s.list_cell, s.finder_cell,
                                "tested from the list of a cell it does not lie in (a stale list)"});
    }
  }
  invariant_ms(Invariant::Cells) += lap(t);

  // contract: the frame's first broken contract (found by the pipeline in its trace), one violation.
  out.contract_checked = in.contract_checked;
  out.contract.clear();
  if (in.contract != nullptr) {
    const BrokenContract& c = *in.contract;
    const bool named = c.subject.i >= 0 && c.subject.j >= 0 && c.subject.i < n && c.subject.j < n;
    const Pair p = named ? c.subject : Pair{0, 0};
    ++out.broken[static_cast<std::size_t>(Invariant::Contract)];
    out.contract = std::string(contract_name(c.contract)) + ": " + c.text;
    if (n > 0 && out.violations.size() < kMaxListedViolationsPerFrame)
      out.violations.push_back({frame, Invariant::Contract, p, cell_of(p.i), cell_of(p.j), "breaks the detector's contract (the frame's first broken one)"});
  }

  if (world_ == nullptr) return;  // recorded frames: the rest needs Box2D's world
  const Box2dFrame& world = *world_;

  // A ⊆ F, on the pairs Box2D would consider.
  Box2dScope why;
  world.in_box2d_scope(a, scope_, why);
  out.counts.f = static_cast<std::int64_t>(f_.size());
  out.counts.a_in_scope = static_cast<std::int64_t>(scope_.size());
  out.counts.same_body = static_cast<std::int64_t>(why.same_body);
  out.counts.no_dynamic = static_cast<std::int64_t>(why.no_dynamic);
  out.counts.joint = static_cast<std::int64_t>(why.joint);
  out.counts.fixture_filter = static_cast<std::int64_t>(why.fixture_filter);
  out.counts.beyond_aabb = static_cast<std::int64_t>(why.beyond_aabb);
  const PairList* f = &f_;
  if (in.drop_box2d_contact && !scope_.empty()) {
    f_faulty_ = f_;
    const Pair lost = scope_[scope_.size() / 2];
    if (const auto it = std::lower_bound(f_faulty_.begin(), f_faulty_.end(), lost); it != f_faulty_.end() && *it == lost)
      f_faulty_.erase(it);
    f = &f_faulty_;
  }
  if (out.box2d_stepped)
    for_each_missing(scope_, *f, [&](const Pair& p) { report(Invariant::AInF, p, "not in Box2D's contact list"); });
  invariant_ms(Invariant::AInF) += lap(t);

  // T ⊆ A.
  out.counts.g = static_cast<std::int64_t>(g_.size());
  out.counts.t = static_cast<std::int64_t>(t_.size());
  for_each_missing(t_, a, [&](const Pair& p) { report(Invariant::TInA, p, "shapes touch but the pair is not in A"); });
  invariant_ms(Invariant::TInA) += lap(t);

  // Tight-AABB pairs ⊆ cell-neighbour candidates.
  for (const Pair& p : g_) {
    const CellIndex ci = cell_of(p.i), cj = cell_of(p.j);
    if (std::abs(ci.ix - cj.ix) <= 1 && std::abs(ci.iy - cj.iy) <= 1) continue;
    // Only pairs whose elements' exact boxes overlap must be neighbours; Box2D's float AABBs may
    // touch where the double ones are a rounding error apart.
    const double reach = e.r[p.i] + e.r[p.j];
    if (std::abs(e.x[p.i] - e.x[p.j]) <= reach && std::abs(e.y[p.i] - e.y[p.j]) <= reach) {
      report(Invariant::AabbInCells, p, "tight AABBs overlap but the cells are not neighbours");
    } else {
      ++out.counts.aabb_float_rounding;
    }
  }
  invariant_ms(Invariant::AabbInCells) += lap(t);
}

}  // namespace nbscope

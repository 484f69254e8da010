// nbscope check: the cross-check's results, per frame and per run, as plain structs: the check
// fills them, the frame loop keeps the current frame's, the GUI draws them and io/report_json
// writes a headless run's as JSON. Plain data (no Box2D), so io may include it.
//
// Index: Invariant | Violation | FrameCounts, FrameTimings, CheckTimings, FrameReport | FrameSummary |
// TimingStats, AlgorithmRun, RunReport.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "check/units.hpp"
#include "core/cells.hpp"
#include "core/pairs.hpp"

namespace nbscope {

// The five per-frame invariants of docs/architecture.md "Invariants".
enum class Invariant : std::uint8_t {
  AEqualsR,     // "A==R": the algorithm's pairs equal the reference's
  AInF,         // "A-in-F": the pairs of A in Box2D's scope are all in Box2D's contact list
  TInA,         // "T-in-A": every pair of shapes touching now is in A
  AabbInCells,  // "AABB-in-cells": every tight-AABB pair lies in neighbouring cells of the detector's grid
  Cells,        // "cells": a detector's own integerisation (a plugin's) gives every element the grid's cell
  Contract,     // "contract": the detector keeps its algorithm's contracts and the plugin API's rules (docs/diagnosis.md)
};
inline constexpr int kInvariantCount = 6;
// Short name used in reports, summaries and test expectations ("A==R", "A-in-F", "T-in-A", "AABB-in-cells", "cells", "contract").
const char* invariant_name(Invariant invariant);

// One sentence saying what the invariant checks.
const char* invariant_description(Invariant invariant);


// One broken invariant for one pair in one frame. A `cells` violation names one element k as the
// pair (k, k), cell_i the detector's cell of k and cell_j the grid's; or, for a stray on a walked
// list, the pair (stray, finder), cell_i the cell whose list held the stray (where the detector had
// it) and cell_j the finder's.
struct Violation {
  std::int64_t frame = 0;
  Invariant invariant = Invariant::AEqualsR;
  Pair pair;
  CellIndex cell_i, cell_j;  // cells of pair.i and pair.j (cells: the detector's, then the grid's)
  const char* what = "";     // static text: "missing from A", "extra in A", "not in Box2D's contact list", ...
  // The atom ids of pair.i and pair.j when the frame names its elements by them (a dump's), else -1:
  // the violation names its atoms after the frame is gone (the run's log, reports).
  std::int64_t atom_i = -1, atom_j = -1;
  // The MPI ranks whose files held pair.i and pair.j (a run's per-rank dumps), else -1.
  std::int32_t rank_i = -1, rank_j = -1;
  // |c_i - c_j| - (r_i + r_j) of the pair, minimum image on periodic axes (negative: they overlap);
  // NaN when the pair is no two elements of the frame (a `cells` violation, a pair out of range).
  double gap = std::numeric_limits<double>::quiet_NaN();
};
// "distance - radii = -0.00189614 (in contact)" for a pair's gap: verify's wrong pairs and every
// violation say it in these words.
std::string gap_text(double gap);

// What a run calls its frames: a scene's and a recording's frames are numbered frames, a dump's
// numbers are the simulation's timesteps (issue 39). Recording::frame_unit says it for recorded frames.
enum class FrameUnit : std::uint8_t { frame, timestep };
// "frame 12" or "timestep 20000": how every message, report line and panel names frame `number`.
std::string frame_label(FrameUnit unit, std::int64_t number);
// "frame" or "timestep".
const char* frame_unit_name(FrameUnit unit);
// "x,y" for the periodic axes of `periodic` (x, y, z), "none" for none.
std::string periodic_text(const std::array<bool, 3>& periodic);

// A pair on which A and R disagree only at the contact boundary: the recorded pairs came from a file,
// and the gap |c_i - c_j| - (r_i + r_j) is within what its printed digits resolve, or exactly 0 (a tie
// the two touching conventions decide differently). Listed and counted, never a violation.
struct BoundaryPair {
  Pair pair;
  double gap = 0;         // |c_i - c_j| - (r_i + r_j), minimum image on periodic axes
  double resolution = 0;  // what the data resolves (FrameInput::precision); 0 for an exact tie
  bool tie = false;       // gap exactly 0: in contact under --touching inclusive, not under strict
  bool in_r = false;      // R has it (the recorded pairs do not), else the reverse
};
// "hint: 3126 of the 3660 listed pairs do not touch (gaps up to 0.3): a neighbour list rather than
// contacts? ..." when many of a simulation's `listed` pairs are `apart` (at least 10, and 5 % of
// them: a code's neighbour list dumped as its contacts; a bug's few extra pairs stay below), else "".
[[nodiscard]] std::string apart_pairs_hint(std::int64_t apart, std::int64_t listed, double gap_max);

// Most boundary pairs listed per frame; the count stays exact beyond it.
inline constexpr std::size_t kMaxListedBoundaryPerFrame = 200;
// "at the boundary, within the data's precision (gap -3.1e-08, resolution 8.7e-08)" or
// "an exact tie (gap 0): a contact under --touching inclusive, not under strict"; with `units`
// (a run in its own units), the lengths carry their unit ("gap -3.1e-08 sigma").
std::string boundary_text(const BoundaryPair& b, const Units* units = nullptr);

// Sizes of the frame's sets (see docs/architecture.md "Invariants").
struct FrameCounts {
  std::int64_t elements = 0;
  std::int64_t bodies = 0;
  std::int64_t a = 0;           // the algorithm's pairs
  std::int64_t r = 0;           // the reference's pairs
  std::int64_t f = 0;           // Box2D's contact list
  std::int64_t t = 0;           // shapes touching now
  std::int64_t g = 0;           // tight-AABB pairs
  std::int64_t a_in_scope = 0;  // pairs of A that A-in-F applies to
  // Pairs of A left out of A-in-F, by reason (Box2D's filters, then shapes' AABBs apart).
  std::int64_t same_body = 0, no_dynamic = 0, joint = 0, fixture_filter = 0, beyond_aabb = 0;
  // Tight-AABB pairs left out of AABB-in-cells: Box2D's float AABBs touch, the elements' exact boxes do not.
  std::int64_t aabb_float_rounding = 0;
  // A==R disagreements of recorded pairs at the boundary (BoundaryPair): within the data's precision, exact ties.
  std::int64_t boundary = 0, ties = 0;
  // Recorded pairs apart (in the list, not in contact, not at the boundary) and their largest gap.
  std::int64_t apart = 0;
  double apart_gap_max = 0;
};

// Wall-clock milliseconds of one frame's three stages.
struct FrameTimings {
  double physics_ms = 0;    // Box2D step(s), emitters, elements and AABBs at the new transforms
  double detection_ms = 0;  // the chosen algorithm (and any injected fault)
  double check_ms = 0;      // reference detection, Box2D's sets, the six invariants
};

// Where one frame's check time (FrameTimings::check_ms) went, in milliseconds: the sets, then each
// invariant. The sets every algorithm of a frame shares (F, G and T; R when two algorithms have the
// same reference) count for the first algorithm checked, as check_ms does.
struct CheckTimings {
  double r_ms = 0;    // the reference detector's pairs R, sorted
  double f_ms = 0;    // Box2D's contact list F, sorted
  double g_t_ms = 0;  // the tight-AABB pairs G and the touching pairs T
  std::array<double, kInvariantCount> invariant_ms{};  // each invariant's own work, indexed by Invariant

  // The parts' names as reports show them, and their values, in one order: R, F, G/T, then the invariants.
  static constexpr int kParts = 3 + kInvariantCount;
  [[nodiscard]] static const char* part_name(int k) {
    constexpr const char* sets[] = {"R", "F", "G/T"};
    return k < 3 ? sets[k] : invariant_name(static_cast<Invariant>(k - 3));
  }
  [[nodiscard]] double part(int k) const {
    const double sets[] = {r_ms, f_ms, g_t_ms};
    return k < 3 ? sets[k] : invariant_ms[static_cast<std::size_t>(k - 3)];
  }
};

// Most violations listed per frame; counts stay exact beyond it.
inline constexpr std::size_t kMaxListedViolationsPerFrame = 200;

// Everything the cross-check found in one frame.
struct FrameReport {
  std::int64_t frame = 0;
  std::uint64_t hash = 0;        // hash_elements() of the frame's elements (core/elements.hpp)
  int dim = 2;                   // of the frame's elements: in 3D a violation's cells have their iz
  bool checked = false;          // the invariants ran (off in the GUI when the user turns checks off)
  bool box2d_stepped = false;    // A-in-F needs Box2D's contact list, which exists only after a step
  bool box2d_checks = true;      // A-in-F, T-in-A, AABB-in-cells ran: false for recorded frames (no Box2D world)
  bool cells_checked = false;    // `cells` applied: the detector's own cells or walked lists (a plugin's)
  bool contract_checked = false; // `contract` applied: the frame was traced, or the detector misbehaved
  std::string contract;          // the frame's first broken contract, "name: what broke" ("" when none)
  std::string reference;         // detector that computed R ("brute", "nbs", "box2d")
  FrameCounts counts;
  FrameTimings timings;
  CheckTimings check_timings;                          // check_ms by part (zero when not checked)
  std::array<std::int64_t, kInvariantCount> broken{};  // violations per invariant (exact)
  std::vector<Violation> violations;                   // the first kMaxListedViolationsPerFrame
  std::vector<BoundaryPair> boundary;                  // the first kMaxListedBoundaryPerFrame (counts.boundary + ties: all)

  // Total violations of the frame.
  [[nodiscard]] std::int64_t violation_count() const {
    std::int64_t n = 0;
    for (const std::int64_t b : broken) n += b;
    return n;
  }
  // True when checked and nothing broke.
  [[nodiscard]] bool ok() const { return checked && violation_count() == 0; }
};

// Gives each violation of `report` the atom ids of its pair from `ids` (the frame's, by row; null:
// rows name the elements) and their ranks from `ranks` (per-rank dumps; null: none).
void name_atoms(FrameReport& report, const std::vector<std::int64_t>* ids, const std::vector<std::int32_t>* ranks = nullptr);

// Violation `v`'s two elements as every text names them: "4 of rank 1, 22 of rank 0" when its atoms
// were in two ranks' files, else "4, 22" (atom ids, or rows numbered from `first`: 0, or 1 as the book).
std::string violation_pair_text(const Violation& v, int first = 0);

// What the timeline shows of one frame of a run: kept for every frame, whether or not the frame
// itself can still be shown (the history keeps frames within a memory budget, check/history.hpp).
struct FrameSummary {
  std::int64_t frame = 0;
  double time = 0;
  std::uint64_t hash = 0;        // hash_elements() of the frame's elements
  bool kept = false;             // the frame can be shown again (re-detected, re-checked, resumed from)
  bool checked = false;          // detected and checked (a recorded frame not visited yet: false)
  std::int64_t elements = 0;
  std::int64_t pairs = 0;        // |A| of the algorithm shown
  std::int64_t violations = 0;   // all invariants together
  float physics_ms = 0, detection_ms = 0, check_ms = 0;
};

// Mean, max and total of one timing over a run's frames, kept as the frames come.
struct TimingStats {
  double total = 0, max = 0;
  void add(double ms) {
    total += ms;
    if (ms > max) max = ms;
  }
  // The mean over `frames` frames (0 for none).
  [[nodiscard]] double mean(std::int64_t frames) const { return frames > 0 ? total / static_cast<double>(frames) : 0; }
};

// Where a run's first listed violation was decided in its frame's traced detection (check/diagnosis.hpp).
struct LocatedViolation {
  std::int64_t frame = 0;
  std::optional<std::int64_t> operation;  // 1-based, as the Stepper counts; none when the trace says nothing of the pair
  std::int64_t operations = 0;            // the trace's length
  std::string kind;                       // the operation's kind: "test-pair", "push", "visit-cell", ...
  std::string contract;                   // the frame's first broken contract ("row-processed", ...), "" when all held
  int line = -1;                          // its pseudocode line, from 1 (-1: none)
  std::string pseudocode;                 // that line's text
  std::string text;                       // "operation 81 of 14929: ...", as the window's Violations panel says it
};

// One algorithm's frames in a headless run, aggregated as they come. It holds nothing per frame, so
// a run of any length takes the same memory; each frame's own report is streamed to --report as it
// is made (io/report_json.hpp).
struct AlgorithmRun {
  // An algorithm's run before its first frame.
  explicit AlgorithmRun(std::string name = {}) : algorithm(std::move(name)) {}

  std::string algorithm;
  std::int64_t frames_run = 0;
  bool all_held = true;  // every frame so far was checked and held
  std::array<std::int64_t, kInvariantCount> broken{};  // violations per invariant, over the frames
  std::int64_t violations = 0;              // all of them
  std::int64_t listed = 0;                  // those the frames list (at most kMaxListedViolationsPerFrame each)
  std::int64_t frames_with_violations = 0;
  std::optional<std::int64_t> first_violation_frame;
  std::optional<Violation> first_listed;    // the first violation a frame lists
  std::optional<LocatedViolation> located;  // where first_listed was decided (the loop's own algorithm, traced)
  std::map<std::string, std::int64_t> references;  // frames per reference detector's name
  std::int64_t last_elements = 0;           // elements of the last frame
  std::int64_t boundary = 0, ties = 0;      // recorded pairs at the boundary (FrameCounts::boundary, ties), over the frames
  std::int64_t pairs = 0;                   // |A| over the frames (a recorded lane: the pairs listed)
  std::int64_t apart = 0;                   // recorded pairs apart (FrameCounts::apart), over the frames
  double apart_gap_max = 0;                 // and their largest gap
  TimingStats physics, detection, check;    // FrameTimings, by stage
  std::array<TimingStats, CheckTimings::kParts> check_parts;  // CheckTimings, by part

  // Adds one frame's results.
  void add(const FrameReport& f) {
    ++frames_run;
    all_held = all_held && f.ok();
    const std::int64_t n = f.violation_count();
    for (std::size_t k = 0; k < broken.size(); ++k) broken[k] += f.broken[k];
    violations += n;
    listed += static_cast<std::int64_t>(f.violations.size());
    if (n > 0 && frames_with_violations++ == 0) first_violation_frame = f.frame;
    if (!first_listed && !f.violations.empty()) first_listed = f.violations.front();
    ++references[f.reference];
    last_elements = f.counts.elements;
    boundary += f.counts.boundary;
    ties += f.counts.ties;
    pairs += f.counts.a;
    apart += f.counts.apart;
    apart_gap_max = std::max(apart_gap_max, f.counts.apart_gap_max);
    physics.add(f.timings.physics_ms);
    detection.add(f.timings.detection_ms);
    check.add(f.timings.check_ms);
    for (int k = 0; k < CheckTimings::kParts; ++k) check_parts[static_cast<std::size_t>(k)].add(f.check_timings.part(k));
  }
  // True when every frame was checked and held.
  [[nodiscard]] bool passed() const { return all_held; }
};

// A headless run (one or more algorithms on the same frames), for the JSON report.
struct RunReport {
  std::string scene_path;
  std::string scene_name;
  std::string fault;                 // "none" or the injected fault's name
  std::string fault_description;
  std::string reference_policy;      // how R was chosen, in words
  std::string scope_note;            // which pairs A-in-F applies to, in words (Box2D's filters)
  std::string note;                  // anything else the reader should know ("" for nothing)
  std::string touching = "inclusive";  // the contact convention (--touching): "inclusive" or "strict"
  Units units;                       // the run's units (LAMMPS's: --units, a data file's, a log's; else m and s)
  std::string source = "scene";      // where the frames came from: "scene" (Box2D), "recording" (.nbsrec), "dump" (LAMMPS/LIGGGHTS)
                                     // or "watch" (a LAMMPS/LIGGGHTS run's dumps while it writes them)
  FrameUnit frame_unit = FrameUnit::frame;  // what the frames' numbers are: a dump's are timesteps
  std::array<bool, 3> periodic{};    // the axes periodic in any frame run (x, y, z)
  std::int64_t frames_requested = 0;
  std::vector<AlgorithmRun> runs;
  // headless --rewind FROM:TO: the run went back from frame FROM to TO and simulated the frames
  // after TO again; `diverged_at` is the first of them whose elements differed from the first pass.
  struct Rewind {
    std::int64_t from = 0, to = 0;
    std::optional<std::int64_t> diverged_at;
  };
  std::optional<Rewind> rewind;
  // headless --stop-at-violation: the frame the run stopped on (nullopt: no violation, every frame ran).
  std::optional<std::int64_t> stopped_at;

  // False for a dump's frames, which never had a Box2D world: their reports leave out Box2D's sets
  // (F, G, T), their invariants and the physics time. A recording of a scene keeps them (its
  // report says what it could not check again).
  [[nodiscard]] bool box2d_fields() const { return source != "dump" && source != "watch"; }

  // True when every run ran every requested frame and passed.
  [[nodiscard]] bool passed() const {
    if (rewind && rewind->diverged_at) return false;
    for (const AlgorithmRun& r : runs)
      if (!r.passed() || r.frames_run != frames_requested) return false;
    return !runs.empty();
  }
};

// The invariants that need Box2D's world (A-in-F, T-in-A, AABB-in-cells), and why recorded frames skip them.
[[nodiscard]] inline bool needs_box2d(Invariant invariant) {
  return invariant != Invariant::AEqualsR && invariant != Invariant::Cells && invariant != Invariant::Contract;
}
// True when part `k` of CheckTimings (R, F, G/T, then the invariants) is work on Box2D's sets: none
// of it runs on recorded frames, so their reports leave it out.
[[nodiscard]] inline bool check_part_needs_box2d(int k) {
  return k == 1 || k == 2 || (k >= 3 && needs_box2d(static_cast<Invariant>(k - 3)));
}
inline constexpr const char* kNoBox2dReason =
    "recorded frames have no Box2D world: A-in-F, T-in-A and AABB-in-cells are not available (not passed: not checked)";

}  // namespace nbscope

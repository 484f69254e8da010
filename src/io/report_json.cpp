// The headless report. Keys:
//   nbscope_report (format version 1), source ("scene" | "recording" | "dump" | "watch"), scene {path, name} (a recording's
//   path and file stem), not_checked {invariants [names], why} (recordings: the Box2D invariants), algorithms [names], fault {name, description},
//   reference_policy, a_in_f_scope, note, touching ("inclusive" | "strict"), frame_unit ("frame" | "timestep": what the
//   frame numbers are), periodic [axes: "x", "y", "z"], invariants [{name, description}], frames_requested,
//   rewind (null | {from, to, frames_simulated_again, identical, first_difference}),
//   stopped_at_violation (null | frame), passed,
//   violations_total, runs [one per algorithm:
//     {algorithm, passed, frames_run, violations {total, by_invariant, frames_with_violations, first_frame,
//      listed, located (null | {frame, operation, operations, kind, contract, line, pseudocode, text})}, references_used {name: frames}, timing_ms {physics|detection|check: {mean, max, total}},
//      check_ms_parts {R|F|G/T|A==R|A-in-F|T-in-A|AABB-in-cells: {mean, max, total}} (check split by part),
//      frames [{frame, hash (16 hex digits: hash_elements of the frame's elements), elements, bodies, reference, pairs {A, R, F, T, G, A_in_scope},
//               left_out_of_A_in_F {same_body, no_dynamic, joint, fixture_filter, beyond_aabb},
//               aabb_float_rounding, ms {physics, detection, check},
//               check_ms_parts {R, F, G/T, A==R, A-in-F, T-in-A, AABB-in-cells, cells, contract},
//               held {invariant: true | false | null (not checked)}, contract (null | "name: the frame's first broken contract"),
//               violations [{invariant, pair [i, j], cells [[ix, iy], [ix, iy]], what, gap (|c_i - c_j| - (r_i + r_j),
//               minimum image; null for no pair of two elements)}],
//               violations_not_listed, at_boundary {within_precision, exact_ties, listed [{pair, gap, resolution,
//               tie, in ("R": not recorded, "A": recorded, not in R), what, ids}]}}]}]; with a dump's frames each
//               violation and boundary pair also has ids [id_i, id_j] (the atoms'). A dump's report (no Box2D world:
//               RunReport::box2d_fields) leaves out a_in_f_scope, the invariants that need Box2D (from invariants,
//               by_invariant and held), the check parts F and G/T, the physics times, and each frame's bodies,
//               pairs F, T, G, A_in_scope, left_out_of_A_in_F and aabb_float_rounding.
#include "io/report_json.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>

#include "io/atomic_file.hpp"
#include "io/recording.hpp"

namespace nbscope {

namespace {

using nlohmann::json;

// The check's time by part (CheckTimings), one key per part (without `box2d`, those of Box2D's sets left out).
json check_parts_json(const CheckTimings& t, bool box2d) {
  json parts = json::object();
  for (int k = 0; k < CheckTimings::kParts; ++k)
    if (box2d || !check_part_needs_box2d(k)) parts[CheckTimings::part_name(k)] = t.part(k);
  return parts;
}

// `box2d`: the frame's run has Box2D's fields (RunReport::box2d_fields); without, they are left out.
json frame_json(const FrameReport& f, const std::vector<std::int64_t>* ids, bool box2d) {
  const FrameCounts& c = f.counts;
  json held = json::object();
  for (int k = 0; k < kInvariantCount; ++k) {
    const auto inv = static_cast<Invariant>(k);
    if (!box2d && needs_box2d(inv)) continue;
    const bool ran = f.checked && (!needs_box2d(inv) || f.box2d_checks) && (inv != Invariant::AInF || f.box2d_stepped) &&
                     (inv != Invariant::Contract || f.contract_checked);
    held[invariant_name(inv)] = ran ? json(f.broken[static_cast<std::size_t>(k)] == 0) : json(nullptr);
  }
  json violations = json::array();
  for (const Violation& v : f.violations) {
    violations.push_back({{"invariant", invariant_name(v.invariant)},
                          {"pair", {v.pair.i, v.pair.j}},
                          {"cells", f.dim == 3 ? json{{v.cell_i.ix, v.cell_i.iy, v.cell_i.iz}, {v.cell_j.ix, v.cell_j.iy, v.cell_j.iz}}
                                               : json{{v.cell_i.ix, v.cell_i.iy}, {v.cell_j.ix, v.cell_j.iy}}},
                          {"what", v.what},
                          {"gap", std::isfinite(v.gap) ? json(v.gap) : json(nullptr)}});
    if (ids != nullptr) violations.back()["ids"] = {element_id(ids, v.pair.i), element_id(ids, v.pair.j)};
  }
  json boundary = json::array();
  for (const BoundaryPair& b : f.boundary) {
    boundary.push_back({{"pair", {b.pair.i, b.pair.j}}, {"gap", b.gap}, {"resolution", b.resolution}, {"tie", b.tie},
                        {"in", b.in_r ? "R" : "A"}, {"what", boundary_text(b)}});
    if (ids != nullptr) boundary.back()["ids"] = {element_id(ids, b.pair.i), element_id(ids, b.pair.j)};
  }
  char hash[24];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(f.hash));
  json out = {{"frame", f.frame},
              {"hash", hash},
              {"elements", c.elements},
              {"reference", f.reference},
              {"pairs", {{"A", c.a}, {"R", c.r}}},
              {"ms", {{"detection", f.timings.detection_ms}, {"check", f.timings.check_ms}}},
              {"check_ms_parts", check_parts_json(f.check_timings, box2d)},
              {"held", held},
              {"contract", f.contract.empty() ? json(nullptr) : json(f.contract)},
              {"violations", violations},
              {"violations_not_listed", f.violation_count() - static_cast<std::int64_t>(f.violations.size())},
              {"at_boundary", {{"within_precision", c.boundary}, {"exact_ties", c.ties}, {"listed", boundary}}}};
  if (!box2d) return out;
  out["bodies"] = c.bodies;
  out["pairs"].update({{"F", c.f}, {"T", c.t}, {"G", c.g}, {"A_in_scope", c.a_in_scope}});
  out["left_out_of_A_in_F"] = {{"same_body", c.same_body},
                               {"no_dynamic", c.no_dynamic},
                               {"joint", c.joint},
                               {"fixture_filter", c.fixture_filter},
                               {"beyond_aabb", c.beyond_aabb}};
  out["aabb_float_rounding"] = c.aabb_float_rounding;
  out["ms"]["physics"] = f.timings.physics_ms;
  return out;
}

json timing_json(const TimingStats& t, std::int64_t frames) {
  return {{"mean", t.mean(frames)}, {"max", t.max}, {"total", t.total}};
}

// Mean, max and total over the frames of each part of the check.
json check_parts_timing_json(const AlgorithmRun& run, bool box2d) {
  json parts = json::object();
  for (int k = 0; k < CheckTimings::kParts; ++k)
    if (box2d || !check_part_needs_box2d(k)) parts[CheckTimings::part_name(k)] = timing_json(run.check_parts[static_cast<std::size_t>(k)], run.frames_run);
  return parts;
}

// The first listed violation's operation, or null when it was not located.
json located_json(const std::optional<LocatedViolation>& l) {
  if (!l) return nullptr;
  return {{"frame", l->frame},
          {"operation", l->operation ? json(*l->operation) : json(nullptr)},
          {"operations", l->operations},
          {"kind", l->kind.empty() ? json(nullptr) : json(l->kind)},
          {"contract", l->contract.empty() ? json(nullptr) : json(l->contract)},
          {"line", l->line > 0 ? json(l->line) : json(nullptr)},
          {"pseudocode", l->pseudocode.empty() ? json(nullptr) : json(l->pseudocode)},
          {"text", l->text}};
}

json run_json(const AlgorithmRun& run, bool box2d) {
  json by_invariant = json::object();
  for (int k = 0; k < kInvariantCount; ++k)
    if (box2d || !needs_box2d(static_cast<Invariant>(k))) by_invariant[invariant_name(static_cast<Invariant>(k))] = run.broken[static_cast<std::size_t>(k)];
  json out = {{"algorithm", run.algorithm},
          {"passed", run.passed()},
          {"frames_run", run.frames_run},
          {"violations",
           {{"total", run.violations},
            {"by_invariant", by_invariant},
            {"frames_with_violations", run.frames_with_violations},
            {"first_frame", run.first_violation_frame ? json(*run.first_violation_frame) : json(nullptr)},
            {"listed", run.listed},
            {"located", located_json(run.located)}}},
          {"references_used", run.references},
          {"timing_ms",
           {{"physics", timing_json(run.physics, run.frames_run)},
            {"detection", timing_json(run.detection, run.frames_run)},
            {"check", timing_json(run.check, run.frames_run)}}},
          {"check_ms_parts", check_parts_timing_json(run, box2d)}};
  if (!box2d) out["timing_ms"].erase("physics");
  return out;
}

// The report up to the first run's frames: every key but "runs", then "runs": [ (no newline after).
std::string head_text(const RunReport& report) {
  json invariants = json::array();
  for (int k = 0; k < kInvariantCount; ++k)
    if (report.box2d_fields() || !needs_box2d(static_cast<Invariant>(k)))
      invariants.push_back({{"name", invariant_name(static_cast<Invariant>(k))},
                          {"description", invariant_description(static_cast<Invariant>(k))}});
  json algorithms = json::array();
  std::int64_t total = 0;
  for (const AlgorithmRun& r : report.runs) {
    algorithms.push_back(r.algorithm);
    total += r.violations;
  }
  json not_checked = json::array();
  if (report.source != "scene")
    for (int k = 0; k < kInvariantCount; ++k)
      if (needs_box2d(static_cast<Invariant>(k))) not_checked.push_back(invariant_name(static_cast<Invariant>(k)));
  json periodic = json::array();
  for (std::size_t a = 0; a < 3; ++a)
    if (report.periodic[a]) periodic.push_back(std::string(1, static_cast<char>('x' + a)));
  json head = {{"nbscope_report", 1},
                     {"source", report.source},
                     {"scene", {{"path", report.scene_path}, {"name", report.scene_name}}},
                     {"not_checked", {{"invariants", not_checked}, {"why", not_checked.empty() ? "" : kNoBox2dReason}}},
                     {"algorithms", algorithms},
                     {"fault", {{"name", report.fault}, {"description", report.fault_description}}},
                     {"reference_policy", report.reference_policy},
                     {"a_in_f_scope", report.scope_note},
                     {"note", report.note},
                     {"touching", report.touching},
                     {"frame_unit", frame_unit_name(report.frame_unit)},
                     {"periodic", periodic},
                     {"units", {{"name", report.units.name.empty() ? json(nullptr) : json(report.units.name)},
                                {"length", report.units.length},
                                {"time", report.units.time}}},
                     {"invariants", invariants},
                     {"frames_requested", report.frames_requested},
                     {"rewind", report.rewind ? json{{"from", report.rewind->from},
                                                     {"to", report.rewind->to},
                                                     {"frames_simulated_again", report.rewind->from - report.rewind->to},
                                                     {"identical", !report.rewind->diverged_at},
                                                     {"first_difference", report.rewind->diverged_at ? json(*report.rewind->diverged_at) : json(nullptr)}}
                                              : json(nullptr)},
                     {"stopped_at_violation", report.stopped_at ? json(*report.stopped_at) : json(nullptr)},
                     {"passed", report.passed()},
                     {"violations_total", total}};
  if (!report.box2d_fields()) head.erase("a_in_f_scope");
  // Each run's summary indented, its frames one line each: a 600-frame report stays readable and greppable.
  std::string out = head.dump(2);
  out.pop_back();  // the closing brace
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  return out + ",\n  \"runs\": [";
}

// Run `r`'s summary, indented, up to its frames: "\n    {...,\n      \"frames\": [".
std::string run_head_text(const AlgorithmRun& run, std::size_t r, bool box2d) {
  std::string text = run_json(run, box2d).dump(2);
  text.pop_back();
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  std::string indented;
  for (const char c : text) indented += c == '\n' ? std::string("\n    ") : std::string(1, c);
  return (r == 0 ? "\n    " : ",\n    ") + indented + ",\n      \"frames\": [";
}

// What follows a run's frames, and the whole report's end.
const char* run_tail_text(bool no_frames) { return no_frames ? "]\n    }" : "\n      ]\n    }"; }
const char* report_tail_text(bool no_runs) { return no_runs ? "]\n}\n" : "\n  ]\n}\n"; }

// One frame's line as it stands in its run's "frames" array, with the separator before it.
std::string frame_line(const FrameReport& f, bool first, bool box2d, const std::vector<std::int64_t>* ids = nullptr) {
  return (first ? "\n        " : ",\n        ") + frame_json(f, ids, box2d).dump();
}

}  // namespace

std::string run_report_json(const RunReport& report, const std::vector<std::vector<FrameReport>>& frames) {
  std::string out = head_text(report);
  for (std::size_t r = 0; r < report.runs.size(); ++r) {
    out += run_head_text(report.runs[r], r, report.box2d_fields());
    const std::size_t n = r < frames.size() ? frames[r].size() : 0;
    for (std::size_t k = 0; k < n; ++k) out += frame_line(frames[r][k], k == 0, report.box2d_fields());
    out += run_tail_text(n == 0);
  }
  return out + report_tail_text(report.runs.empty());
}

// ---- RunReportWriter ----------------------------------------------------------------------

RunReportWriter::RunReportWriter(std::string path, std::size_t runs, bool box2d_fields) : path_(std::move(path)), box2d_(box2d_fields) {
  for (std::size_t r = 0; r < runs; ++r) spools_.push_back(Spool{std::make_unique<ScratchFile>(path_), 0});
}

RunReportWriter::~RunReportWriter() = default;

void RunReportWriter::add_frame(std::size_t run, const FrameReport& frame, const std::vector<std::int64_t>* ids) {
  Spool& spool = spools_.at(run);
  spool.file->write(frame_line(frame, spool.frames == 0, box2d_, ids));
  ++spool.frames;
}

RunReportWriter::Mark RunReportWriter::mark() const {
  Mark m;
  for (const Spool& s : spools_) m.push_back({s.file->size(), s.frames});
  return m;
}

void RunReportWriter::back_to(const Mark& mark) {
  for (std::size_t r = 0; r < spools_.size() && r < mark.size(); ++r) {
    spools_[r].file->truncate(mark[r].bytes);
    spools_[r].frames = mark[r].frames;
  }
}

std::int64_t RunReportWriter::spooled_bytes() {
  std::int64_t n = 0;
  for (Spool& s : spools_) n += s.file->bytes_on_disk();
  return n;
}

void RunReportWriter::commit(const RunReport& report) {
  AtomicFileWriter file(path_);
  std::ostream& out = file.stream();
  out << head_text(report);
  for (std::size_t r = 0; r < report.runs.size(); ++r) {
    out << run_head_text(report.runs[r], r, report.box2d_fields());
    const bool has = r < spools_.size() && spools_[r].frames > 0;
    if (has) spools_[r].file->copy_to(out);
    out << run_tail_text(!has);
  }
  out << report_tail_text(report.runs.empty());
  file.commit();
}

}  // namespace nbscope

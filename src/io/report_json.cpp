// The headless report. Keys:
//   nbscope_report (format version 1), source ("scene" | "recording" | "dump"), scene {path, name} (a recording's
//   path and file stem), not_checked {invariants [names], why} (recordings: the Box2D invariants), algorithms [names], fault {name, description},
//   reference_policy, a_in_f_scope, note, invariants [{name, description}], frames_requested,
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
//               violations [{invariant, pair [i, j], cells [[ix, iy], [ix, iy]], what}],
//               violations_not_listed, at_boundary {within_precision, exact_ties, listed [{pair, gap, resolution,
//               tie, in ("R": not recorded, "A": recorded, not in R), what, ids}]}}]}]; with a dump's frames each
//               violation and boundary pair also has ids [id_i, id_j] (the atoms'). touching ("inclusive" | "strict").
#include "io/report_json.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>

#include "io/atomic_file.hpp"
#include "io/recording.hpp"

namespace nbscope {

namespace {

using nlohmann::json;

// The check's time by part (CheckTimings), one key per part.
json check_parts_json(const CheckTimings& t) {
  json parts = json::object();
  for (int k = 0; k < CheckTimings::kParts; ++k) parts[CheckTimings::part_name(k)] = t.part(k);
  return parts;
}

json frame_json(const FrameReport& f, const std::vector<std::int64_t>* ids) {
  const FrameCounts& c = f.counts;
  json held = json::object();
  for (int k = 0; k < kInvariantCount; ++k) {
    const auto inv = static_cast<Invariant>(k);
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
                          {"what", v.what}});
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
  return {{"frame", f.frame},
          {"hash", hash},
          {"elements", c.elements},
          {"bodies", c.bodies},
          {"reference", f.reference},
          {"pairs", {{"A", c.a}, {"R", c.r}, {"F", c.f}, {"T", c.t}, {"G", c.g}, {"A_in_scope", c.a_in_scope}}},
          {"left_out_of_A_in_F",
           {{"same_body", c.same_body},
            {"no_dynamic", c.no_dynamic},
            {"joint", c.joint},
            {"fixture_filter", c.fixture_filter},
            {"beyond_aabb", c.beyond_aabb}}},
          {"aabb_float_rounding", c.aabb_float_rounding},
          {"ms", {{"physics", f.timings.physics_ms}, {"detection", f.timings.detection_ms}, {"check", f.timings.check_ms}}},
          {"check_ms_parts", check_parts_json(f.check_timings)},
          {"held", held},
          {"contract", f.contract.empty() ? json(nullptr) : json(f.contract)},
          {"violations", violations},
          {"violations_not_listed", f.violation_count() - static_cast<std::int64_t>(f.violations.size())},
          {"at_boundary", {{"within_precision", c.boundary}, {"exact_ties", c.ties}, {"listed", boundary}}}};
}

json timing_json(const TimingStats& t, std::int64_t frames) {
  return {{"mean", t.mean(frames)}, {"max", t.max}, {"total", t.total}};
}

// Mean, max and total over the frames of each part of the check.
json check_parts_timing_json(const AlgorithmRun& run) {
  json parts = json::object();
  for (int k = 0; k < CheckTimings::kParts; ++k)
    parts[CheckTimings::part_name(k)] = timing_json(run.check_parts[static_cast<std::size_t>(k)], run.frames_run);
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

json run_json(const AlgorithmRun& run) {
  json by_invariant = json::object();
  for (int k = 0; k < kInvariantCount; ++k) by_invariant[invariant_name(static_cast<Invariant>(k))] = run.broken[static_cast<std::size_t>(k)];
  return {{"algorithm", run.algorithm},
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
          {"check_ms_parts", check_parts_timing_json(run)}};
}

// The report up to the first run's frames: every key but "runs", then "runs": [ (no newline after).
std::string head_text(const RunReport& report) {
  json invariants = json::array();
  for (int k = 0; k < kInvariantCount; ++k)
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
  const json head = {{"nbscope_report", 1},
                     {"source", report.source},
                     {"scene", {{"path", report.scene_path}, {"name", report.scene_name}}},
                     {"not_checked", {{"invariants", not_checked}, {"why", not_checked.empty() ? "" : kNoBox2dReason}}},
                     {"algorithms", algorithms},
                     {"fault", {{"name", report.fault}, {"description", report.fault_description}}},
                     {"reference_policy", report.reference_policy},
                     {"a_in_f_scope", report.scope_note},
                     {"note", report.note},
                     {"touching", report.touching},
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
  // Each run's summary indented, its frames one line each: a 600-frame report stays readable and greppable.
  std::string out = head.dump(2);
  out.pop_back();  // the closing brace
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  return out + ",\n  \"runs\": [";
}

// Run `r`'s summary, indented, up to its frames: "\n    {...,\n      \"frames\": [".
std::string run_head_text(const AlgorithmRun& run, std::size_t r) {
  std::string text = run_json(run).dump(2);
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
std::string frame_line(const FrameReport& f, bool first, const std::vector<std::int64_t>* ids = nullptr) {
  return (first ? "\n        " : ",\n        ") + frame_json(f, ids).dump();
}

}  // namespace

std::string run_report_json(const RunReport& report, const std::vector<std::vector<FrameReport>>& frames) {
  std::string out = head_text(report);
  for (std::size_t r = 0; r < report.runs.size(); ++r) {
    out += run_head_text(report.runs[r], r);
    const std::size_t n = r < frames.size() ? frames[r].size() : 0;
    for (std::size_t k = 0; k < n; ++k) out += frame_line(frames[r][k], k == 0);
    out += run_tail_text(n == 0);
  }
  return out + report_tail_text(report.runs.empty());
}

// ---- RunReportWriter ----------------------------------------------------------------------

RunReportWriter::RunReportWriter(std::string path, std::size_t runs) : path_(std::move(path)) {
  for (std::size_t r = 0; r < runs; ++r) spools_.push_back(Spool{std::make_unique<ScratchFile>(path_), 0});
}

RunReportWriter::~RunReportWriter() = default;

void RunReportWriter::add_frame(std::size_t run, const FrameReport& frame, const std::vector<std::int64_t>* ids) {
  Spool& spool = spools_.at(run);
  spool.file->write(frame_line(frame, spool.frames == 0, ids));
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
    out << run_head_text(report.runs[r], r);
    const bool has = r < spools_.size() && spools_[r].frames > 0;
    if (has) spools_[r].file->copy_to(out);
    out << run_tail_text(!has);
  }
  out << report_tail_text(report.runs.empty());
  file.commit();
}

}  // namespace nbscope

// The headless report. Keys:
//   nbscope_report (format version 1), source ("scene" | "recording"), scene {path, name} (a recording's
//   path and file stem), not_checked {invariants [names], why} (recordings: the Box2D invariants), algorithms [names], fault {name, description},
//   reference_policy, a_in_f_scope, note, invariants [{name, description}], frames_requested,
//   rewind (null | {from, to, frames_simulated_again, identical, first_difference}),
//   stopped_at_violation (null | frame), passed,
//   violations_total, runs [one per algorithm:
//     {algorithm, passed, frames_run, violations {total, by_invariant, frames_with_violations, first_frame,
//      listed}, references_used {name: frames}, timing_ms {physics|detection|check: {mean, max, total}},
//      check_ms_parts {R|F|G/T|A==R|A-in-F|T-in-A|AABB-in-cells: {mean, max, total}} (check split by part),
//      frames [{frame, hash (16 hex digits: hash_elements of the frame's elements), elements, bodies, reference, pairs {A, R, F, T, G, A_in_scope},
//               left_out_of_A_in_F {same_body, no_dynamic, joint, fixture_filter, beyond_aabb},
//               aabb_float_rounding, ms {physics, detection, check},
//               check_ms_parts {R, F, G/T, A==R, A-in-F, T-in-A, AABB-in-cells},
//               held {invariant: true | false | null (not checked)},
//               violations [{invariant, pair [i, j], cells [[ix, iy], [ix, iy]], what}],
//               violations_not_listed}]}].
#include "io/report_json.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>

#include "io/atomic_file.hpp"

namespace nbscope {

namespace {

using nlohmann::json;

// The check's time by part (CheckTimings), one key per part.
json check_parts_json(const CheckTimings& t) {
  json parts = json::object();
  for (int k = 0; k < CheckTimings::kParts; ++k) parts[CheckTimings::part_name(k)] = t.part(k);
  return parts;
}

json frame_json(const FrameReport& f) {
  const FrameCounts& c = f.counts;
  json held = json::object();
  for (int k = 0; k < kInvariantCount; ++k) {
    const auto inv = static_cast<Invariant>(k);
    const bool ran = f.checked && (!needs_box2d(inv) || f.box2d_checks) && (inv != Invariant::AInF || f.box2d_stepped);
    held[invariant_name(inv)] = ran ? json(f.broken[static_cast<std::size_t>(k)] == 0) : json(nullptr);
  }
  json violations = json::array();
  for (const Violation& v : f.violations) {
    violations.push_back({{"invariant", invariant_name(v.invariant)},
                          {"pair", {v.pair.i, v.pair.j}},
                          {"cells", {{v.cell_i.ix, v.cell_i.iy}, {v.cell_j.ix, v.cell_j.iy}}},
                          {"what", v.what}});
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
          {"violations", violations},
          {"violations_not_listed", f.violation_count() - static_cast<std::int64_t>(f.violations.size())}};
}

json timing_json(const std::vector<FrameReport>& frames, double FrameTimings::*field) {
  double total = 0, max = 0;
  for (const FrameReport& f : frames) {
    total += f.timings.*field;
    max = std::max(max, f.timings.*field);
  }
  const double mean = frames.empty() ? 0 : total / static_cast<double>(frames.size());
  return {{"mean", mean}, {"max", max}, {"total", total}};
}

// Mean, max and total over the frames of each part of the check.
json check_parts_timing_json(const std::vector<FrameReport>& frames) {
  json parts = json::object();
  for (int k = 0; k < CheckTimings::kParts; ++k) {
    double total = 0, max = 0;
    for (const FrameReport& f : frames) {
      total += f.check_timings.part(k);
      max = std::max(max, f.check_timings.part(k));
    }
    const double mean = frames.empty() ? 0 : total / static_cast<double>(frames.size());
    parts[CheckTimings::part_name(k)] = {{"mean", mean}, {"max", max}, {"total", total}};
  }
  return parts;
}

json run_json(const AlgorithmRun& run) {
  std::array<std::int64_t, kInvariantCount> by{};
  std::int64_t total = 0, listed = 0, bad_frames = 0;
  json first_frame = nullptr;
  std::map<std::string, std::int64_t> references;
  for (const FrameReport& f : run.frames) {
    for (int k = 0; k < kInvariantCount; ++k) by[static_cast<std::size_t>(k)] += f.broken[static_cast<std::size_t>(k)];
    total += f.violation_count();
    listed += static_cast<std::int64_t>(f.violations.size());
    if (f.violation_count() > 0) {
      ++bad_frames;
      if (first_frame.is_null()) first_frame = f.frame;
    }
    ++references[f.reference];
  }
  json by_invariant = json::object();
  for (int k = 0; k < kInvariantCount; ++k) by_invariant[invariant_name(static_cast<Invariant>(k))] = by[static_cast<std::size_t>(k)];
  return {{"algorithm", run.algorithm},
          {"passed", run.passed()},
          {"frames_run", static_cast<std::int64_t>(run.frames.size())},
          {"violations",
           {{"total", total}, {"by_invariant", by_invariant}, {"frames_with_violations", bad_frames}, {"first_frame", first_frame}, {"listed", listed}}},
          {"references_used", references},
          {"timing_ms",
           {{"physics", timing_json(run.frames, &FrameTimings::physics_ms)},
            {"detection", timing_json(run.frames, &FrameTimings::detection_ms)},
            {"check", timing_json(run.frames, &FrameTimings::check_ms)}}},
          {"check_ms_parts", check_parts_timing_json(run.frames)}};
}

}  // namespace

std::string run_report_json(const RunReport& report) {
  json invariants = json::array();
  for (int k = 0; k < kInvariantCount; ++k)
    invariants.push_back({{"name", invariant_name(static_cast<Invariant>(k))},
                          {"description", invariant_description(static_cast<Invariant>(k))}});
  json algorithms = json::array();
  std::int64_t total = 0;
  for (const AlgorithmRun& r : report.runs) {
    algorithms.push_back(r.algorithm);
    for (const FrameReport& f : r.frames) total += f.violation_count();
  }
  json not_checked = json::array();
  if (report.source == "recording")
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
  out += ",\n  \"runs\": [";
  for (std::size_t r = 0; r < report.runs.size(); ++r) {
    std::string run = run_json(report.runs[r]).dump(2);
    run.pop_back();
    while (!run.empty() && (run.back() == '\n' || run.back() == ' ')) run.pop_back();
    std::string indented;
    for (const char c : run) indented += c == '\n' ? std::string("\n    ") : std::string(1, c);
    out += (r == 0 ? "\n    " : ",\n    ") + indented + ",\n      \"frames\": [";
    const std::vector<FrameReport>& frames = report.runs[r].frames;
    for (std::size_t k = 0; k < frames.size(); ++k) out += (k == 0 ? "\n        " : ",\n        ") + frame_json(frames[k]).dump();
    out += frames.empty() ? "]\n    }" : "\n      ]\n    }";
  }
  out += report.runs.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return out;
}

void write_run_report(const std::string& path, const RunReport& report) {
  const std::string text = run_report_json(report);
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace nbscope

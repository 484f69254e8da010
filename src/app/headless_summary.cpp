// nbscope app: the one line a headless run or a replay prints on stdout (headless.hpp): what ran,
// whether every invariant held, where it broke, the mean timings. A dump's frames are named by their
// timesteps and its line holds only what applies to it (no Box2D world: no F, G, T or their invariants).
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "app/frame_loop.hpp"
#include "app/headless.hpp"
#include "check/report.hpp"
#include "core/detector.hpp"
#include "io/plural.hpp"
#include "io/recording.hpp"

namespace nbscope {

namespace {

// "A==R 30, T-in-A 7" for the invariants `run` broke.
std::string broken_text(const AlgorithmRun& run) {
  std::string s;
  for (int k = 0; k < kInvariantCount; ++k)
    if (run.broken[static_cast<std::size_t>(k)] > 0)
      s += (s.empty() ? "" : ", ") + std::string(invariant_name(static_cast<Invariant>(k))) + " " +
           std::to_string(run.broken[static_cast<std::size_t>(k)]);
  return s;
}

// "A==R (2, 11) given twice in the recorded pairs" for violation `v`; a recording whose pairs count
// from 1 also gets the pair as its file numbers it, a dump's frame names the atoms by their ids (and
// their ranks when two ranks' files held them: "atoms 4 of rank 1, 22 of rank 0"); a pair of two
// elements ends with its gap, as verify gives it.
std::string violation_text(const Violation& v, const LoopSource& source) {
  std::string pair = violation_pair_text(v);
  if (v.atom_i >= 0) {
    pair = "atoms " + pair;
  } else if (const int base = source.carries_pairs() ? source.pair_base() : 0; base != 0) {
    pair += "; the file's " + std::to_string(v.pair.i + base) + "," + std::to_string(v.pair.j + base);
  }
  return std::string(invariant_name(v.invariant)) + " (" + pair + ") " + v.what + (std::isfinite(v.gap) ? "; " + gap_text(v.gap) : "");
}

// ": A==R (2, 11) given twice in the recorded pairs" for the first violation `run` lists.
std::string first_violation_text(const AlgorithmRun& run, const LoopSource& source) {
  if (!run.first_listed) return "";
  return ": " + violation_text(*run.first_listed, source) + (run.located ? "; located: " + run.located->text : "");
}

}  // namespace

FrameUnit frame_unit_of(const LoopSource& source) {
  const Recording* recording = source.recording();
  return recording != nullptr ? recording->frame_unit : FrameUnit::frame;
}

std::string headless_summary(const HeadlessOptions& o, const FrameLoop& loop, const RunReport& report, double back_ms) {
  const LoopSource& source = loop.source();
  const auto label = [&](std::int64_t n) { return frame_label(report.frame_unit, n); };
  // A dump never had a Box2D world: its line leaves out what only Box2D's sets have (a recording
  // of a scene says what it could not check again).
  const bool box2d_fields = report.box2d_fields();
  std::map<std::string, std::int64_t> refs;
  for (const AlgorithmRun& run : report.runs)
    for (const auto& [name, count] : run.references) refs[name] += count;
  std::string refs_text;
  for (const auto& [name, count] : refs) refs_text += (refs_text.empty() ? "" : ", ") + name;
  std::string names;
  for (const AlgorithmRun& run : report.runs) names += (names.empty() ? "" : ",") + detector_label(run.algorithm);
  const std::int64_t frames = report.runs.empty() ? 0 : report.runs.front().frames_run;
  // The run's last frame's, not the frame shown at the end (--back, --violation go elsewhere).
  const std::int64_t elements = frames > 0 ? report.runs.front().last_elements : source.elements().size();
  std::string s = std::string(o.watch ? "watch: " : source.replaying() ? "replay: " : "headless: ") + source.scene().name + ", " + names +
                  (o.fault == Fault::None ? "" : std::string(", fault ") + fault_name(o.fault)) + ", " +
                  plural(static_cast<long long>(frames), "frame") + ", " + plural(elements, "element") + ": ";
  std::string failures;
  for (const AlgorithmRun& run : report.runs) {
    if (run.violations == 0) continue;
    failures += (failures.empty() ? "" : "; ") + (report.runs.size() > 1 ? run.algorithm + ": " : std::string()) +
                plural(run.violations, "violation") + " in " + plural(run.frames_with_violations, "frame") + " (" + broken_text(run) +
                "), first in " + label(run.first_violation_frame.value_or(-1)) + first_violation_text(run, source);
  }
  const std::string every = report.runs.size() > 1 ? " for every algorithm" : "";
  if (failures.empty() && source.replaying()) {
    s += "A==R held in every frame" + every;
  } else if (failures.empty()) {
    s += "all " + std::to_string(kInvariantCount) + " invariants held in every frame" + every;
  } else {
    s += failures;
  }
  s += " (reference " + refs_text + ")";
  // Recorded pairs the data cannot decide: named, counted, not violations.
  for (const AlgorithmRun& run : report.runs) {
    if (run.boundary == 0 && run.ties == 0) continue;
    s += "; " + (report.runs.size() > 1 ? run.algorithm + ": " : std::string());
    if (run.boundary > 0) s += plural(run.boundary, "pair") + " at the boundary, within the data's precision";
    if (run.ties > 0) s += std::string(run.boundary > 0 ? ", " : "") + plural(run.ties, "exact tie") + " (a contact under --touching inclusive, not strict)";
  }
  // A dump's line says how its contacts were decided, always: the axes measured by the minimum
  // image and the convention at zero gap (a scene's says the convention only when it is strict).
  if (!box2d_fields) {
    s += "; periodic: " + periodic_text(report.periodic) + "; touching: " + report.touching +
         (o.touching == Touching::strict ? " (<)" : " (<=)");
  } else if (o.touching == Touching::strict) {
    s += "; touching strict (<)";
  }
  if (!o.view.units.name.empty()) s += "; " + o.view.units.description();
  if (report.stopped_at) {
    const Violation& v = loop.result().report().violations.front();
    s += "; stopped at the first violation, " + label(*report.stopped_at) + ": " + violation_text(v, source);
  } else if (o.stop_at_violation) {
    s += "; no violation to stop at";
  }
  if (report.rewind) {
    const RunReport::Rewind& r = *report.rewind;
    s += "; rewound from frame " + std::to_string(r.from) + " to " + std::to_string(r.to) + " and resumed: " +
         (r.diverged_at ? "the frames simulated again DIFFER from the first run from frame " + std::to_string(*r.diverged_at)
                        : "frames " + std::to_string(r.to + 1) + ".." + std::to_string(r.from) +
                              " simulated again are identical to the first run (element hashes)");
  }
  // Recorded frames of a scene: say plainly what was not checked rather than let it pass silently.
  if (source.replaying() && box2d_fields) s += "; A-in-F, T-in-A, AABB-in-cells not checked (recorded frames have no Box2D world)";
  if (!report.note.empty()) s += " (" + report.note + ")";
  char buf[160];
  std::snprintf(buf, sizeof buf, "; ms per frame: physics %.3f, detection", report.runs.empty() ? 0.0 : report.runs.front().physics.mean(report.runs.front().frames_run));
  s += source.replaying() ? "; ms per frame: detection" : buf;  // recorded frames have no physics
  double check = 0;
  for (const AlgorithmRun& run : report.runs) {
    std::snprintf(buf, sizeof buf, "%s%s %.3f", &run == &report.runs.front() ? " " : ", ", report.runs.size() > 1 ? run.algorithm.c_str() : "",
                  run.detection.mean(run.frames_run));
    s += report.runs.size() > 1 ? buf : buf + 1;  // one algorithm: no name
    check += run.check.mean(run.frames_run);
  }
  std::snprintf(buf, sizeof buf, ", check %.3f", check);
  s += buf;
  // The check by part (CheckTimings), each the sum of the algorithms' means: R, F, G/T, then each
  // invariant (a dump's: those that apply).
  const char* open = " (";
  for (int k = 0; k < CheckTimings::kParts; ++k) {
    if (!box2d_fields && check_part_needs_box2d(k)) continue;
    double ms = 0;
    for (const AlgorithmRun& run : report.runs) ms += run.check_parts[static_cast<std::size_t>(k)].mean(run.frames_run);
    std::snprintf(buf, sizeof buf, "%s%s %.3f", open, CheckTimings::part_name(k), ms);
    s += buf;
    open = ", ";
  }
  s += ")";
  if (o.back > 0) {
    std::snprintf(buf, sizeof buf, "; went back %s to ", plural(o.back, "frame").c_str());
    s += buf + label(source.frame());
    std::snprintf(buf, sizeof buf, ": %.3f ms a frame (kept frame rebuilt, detected, checked)", back_ms / static_cast<double>(o.back));
    s += buf;
  }
  if (o.violation > 0)  // where it went, as the Violations panel would say it
    s += "; went to violation " + std::to_string(o.violation) + ", " + label(source.frame()) + ": " +
         violation_text(loop.history().violation_log().listed()[static_cast<std::size_t>(o.violation - 1)], source);
  return s;
}

}  // namespace nbscope

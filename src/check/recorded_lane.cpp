#include "check/recorded_lane.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace nbscope {

void RecordedPairsDetector::detect(const Elements& /*elements*/, const DetectOptions& options, PairList& out_pairs) {
  if (pairs_ == nullptr) throw Error("recorded: there are no recorded pairs for this frame");
  if (pairs_->size() > options.max_pairs) throw_pair_limit(options.max_pairs);
  out_pairs.resize(pairs_->size());
  std::transform(pairs_->begin(), pairs_->end(), out_pairs.begin(),
                 [](const Pair& p) { return p.i <= p.j ? p : Pair{p.j, p.i}; });
}

void RecordedPairsDetector::detect_traced(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                                          TraceLog& out_trace) {
  out_trace.reset();
  detect(elements, options, out_pairs);
}

const DetectorInfo& recorded_info() {
  static const DetectorInfo info = [] {
    DetectorInfo d;
    d.name = std::string(kRecordedAlgorithm);
    d.summary = "the pairs a recording carries (its frames' pairs blocks), checked as any detector's";
    d.dim2 = true;
    d.dim3 = true;  // a dump's frames may be 3D
    d.traces = false;
    d.has_lists = false;
    d.make = [] { return std::make_unique<RecordedPairsDetector>(); };
    return d;
  }();
  return info;
}

const DetectorInfo& algorithm_info(std::string_view name) {
  return name == kRecordedAlgorithm ? recorded_info() : detector_info(name);
}

std::unique_ptr<Detector> make_lane_detector(std::string_view name) {
  if (name == kRecordedAlgorithm) return std::make_unique<RecordedPairsDetector>();
  // The registry does not know `recorded`: an unknown name's message names it too.
  const auto& infos = detector_infos();
  if (std::none_of(infos.begin(), infos.end(), [&](const DetectorInfo& d) { return d.name == name; }))
    throw Error("unknown algorithm '" + std::string(name) + "' (known: " + detector_names() + "; in a replay of a recording with pairs also " +
                std::string(kRecordedAlgorithm) + ")");
  // A detector of one dimension (a 3D-only plugin) is a lane like any: a frame of the other dimension
  // is refused when it comes, naming both (Pipeline::detect).
  return make_detector(name);
}

void check_recorded_fault(Fault fault) {
  if (fault == Fault::None || fault == Fault::DropPair) return;
  throw Error(std::string("--inject-fault ") + fault_name(fault) +
              (fault == Fault::DropBox2dContact ? ": acts on Box2D's contact list" : ": emulates a bug in a detector's input or cells") +
              ", and the recorded pairs are read from the recording, not detected: only drop-pair acts on them (or check a "
              "detector, e.g. --algorithm nbs)");
}

const char* recorded_trace_refusal() {
  return "recorded: the recording's own pairs, read from the file, not detected here: there are no operations or lists to "
         "show (choose a detector such as nbs to see them)";
}

}  // namespace nbscope

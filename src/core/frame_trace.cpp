#include "core/frame_trace.hpp"

#include <atomic>

namespace nbscope {

FrameTrace refused_trace(std::int64_t frame, std::string_view algorithm) {
  static std::atomic<std::uint64_t> next_serial{1};
  FrameTrace out;
  out.serial = next_serial++;
  out.frame = frame;
  out.algorithm = std::string(algorithm);
  return out;
}

std::shared_ptr<const FrameTrace> trace_frame(Detector& detector, const Elements& elements, const DetectOptions& options,
                                              std::int64_t frame, const Grid& frame_grid) {
  auto out = std::make_shared<FrameTrace>(refused_trace(frame, detector.name()));
  out->grid = frame_grid;
  out->touching = options.touching;
  const std::string name = out->algorithm;
  if (!detector.supports_dim(elements.dim)) {
    out->refusal = name + " does not handle " + std::to_string(elements.dim) + "D elements";
    return out;
  }
  if (elements.size() > kMaxTracedElements) {
    out->refusal = std::to_string(elements.size()) + " elements: too many to record every operation (limit " +
                   std::to_string(kMaxTracedElements) + "); step through a smaller scene";
    return out;
  }
  // Brute force records one test per pair: past a few million the recording alone takes gigabytes.
  const double brute_tests = 0.5 * static_cast<double>(elements.size()) * static_cast<double>(elements.size() - 1);
  if (name == "brute" && brute_tests > static_cast<double>(kMaxTracedBruteTests)) {
    out->refusal = "brute: " + std::to_string(elements.size()) + " elements make " +
                   std::to_string(static_cast<std::int64_t>(brute_tests)) + " pair tests, too many to record (limit " +
                   std::to_string(kMaxTracedBruteTests) + "); step through a smaller scene or a grid algorithm";
    return out;
  }
  DetectOptions serial = options;
  serial.threads = 1;  // the stepper walks the book's serial loops, whatever the run's --threads
  detector.detect_traced(elements, serial, out->pairs, out->log);
  out->detected = true;
  if (const Misbehaviour* m = detector.misbehaviour()) out->misbehaviour = *m;
  if (out->log.events().empty() && !out->misbehaviour) {  // a bug before its first operation is still located there
    std::string tracing;
    for (const DetectorInfo& d : detector_infos())
      if (d.traces && (elements.dim == 3 ? d.dim3 : d.dim2)) tracing += (tracing.empty() ? "" : ", ") + d.name;
    out->refusal = name + " records no operations (it keeps no book arrays): choose " + tracing + " to see them";
    return out;
  }
  if (const Grid* g = detector.last_grid()) {
    out->grid = *g;
    out->detector_grid = true;
  }
  const auto& lines = detector.pseudocode(elements.dim);
  out->pseudocode.assign(lines.begin(), lines.end());
  out->elements = elements;
  return out;
}

}  // namespace nbscope

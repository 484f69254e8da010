// nbscope app: a headless run's first violation followed to the operation that decided it
// (check/diagnosis.hpp), for the summary line and the report (headless.hpp).
#include <string>

#include "app/frame_loop.hpp"
#include "app/headless.hpp"
#include "check/diagnosis.hpp"
#include "core/detector.hpp"

namespace nbscope {

namespace {
const DetectorInfo* info_of(const std::string& algorithm) {
  for (const DetectorInfo& d : detector_infos())
    if (d.name == algorithm) return &d;
  return nullptr;
}
}  // namespace

bool traces_every_frame(const std::string& algorithm) {
  const DetectorInfo* d = info_of(algorithm);
  return d != nullptr && !d->library.empty() && d->traces;
}

std::optional<LocatedViolation> locate_violation(FrameLoop& loop, const Violation& v) {
  if (v.frame != loop.source().frame()) return std::nullopt;  // only the frame shown has its trace at hand
  // A built-in that traces is traced once more for it (it keeps no state between calls); a plugin
  // only when its frame's one detection recorded the trace: it is never called twice for a frame.
  const DetectorInfo* info = info_of(loop.pipeline().algorithm());
  if (info == nullptr || !info->traces || (!info->library.empty() && !loop.pipeline().record_traces())) return std::nullopt;
  const std::shared_ptr<const FrameTrace> trace = loop.pipeline().frame_trace();
  if (!trace || !trace->refusal.empty()) return std::nullopt;  // nothing recorded: nothing to locate in
  const std::vector<std::int64_t>* ids = loop.result().ids.get();  // the frame shown's atoms (a dump's)
  const auto id = [&](std::int64_t row) { return element_label(element_id(ids, row), row); };
  const Diagnosis d = diagnose_frame(v, *trace, id);
  LocatedViolation l;
  l.frame = v.frame;
  if (d.event) l.operation = static_cast<std::int64_t>(*d.event) + 1;
  if (d.contract) l.contract = contract_name(d.contract->contract);
  l.operations = static_cast<std::int64_t>(d.operations);
  l.kind = d.kind;
  l.line = d.line >= 0 ? d.line + 1 : -1;
  l.pseudocode = d.pseudocode;
  l.text = d.text;
  return l;
}

}  // namespace nbscope

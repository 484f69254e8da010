#include "core/brute.hpp"

namespace nbscope {

namespace {
template <class Trace>
void brute_pairs(const Elements& e, const DetectOptions& options, PairList& out, Trace& trace) {
  check_periodic_box(e, "brute");
  PairCollector pairs(out, options.max_pairs);
  const auto n = static_cast<ElementId>(e.size());
  trace.phase(0, "all pairs", -1);
  for (ElementId i = 0; i < n; ++i) {
    for (ElementId j = i + 1; j < n; ++j) {
      const bool contact = in_contact(e, i, j, options.touching);
      trace.test_pair(1, i, j, contact);
      if (contact) pairs.add(i, j);
    }
  }
}
}  // namespace

const std::vector<const char*>& BruteDetector::pseudocode(int /*dim*/) const {
  static const std::vector<const char*> lines = {
      "Loop over all discrete elements i, and for each over all discrete elements j > i",
      "  check i against j: in contact when |c_i - c_j| <= r_i + r_j (strict: <; minimum image on periodic axes)",
  };
  return lines;
}

void BruteDetector::detect(const Elements& elements, const DetectOptions& options, PairList& out_pairs) {
  NullTrace none;
  brute_pairs(elements, options, out_pairs, none);
}

void BruteDetector::detect_traced(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                                  TraceLog& out_trace) {
  out_trace.reset();
  brute_pairs(elements, options, out_pairs, out_trace);
}

}  // namespace nbscope

// nbscope core: `brute`, direct checking of all N(N-1)/2 pairs — the reference every detector
// is compared with.
#pragma once
#include "core/detector.hpp"

namespace nbscope {

class BruteDetector final : public Detector {
 public:
  [[nodiscard]] std::string_view name() const override { return "brute"; }
  [[nodiscard]] bool supports_dim(int dim) const override { return dim == 2 || dim == 3; }
  void detect(const Elements& elements, const DetectOptions& options, PairList& out_pairs) override;
  void detect_traced(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                     TraceLog& out_trace) override;
  [[nodiscard]] std::size_t own_bytes() const override { return 0; }
  [[nodiscard]] const std::vector<const char*>& pseudocode(int dim) const override;
};

}  // namespace nbscope

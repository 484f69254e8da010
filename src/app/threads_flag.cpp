// --threads, on every command that detects (app/threads_flag.hpp).
#include "app/threads_flag.hpp"

#include "core/threads.hpp"

namespace nbscope {

int take_threads(Args& args) {
  const auto n = args.integer("--threads");
  return n ? static_cast<int>(*n) : machine_threads();
}

OptionSpec threads_option() {
  return {"--threads", "N", "the machine's cores",
          "threads one detection may use, 1 to 64: nbs detects bands of rows (3D: layers) on N threads, with the same "
          "arrays and pairs as on one; the other detectors, the checks' references and the stepper's traced run use one",
          integer_value(1, kMaxThreads)};
}

}  // namespace nbscope

// nbscope core: threads.hpp.
#include "core/threads.hpp"

#include <algorithm>
#include <thread>

namespace nbscope {

int machine_threads() {
  const auto n = static_cast<int>(std::thread::hardware_concurrency());  // 0 when unknown
  return std::clamp(n, 1, kMaxThreads);
}

}  // namespace nbscope

// nbscope app: the wall clock the frame loops and views time their work with.
#pragma once
#include <chrono>

namespace nbscope {

using Clock = std::chrono::steady_clock;

// Milliseconds since t0.
inline double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

}  // namespace nbscope

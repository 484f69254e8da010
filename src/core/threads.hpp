// nbscope core: how many threads a detection may use (DetectOptions::threads).
#pragma once
#include <cstdint>

namespace nbscope {

// Most threads one detection uses (--threads is refused above it).
inline constexpr int kMaxThreads = 64;

// Fewest elements per band by default (DetectOptions::min_band_elements): below about this many a
// band's thread costs more to wake than its share of the work saves (BM_Detect/nbs at 1e4 on 1 and 2 threads).
inline constexpr std::int64_t kMinBandElements = 8192;

// The machine's hardware threads (std::thread::hardware_concurrency), at least 1 and at most
// kMaxThreads: the default of --threads.
[[nodiscard]] int machine_threads();

}  // namespace nbscope

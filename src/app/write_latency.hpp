// nbscope app: how long after a watched run wrote a frame nbscope had checked it (`watch`'s summary).
#pragma once
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace nbscope {

// Seconds since the epoch now (the clock a file's modification time is on).
inline double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

// The latencies from write to check of the frames written after the watch started.
class WriteToCheck {
 public:
  // A frame checked now that was written at `written` (none: not a watched frame); frames written
  // before `since` (the watch's start: they waited for it, not for nbscope) are not counted.
  void add(std::optional<double> written, double since) {
    if (!written || *written < since) return;
    ms_.push_back(std::max(0.0, (wall_seconds() - *written) * 1000.0));
  }
  // "; N frames checked a median of X ms (at most Y ms) after they were written", or "" for none.
  [[nodiscard]] std::string text() const {
    if (ms_.empty()) return "";
    std::vector<double> sorted = ms_;
    std::sort(sorted.begin(), sorted.end());
    char buf[160];
    std::snprintf(buf, sizeof buf, "; %zu frame%s checked a median of %.0f ms (at most %.0f ms) after %s written", sorted.size(),
                  sorted.size() == 1 ? "" : "s", sorted[sorted.size() / 2], sorted.back(), sorted.size() == 1 ? "it was" : "they were");
    return buf;
  }

 private:
  std::vector<double> ms_;
};

}  // namespace nbscope

// nbscope app: the progress bar of `headless` and `replay --headless` on a terminal.
#pragma once
#include <algorithm>
#include <cstdint>
#include <cstdio>

#include "io/plural.hpp"

namespace nbscope {

// A one-line bar on stderr, redrawn only when it changes; erased when done or when an error
// unwinds past it, so that the error line starts clean.
class Progress {
 public:
  // A bar for `total` frames, drawn only when `on` (stderr is a terminal and no --quiet).
  Progress(bool on, std::int64_t total) : on_(on), total_(total) {}
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  ~Progress() { finish(); }
  // `done` frames of the total have run.
  void update(std::int64_t done) {
    if (!on_) return;
    const int width = 40;
    const int filled = static_cast<int>(width * done / std::max<std::int64_t>(total_, 1));
    if (filled == last_ && done != total_) return;
    last_ = filled;
    std::fprintf(stderr, "\r[%.*s%*s] %lld/%s", filled, "========================================", width - filled, "",
                 static_cast<long long>(done), plural(total_, "frame").c_str());
    std::fflush(stderr);
  }
  // Erases the bar (once).
  void finish() {
    if (on_ && last_ != -1) std::fputs("\r\033[K", stderr);
    last_ = -1;
  }

 private:
  bool on_;
  std::int64_t total_;
  int last_ = -1;
};

}  // namespace nbscope

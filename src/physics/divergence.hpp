// nbscope physics: the check that a run made again is the run made the first time: the first frame
// whose element hash (core/elements.hpp) differs from the hash the first run had. A resume
// (physics/resume.hpp) compares against the history, `headless --rewind` against its first pass.
#pragma once
#include <cstdint>
#include <optional>

namespace nbscope {

class Divergence {
 public:
  // Forgets what was found (a new comparison).
  void clear() { first_.reset(); }
  // Frame `frame` made again with element hash `now`, where the first run had `before` (0: not
  // known, not compared); the first frame that differs is kept.
  void compare(std::int64_t frame, std::uint64_t before, std::uint64_t now) {
    if (!first_ && before != 0 && before != now) first_ = frame;
  }
  // The first frame that differed, or nullopt when every frame compared came back exactly.
  [[nodiscard]] std::optional<std::int64_t> first() const { return first_; }

 private:
  std::optional<std::int64_t> first_;
};

}  // namespace nbscope

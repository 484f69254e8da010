// nbscope app: the slow-frame note. A frame (Box2D's step, detection, the check) that runs longer
// than a few seconds says so once per run on stderr, terminal or not, while it still runs:
//   nbscope: note: frame 1 has run for 5.0 s so far (Box2D step: 2,000 bodies, about 1,234,567 contacts)
// so that a run that seems to hang says what it is doing. So do the last kSlowWindow frames when
// together they took longer than that, none alone (a world growing slowly heavier, an emitter
// piling bodies up), said when the last of them ends and describing the phase that took most:
//   nbscope: note: frames 60 to 69 took 5.2 s together (Box2D step: 682 bodies, about 25,252 contacts)
// Either note comes once per run. Frames made by a step are watched (the step, then their
// detection and check); frame 0 and frames detected again are not. A watcher thread waits for the
// deadline; arming and disarming cost a mutex and a notify.
//
// The threshold is 5 s; the environment variable NBSCOPE_SLOW_FRAME_SECONDS sets another (tests).
#pragma once
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace nbscope {

// How many consecutive watched frames the note adds up.
inline constexpr int kSlowWindow = 10;

class FrameWatch {
 public:
  // What the frame is doing, asked for only when the note is printed (from the watcher thread:
  // it must read only what is safe to read while the frame runs).
  using Describe = std::function<std::string()>;

  FrameWatch();
  ~FrameWatch();
  FrameWatch(const FrameWatch&) = delete;
  FrameWatch& operator=(const FrameWatch&) = delete;

  // Frame `frame` starts (or moves to another phase): the note, if due, describes it with `describe`.
  void arm(std::int64_t frame, Describe describe);
  // The frame being watched moves to another phase (no effect when `frame` is not being watched:
  // frames detected again, not stepped, e.g. on load or a change of algorithm, are not watched).
  void next_phase(std::int64_t frame, Describe describe);
  // The frame is done (the note on the last kSlowWindow frames is printed here when due).
  void disarm();
  // A new run: the note may be printed again.
  void reset();
  // True once the note was printed in this run.
  [[nodiscard]] bool noted() const;
  // The threshold in seconds (NBSCOPE_SLOW_FRAME_SECONDS, else 5).
  [[nodiscard]] double threshold() const { return threshold_; }

 private:
  void watch();
  // Adds the frame that just ended to the recent ones, and prints their note when due (under the lock).
  void add_recent(std::chrono::steady_clock::time_point now);

  double threshold_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool armed_ = false, noted_ = false, quit_ = false;
  std::uint64_t generation_ = 0;  // one per arm(): a deadline belongs to the frame that set it
  std::int64_t frame_ = 0;
  std::chrono::steady_clock::time_point started_;
  Describe describe_;
  // The frame being watched: when its first phase (the step) ended, and that phase's description.
  std::optional<std::chrono::steady_clock::time_point> first_phase_ended_;
  Describe first_describe_;
  // The last frames watched to their end, oldest first: seconds in the first phase and after.
  struct Spent {
    std::int64_t frame;
    double first_phase, later;
  };
  std::deque<Spent> recent_;
  std::thread thread_;  // started at the first arm()
};

}  // namespace nbscope

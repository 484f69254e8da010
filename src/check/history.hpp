// nbscope check: the frame history behind the timeline and the Violations panel.
//
//   FrameHistory  one FrameSummary per frame of the run (what the timeline plots), and for the
//                 newest frames within a memory budget the kept world state that shows the frame
//                 again (oldest states dropped first; their summaries stay, marked not kept).
//   ViolationLog  every violation of the run in frame order (a frame checked again replaces its own).
//
// Neither knows Box2D: a kept state is an opaque physics::WorldState held by shared pointer.
#pragma once
#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "check/report.hpp"

namespace nbscope {

struct WorldState;

class FrameHistory {
 public:
  // Memory for kept world states by default (the window's; settable, saved in the settings).
  static constexpr std::size_t kDefaultBudget = std::size_t{256} << 20;
  // Most summaries kept: beyond it the oldest go too (a run of a million frames plots in ~100 MB).
  static constexpr std::size_t kMaxSummaries = 1'000'000;

  // Forgets every frame (a new scene, a restart).
  void clear();
  // Bytes the kept states may take; states past it are dropped now, oldest first (never the newest).
  void set_budget(std::size_t bytes);
  [[nodiscard]] std::size_t budget() const { return budget_; }
  // Most summaries kept (default kMaxSummaries; a headless run that never goes back and draws no
  // timeline needs only the newest few): beyond it the oldest go, as their states do.
  void set_max_summaries(std::size_t count);
  // Bytes of the kept states and the summaries.
  [[nodiscard]] std::size_t bytes() const { return state_bytes_ + summaries_.size() * sizeof(FrameSummary); }
  // Frames whose states were dropped for the budget (their summaries remain).
  [[nodiscard]] std::int64_t dropped() const { return dropped_; }

  // Appends the newest frame, whose number must exceed the last one's; `state` (null for a frame
  // that needs none, as a recorded one) makes it kept. Drops old states past the budget.
  void push(const FrameSummary& summary, std::shared_ptr<const WorldState> state, std::size_t state_bytes);
  // Index of frame `frame` among the summaries, or nullopt.
  [[nodiscard]] std::optional<std::size_t> find(std::int64_t frame) const;
  // Index of the first summary at or after frame `frame` (size() when there is none).
  [[nodiscard]] std::size_t first_from(std::int64_t frame) const;
  // The summaries, oldest first, and one by index.
  [[nodiscard]] const std::deque<FrameSummary>& summaries() const { return summaries_; }
  [[nodiscard]] const FrameSummary& at(std::size_t index) const { return summaries_[index]; }
  [[nodiscard]] std::size_t size() const { return summaries_.size(); }
  [[nodiscard]] bool empty() const { return summaries_.empty(); }
  // The kept state of summary `index` (null when not kept or a recorded frame).
  [[nodiscard]] const std::shared_ptr<const WorldState>& state(std::size_t index) const { return states_[index]; }
  // Replaces the counts of summary `index` (the frame was detected or checked again); `kept` stays.
  void update(std::size_t index, const FrameSummary& summary);
  // Drops every frame after `frame` (resuming from it replaces them).
  void truncate_after(std::int64_t frame);
  // The oldest kept frame, or nullopt.
  [[nodiscard]] std::optional<std::int64_t> first_kept() const;

 private:
  void enforce_budget();

  std::deque<FrameSummary> summaries_;
  std::deque<std::shared_ptr<const WorldState>> states_;
  std::deque<std::size_t> state_sizes_;
  std::size_t first_state_ = 0;  // summaries before it have no state
  std::size_t budget_ = kDefaultBudget;
  std::size_t max_summaries_ = kMaxSummaries;
  std::size_t state_bytes_ = 0;
  std::int64_t dropped_ = 0;
};

class ViolationLog {
 public:
  // Most violations listed over a run (48 bytes each); beyond it they are counted, not listed.
  static constexpr std::size_t kMaxListed = 1'000'000;

  void clear();
  // Records the violations of `report`'s frame, replacing any recorded for that frame before.
  void set_frame(const FrameReport& report);
  // Drops the violations of frames after `frame`.
  void truncate_after(std::int64_t frame);
  // Every listed violation, in frame order (within a frame, in the order the check found them).
  [[nodiscard]] const std::vector<Violation>& listed() const { return listed_; }
  // All violations (listed or not), per invariant, and the frames that had any.
  [[nodiscard]] std::int64_t total() const;
  [[nodiscard]] const std::array<std::int64_t, kInvariantCount>& by_invariant() const { return by_invariant_; }
  [[nodiscard]] std::int64_t frames() const { return static_cast<std::int64_t>(per_frame_.size()); }
  // The first frame with a violation, or nullopt.
  [[nodiscard]] std::optional<std::int64_t> first_frame() const;
  // Bumped on every change (the panel rebuilds its filtered view only then).
  [[nodiscard]] std::uint64_t generation() const { return generation_; }

 private:
  void forget_frame(std::int64_t frame);

  std::vector<Violation> listed_;
  std::map<std::int64_t, std::array<std::int64_t, kInvariantCount>> per_frame_;  // frames with violations
  std::array<std::int64_t, kInvariantCount> by_invariant_{};
  std::uint64_t generation_ = 0;
};

}  // namespace nbscope

// FrameLoop's history side: showing kept past frames (and recorded ones) again, and resuming the
// simulation from a past frame by deterministic re-simulation.
//
// Index: history | resume.
#include "app/frame_loop_impl.hpp"

namespace nbscope {

// ---- history -------------------------------------------------------------------------------

LoopHistory::LoopHistory(LoopSource& source, std::size_t budget, std::size_t max_summaries) : source_(source) {
  frames_.set_budget(budget);
  frames_.set_max_summaries(max_summaries);
}

const FrameHistory& LoopHistory::frames() const { return frames_; }
void LoopHistory::set_budget(std::size_t bytes) {
  frames_.set_budget(bytes);
  if (source_.loaded()) source_.frames_->set_budget(bytes);
}
std::size_t LoopHistory::bytes() const { return frames_.bytes() + (source_.loaded() ? source_.frames_->held_bytes() : 0); }
const ViolationLog& LoopHistory::violation_log() const { return violations_; }
bool LoopHistory::showing_past() const { return source_.loaded() && source_.frames_->showing_past(); }
std::int64_t LoopHistory::newest_frame() const { return source_.loaded() ? source_.frames_->newest_frame() : 0; }

bool LoopHistory::can_show(std::int64_t frame) const {
  if (!source_.loaded()) return false;
  if (frame == source_.frames_->newest_frame()) return true;
  const auto index = frames_.find(frame);
  return index && frames_.at(*index).kept;  // a recorded frame, or one whose state is kept
}

std::optional<std::int64_t> LoopHistory::neighbour(std::int64_t delta) const {
  if (!source_.loaded() || delta == 0 || frames_.empty()) return std::nullopt;
  const auto here = frames_.find(source_.frame());
  if (!here) return std::nullopt;
  const auto last = static_cast<std::int64_t>(frames_.size()) - 1;
  std::int64_t index = std::clamp<std::int64_t>(static_cast<std::int64_t>(*here) + delta, 0, last);
  // Past frames whose states were dropped cannot be shown: stop at the oldest that can.
  const auto showable = [&](std::int64_t i) { return can_show(frames_.at(static_cast<std::size_t>(i)).frame); };
  while (index != static_cast<std::int64_t>(*here) && !showable(index)) index += delta > 0 ? -1 : 1;
  if (index == static_cast<std::int64_t>(*here)) return std::nullopt;
  return frames_.at(static_cast<std::size_t>(index)).frame;
}

void LoopHistory::element_path(ElementId k, std::int64_t from, std::int64_t to, std::vector<std::array<double, 2>>& out) const {
  out.clear();
  if (!source_.loaded() || k < 0) return;
  source_.frames_->element_path(frames_, k, from, to, out);  // never waits for a step in flight (io/frame_source.hpp)
}

// ---- resume --------------------------------------------------------------------------------

void LoopResume::begin() {
  FrameLoopState& m = loop_;
  m.settle();
  Simulation* sim = m.simulation();
  if (sim == nullptr || !m.frames().showing_past() || sim->resuming()) return;
  sim->begin_resume();
}

bool LoopResume::advance(double budget_ms) {
  FrameLoopState& m = loop_;
  Simulation* sim = m.simulation();
  if (sim == nullptr || !sim->resuming()) return true;
  // Every kept frame on the way must come back exactly (the hash the history has of it).
  const auto hash_of = [&m](std::int64_t frame) -> std::uint64_t {
    const auto index = m.kept().find(frame);
    return index ? m.kept().at(*index).hash : 0;
  };
  if (!sim->advance_resume(budget_ms, hash_of)) return false;

  // Arrived: the re-simulated world is the newest frame, K; the later frames are gone.
  const std::int64_t k = m.frame_number();
  m.kept().truncate_after(k);
  m.violations().truncate_after(k);
  m.lanes().remember_previous(k, sim->resumed_previous());
  m.set_physics_ms(0);
  m.detect_and_check(FrameChange::Kind::shown);
  return true;
}

void LoopResume::cancel() {
  if (Simulation* sim = loop_.simulation()) sim->cancel_resume();
}
bool LoopResume::active() const { return loop_.resuming(); }
std::pair<std::int64_t, std::int64_t> LoopResume::progress() const {
  const Simulation* sim = loop_.simulation();
  return sim != nullptr ? sim->resume_progress() : std::pair<std::int64_t, std::int64_t>{0, 0};
}
std::optional<std::int64_t> LoopResume::divergence() const {
  const Simulation* sim = loop_.simulation();
  return sim != nullptr ? sim->divergence() : std::nullopt;
}

}  // namespace nbscope

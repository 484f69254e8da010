// FrameLoop's history side: showing kept past frames (and recorded ones) again, and resuming the
// simulation from a past frame by deterministic re-simulation.
//
// Index: history | resume.
#include "app/frame_loop_impl.hpp"

namespace nbscope {

// ---- history -------------------------------------------------------------------------------

const FrameHistory& LoopHistory::frames() const { return s_->history; }
void LoopHistory::set_budget(std::size_t bytes) {
  s_->options.history_budget = bytes;
  s_->history.set_budget(bytes);
  if (s_->replay) s_->replay->set_budget(bytes);
}
std::size_t LoopHistory::bytes() const { return s_->history.bytes() + (s_->replay ? s_->replay->kept_bytes() : 0); }
const ViolationLog& LoopHistory::violation_log() const { return s_->violations; }
bool LoopHistory::showing_past() const { return s_->kept != nullptr; }

std::int64_t LoopHistory::newest_frame() const {
  const FrameLoopState& m = *s_;
  if (m.replay) return m.replay->entries().back().number;
  return m.live ? m.live_frame() : 0;
}

bool LoopHistory::can_show(std::int64_t frame) const {
  const FrameLoopState& m = *s_;
  if (!m.loaded()) return false;
  if (m.live && frame == m.live_frame()) return true;
  const auto index = m.history.find(frame);
  return index && m.history.at(*index).kept && (m.replay || m.history.state(*index));
}

std::optional<std::int64_t> LoopHistory::neighbour(std::int64_t delta) const {
  const FrameLoopState& m = *s_;
  if (!m.loaded() || delta == 0 || m.history.empty()) return std::nullopt;
  const auto here = m.history.find(m.frame_number());
  if (!here) return std::nullopt;
  const auto last = static_cast<std::int64_t>(m.history.size()) - 1;
  std::int64_t index = std::clamp<std::int64_t>(static_cast<std::int64_t>(*here) + delta, 0, last);
  // Past frames whose states were dropped cannot be shown: stop at the oldest that can.
  const auto showable = [&](std::int64_t i) { return can_show(m.history.at(static_cast<std::size_t>(i)).frame); };
  while (index != static_cast<std::int64_t>(*here) && !showable(index)) index += delta > 0 ? -1 : 1;
  if (index == static_cast<std::int64_t>(*here)) return std::nullopt;
  return m.history.at(static_cast<std::size_t>(index)).frame;
}

void LoopHistory::element_path(ElementId k, std::int64_t from, std::int64_t to, std::vector<std::array<double, 2>>& out) const {
  out.clear();
  const FrameLoopState& m = *s_;
  if (!m.loaded() || k < 0) return;
  m.wait_for_worker();  // the world's geometry is read below
  // From the first summary at or after `from` (a trail is a few hundred frames of a long history).
  const auto& summaries = m.history.summaries();
  const auto first = std::lower_bound(summaries.begin(), summaries.end(), from,
                                      [](const FrameSummary& f, std::int64_t n) { return f.frame < n; });
  // A dump's rows shift as atoms come and go: the atom at row k of frame `to` is followed by its id.
  // Recorded frames out of memory are not read again for a trail: it runs through the frames kept.
  const std::shared_ptr<const RecordedFrame> frame_to = m.replay ? m.replay->frame_at(m.replay->index_of(to)) : nullptr;
  const std::vector<std::int64_t>* ids_to = frame_to ? &frame_to->ids : nullptr;
  const bool by_atom = ids_to != nullptr && static_cast<std::size_t>(k) < ids_to->size();
  const std::int64_t atom = by_atom ? (*ids_to)[static_cast<std::size_t>(k)] : -1;
  for (auto i = static_cast<std::size_t>(first - summaries.begin()); i < m.history.size(); ++i) {
    const FrameSummary& f = m.history.at(i);
    if (f.frame > to) break;
    if (m.replay) {
      const std::shared_ptr<const RecordedFrame> held = m.replay->held(m.replay->index_of(f.frame));
      if (!held) continue;
      const RecordedFrame& rf = *held;
      std::int64_t row = k;
      if (by_atom) {
        const auto it = std::lower_bound(rf.ids.begin(), rf.ids.end(), atom);  // ascending (io/recording.hpp)
        row = it != rf.ids.end() && *it == atom ? it - rf.ids.begin() : -1;     // -1: not in that frame
      }
      if (row >= 0 && row < rf.elements.size()) out.push_back({rf.elements.x[row], rf.elements.y[row]});
    } else if (k >= f.elements) {
      continue;
    } else if (const auto& state = m.history.state(i)) {
      std::array<double, 2> p{};
      m.live->world().element_centre(*state, k, p[0], p[1]);
      out.push_back(p);
    } else if (f.frame == m.live_frame()) {
      out.push_back({m.now().x[k], m.now().y[k]});
    }
  }
}

// ---- resume --------------------------------------------------------------------------------

void LoopResume::begin() {
  FrameLoopState& m = *s_;
  m.settle();
  if (!m.live || !m.kept || m.resume.active()) return;
  m.live->release_drag();
  m.resume.begin(m.scene, m.kept->frame());
}

bool LoopResume::advance(double budget_ms) {
  FrameLoopState& m = *s_;
  if (!m.resume.active()) return true;
  // Every kept frame on the way must come back exactly (the hash the history has of it).
  const auto hash_of = [&m](std::int64_t frame) -> std::uint64_t {
    const auto index = m.history.find(frame);
    return index ? m.history.at(*index).hash : 0;
  };
  if (!m.resume.advance(budget_ms, m.live->drags(), hash_of)) return false;

  // Arrived: the re-simulated world is the live one at K, the later frames are gone.
  const std::int64_t k = m.resume.target();
  std::unique_ptr<PhysicsWorld> world = m.resume.take_world();
  m.kept.reset();
  m.live->replace_world(std::move(world));  // the drags from K on go with the frames
  m.history.truncate_after(k);
  m.violations.truncate_after(k);
  m.live->release_drag();  // nobody holds the mouse now; recorded, so a later resume replays it too
  m.pipeline.remember_previous(k, m.resume.previous_elements());
  m.set_physics_ms(0);
  m.detect_and_check(FrameChange::Kind::shown);
  return true;
}

void LoopResume::cancel() { s_->resume.cancel(); }
bool LoopResume::active() const { return s_->resume.active(); }
std::pair<std::int64_t, std::int64_t> LoopResume::progress() const { return s_->resume.progress(); }
std::optional<std::int64_t> LoopResume::divergence() const { return s_->resume.divergence(); }

}  // namespace nbscope

// FrameLoop's history side: showing kept past frames (and recorded ones) again, and resuming the
// simulation from a past frame by deterministic re-simulation.
//
// Index: history | resume.
#include "app/frame_loop_impl.hpp"

namespace nbscope {

// ---- history -------------------------------------------------------------------------------

const FrameHistory& FrameLoop::history() const { return impl_->history; }
void FrameLoop::set_history_budget(std::size_t bytes) {
  impl_->options.history_budget = bytes;
  impl_->history.set_budget(bytes);
}
const ViolationLog& FrameLoop::violation_log() const { return impl_->violations; }
bool FrameLoop::showing_past() const { return impl_->kept != nullptr; }

std::int64_t FrameLoop::newest_frame() const {
  const Impl& m = *impl_;
  if (m.replay) return m.replay->recording().frames.back().number;
  return m.live ? m.live_frame() : 0;
}

bool FrameLoop::can_show(std::int64_t frame) const {
  const Impl& m = *impl_;
  if (!m.loaded()) return false;
  if (m.live && frame == m.live_frame()) return true;
  const auto index = m.history.find(frame);
  return index && m.history.at(*index).kept && (m.replay || m.history.state(*index));
}

void FrameLoop::show_frame(std::int64_t frame) {
  Impl& m = *impl_;
  if (!m.loaded()) return;
  m.settle();  // the newest frame first, so that the run (and its history) is whole
  if (m.resume.active()) throw Error("frame " + std::to_string(frame) + ": the simulation is being resumed; wait or cancel");
  if (!can_show(frame)) {
    const auto first = m.history.first_kept();
    throw Error("frame " + std::to_string(frame) + " is not kept (frames " +
                (first ? std::to_string(*first) : std::to_string(newest_frame())) + ".." + std::to_string(newest_frame()) +
                " are; a larger history budget keeps more)");
  }
  if (frame == m.frame_number()) return;
  const double physics_ms = 0;  // nothing was simulated to show it
  if (m.replay) {
    m.replay->show(frame);
  } else if (frame == m.live->world().frame()) {
    m.kept.reset();
  } else {
    m.live->release_drag();  // leaving the live frame: nobody holds a body in the past
    m.kept = std::make_unique<KeptWorldFrame>(m.live->world(), m.history.state(*m.history.find(frame)));
  }
  m.set_physics_ms(physics_ms);
  m.detect_and_check();
}

bool FrameLoop::step_back() {
  const auto previous = neighbour(-1);
  if (!previous) return false;
  show_frame(*previous);
  return true;
}

std::optional<std::int64_t> FrameLoop::neighbour(std::int64_t delta) const {
  const Impl& m = *impl_;
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

void FrameLoop::element_path(ElementId k, std::int64_t from, std::int64_t to, std::vector<std::array<double, 2>>& out) const {
  out.clear();
  const Impl& m = *impl_;
  if (!m.loaded() || k < 0) return;
  m.wait_for_worker();  // the world's geometry is read below
  // From the first summary at or after `from` (a trail is a few hundred frames of a long history).
  const auto& summaries = m.history.summaries();
  const auto first = std::lower_bound(summaries.begin(), summaries.end(), from,
                                      [](const FrameSummary& f, std::int64_t n) { return f.frame < n; });
  for (auto i = static_cast<std::size_t>(first - summaries.begin()); i < m.history.size(); ++i) {
    const FrameSummary& f = m.history.at(i);
    if (f.frame > to) break;
    if (k >= f.elements) continue;
    if (m.replay) {
      const Elements& e = m.replay->recording().frames[m.replay->index_of(f.frame)].elements;
      out.push_back({e.x[k], e.y[k]});
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

void FrameLoop::begin_resume() {
  Impl& m = *impl_;
  m.settle();
  if (!m.live || !m.kept || m.resume.active()) return;
  m.live->release_drag();
  m.resume.begin(m.scene, m.kept->frame());
}

bool FrameLoop::continue_resume(double budget_ms) {
  Impl& m = *impl_;
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
  m.detect_and_check();
  return true;
}

void FrameLoop::cancel_resume() { impl_->resume.cancel(); }
bool FrameLoop::resuming() const { return impl_->resume.active(); }
std::pair<std::int64_t, std::int64_t> FrameLoop::resume_progress() const { return impl_->resume.progress(); }
std::optional<std::int64_t> FrameLoop::resume_divergence() const { return impl_->resume.divergence(); }

}  // namespace nbscope

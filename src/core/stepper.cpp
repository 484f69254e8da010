#include "core/stepper.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace nbscope {

namespace {
// Fewest events between checkpoints: below this a walk is as cheap as a checkpoint copy.
constexpr std::size_t kMinCheckpointInterval = 1024;

const char* op_name(TraceOp op) { return trace_op_name(op); }
}  // namespace

bool breakpoint_matches(const Breakpoint& b, const TraceEvent& e) {
  switch (b.kind) {
    case BreakKind::Element:
      return b.element >= 0 && e.op != TraceOp::Phase && (e.element == b.element || e.other == b.element);
    case BreakKind::Cell:
      return b.cell[0] >= 0 && b.cell[1] >= 0 && e.op != TraceOp::TestPair && e.cell[0] == b.cell[0] &&
             e.cell[1] == b.cell[1] && e.cell[2] == b.cell[2];
    case BreakKind::List:
      if (e.op == TraceOp::Push) return e.writes[1].array == b.array && e.writes[1].index == b.list;
      if (e.op == TraceOp::Clear) return e.writes[0].array == b.array && e.writes[0].index == b.list;
      return false;
    case BreakKind::FirstPairOf:
      return b.element >= 0 && e.op == TraceOp::TestPair && (e.element == b.element || e.other == b.element);
  }
  return false;
}

void Stepper::clear() {
  trace_ = empty_trace();
  state_.clear();
  position_ = 0;
  checkpoints_.clear();
  phases_.clear();
  phase_of_.clear();
  last_write_.clear();
  next_of_heads_.clear();
  carry_ = 0;
  playing_ = false;
}

std::shared_ptr<const TraceLog> Stepper::empty_trace() {
  static const auto empty = std::make_shared<const TraceLog>();
  return empty;
}

void Stepper::load(TraceLog trace) { load(std::make_shared<const TraceLog>(std::move(trace))); }

void Stepper::load(std::shared_ptr<const TraceLog> trace) {
  clear();
  trace_ = trace ? std::move(trace) : empty_trace();
  const std::vector<TraceEvent>& ev = trace_->events();
  const std::vector<TracedArray>& arrays = trace_->arrays();

  std::size_t state_ints = 0;
  for (const TracedArray& a : arrays) state_ints += a.initial.size();
  // Checkpoint memory (size/interval copies of the state) stays within one int per event.
  interval_ = std::max(kMinCheckpointInterval, state_ints);

  ArrayState s = trace_->state_after(0);
  next_of_heads_.assign(arrays.size(), -1);
  phase_of_.resize(ev.size());
  last_write_.resize(ev.size());
  std::int32_t phase = -1, last_write = -1;
  try {
    for (std::size_t i = 0; i < ev.size(); ++i) {
      const TraceEvent& e = ev[i];
      if (i % interval_ == 0) checkpoints_.push_back(s);
      if (e.op == TraceOp::Phase) {
        phases_.push_back(PhaseMark{i, e.label, e.index});
        phase = static_cast<std::int32_t>(phases_.size()) - 1;
      }
      if (e.write_count > 2) throw Error("stepper: trace event " + std::to_string(i) + " claims more than two writes");
      for (int w = 0; w < e.write_count; ++w) {
        const ArrayWrite& a = e.writes[w];
        if (a.array < 0 || static_cast<std::size_t>(a.array) >= s.size() || a.index < 0 ||
            static_cast<std::size_t>(a.index) >= s[a.array].size()) {
          throw Error("stepper: trace event " + std::to_string(i) + " (" + op_name(e.op) +
                      ") writes outside the declared arrays (array " + std::to_string(a.array) + ", index " +
                      std::to_string(a.index) + ")");
        }
        std::int32_t& slot = s[a.array][static_cast<std::size_t>(a.index)];
        if (slot != a.old_value) {
          throw Error("stepper: trace event " + std::to_string(i) + " (" + op_name(e.op) + ") writes " +
                      arrays[a.array].name + "[" + std::to_string(a.index) + "] over " + std::to_string(a.old_value) +
                      " but the array holds " + std::to_string(slot) + " (the detector's trace is inconsistent)");
        }
        slot = a.new_value;
      }
      if (e.write_count > 0) last_write = static_cast<std::int32_t>(i);
      if (e.op == TraceOp::Push && e.write_count == 2 && next_of_heads_[e.writes[1].array] == -1)
        next_of_heads_[e.writes[1].array] = e.writes[0].array;
      phase_of_[i] = phase;
      last_write_[i] = last_write;
    }
  } catch (...) {
    clear();
    throw;
  }
  if (checkpoints_.empty()) checkpoints_.push_back(s);  // no events: the state is the initial one
  state_ = checkpoints_.front();
  position_ = 0;
}

const TraceEvent* Stepper::current() const { return position_ == 0 ? nullptr : &trace_->events()[position_ - 1]; }

void Stepper::restore_checkpoint(std::size_t n) {
  state_ = checkpoints_[n];
  position_ = n * interval_;
}

void Stepper::seek(std::size_t target) {
  const std::vector<TraceEvent>& ev = trace_->events();
  target = std::min(target, ev.size());
  const std::size_t distance = target > position_ ? target - position_ : position_ - target;
  if (distance > interval_ && !checkpoints_.empty())
    restore_checkpoint(std::min(target / interval_, checkpoints_.size() - 1));
  while (position_ < target) TraceLog::apply(ev[position_++], state_);
  while (position_ > target) TraceLog::undo(ev[--position_], state_);
}

bool Stepper::step_forward() {
  if (position_ >= size()) return false;
  TraceLog::apply(trace_->events()[position_++], state_);
  return true;
}

bool Stepper::step_back() {
  if (position_ == 0) return false;
  TraceLog::undo(trace_->events()[--position_], state_);
  return true;
}

std::int64_t Stepper::current_phase() const { return position_ == 0 ? -1 : phase_of_[position_ - 1]; }

void Stepper::seek_phase(std::size_t n) {
  if (n < phases_.size()) seek(phases_[n].event + 1);
}

bool Stepper::next_phase() {
  // The first phase whose event has not been applied yet; before anything, a phase marked at the
  // very first event is where the stepper already stands (its mark changes no array).
  const std::size_t from = position_ == 0 && !phases_.empty() && phases_.front().event == 0 ? 1 : position_;
  auto it = std::lower_bound(phases_.begin(), phases_.end(), from,
                             [](const PhaseMark& p, std::size_t pos) { return p.event < pos; });
  if (it == phases_.end()) return false;
  seek(it->event + 1);
  return true;
}

bool Stepper::prev_phase() {
  if (position_ == 0) return false;
  const std::size_t current_event = position_ - 1;
  // The last phase that begins strictly before the current event.
  auto it = std::lower_bound(phases_.begin(), phases_.end(), current_event,
                             [](const PhaseMark& p, std::size_t ev) { return p.event < ev; });
  if (it == phases_.begin()) return false;
  --it;
  seek(it->event + 1);
  return true;
}

std::optional<std::size_t> Stepper::find_next(const Breakpoint& b, std::size_t from) const {
  const std::vector<TraceEvent>& ev = trace_->events();
  for (std::size_t i = from; i < ev.size(); ++i)
    if (breakpoint_matches(b, ev[i])) return i;
  return std::nullopt;
}

std::optional<std::size_t> Stepper::find_prev(const Breakpoint& b, std::size_t before) const {
  const std::vector<TraceEvent>& ev = trace_->events();
  for (std::size_t i = std::min(before, ev.size()); i-- > 0;)
    if (breakpoint_matches(b, ev[i])) return i;
  return std::nullopt;
}

bool Stepper::run_to(const Breakpoint& b) {
  const auto hit = find_next(b, position_);
  if (!hit) return false;
  seek(*hit + 1);
  return true;
}

bool Stepper::run_back_to(const Breakpoint& b) {
  if (position_ == 0) return false;
  const auto hit = find_prev(b, position_ - 1);
  if (!hit) return false;
  seek(*hit + 1);
  return true;
}

void Stepper::set_speed(double events_per_second) {
  if (!std::isfinite(events_per_second)) return;
  speed_ = std::clamp(events_per_second, 0.01, 1e9);
}

void Stepper::play() {
  if (size() == 0) return;
  if (position_ == size()) seek(0);
  playing_ = true;
  carry_ = 0;
}

std::size_t Stepper::advance(double dt_seconds) {
  if (!playing_ || !(dt_seconds > 0) || !std::isfinite(dt_seconds)) return 0;
  const std::size_t remaining = size() - position_;
  carry_ += dt_seconds * speed_;
  const double whole = std::floor(carry_);
  carry_ -= whole;
  const std::size_t steps = whole >= static_cast<double>(remaining) ? remaining : static_cast<std::size_t>(whole);
  std::size_t target = position_ + steps;
  if (play_break_) {
    const std::vector<TraceEvent>& ev = trace_->events();
    for (std::size_t i = position_; i < target; ++i) {
      if (breakpoint_matches(*play_break_, ev[i])) {
        target = i + 1;
        playing_ = false;
        break;
      }
    }
  }
  const std::size_t stepped = target - position_;
  seek(target);
  if (position_ == size()) playing_ = false;
  if (!playing_) carry_ = 0;
  return stepped;
}

std::span<const ArrayWrite> Stepper::current_writes() const {
  const TraceEvent* e = current();
  if (e == nullptr) return {};
  return {e->writes, static_cast<std::size_t>(std::min<int>(e->write_count, 2))};
}

std::optional<std::size_t> Stepper::last_write_event() const {
  if (position_ == 0 || last_write_[position_ - 1] < 0) return std::nullopt;
  return static_cast<std::size_t>(last_write_[position_ - 1]);
}

LoopVars Stepper::loop_vars() const {
  LoopVars v;
  const TraceEvent* e = current();
  if (e == nullptr) return v;
  const std::int64_t p = current_phase();
  if (p >= 0) {
    v.phase = phases_[static_cast<std::size_t>(p)].label;
    v.phase_index = phases_[static_cast<std::size_t>(p)].index;
  }
  v.k = e->element;
  v.j = e->other;
  v.ix = e->cell[0];
  v.iy = e->cell[1];
  v.iz = e->cell[2];
  if ((e->op == TraceOp::Push && e->write_count == 2) || (e->op == TraceOp::Clear && e->write_count == 1)) {
    const ArrayWrite& head = e->writes[e->op == TraceOp::Push ? 1 : 0];
    v.list_kind = e->label;
    v.heads_array = head.array;
    v.list = head.index;
    v.head = state_[head.array][static_cast<std::size_t>(head.index)];
  }
  if (e->op == TraceOp::TestPair) {
    // The mask cell being scanned: the VisitCell of k just before this run of k's tests.
    const std::vector<TraceEvent>& ev = trace_->events();
    for (std::size_t i = position_ - 1; i-- > 0;) {
      if (ev[i].op == TraceOp::TestPair && ev[i].element == e->element) continue;
      if (ev[i].op == TraceOp::VisitCell && ev[i].element == e->element) {
        v.ix = ev[i].cell[0];
        v.iy = ev[i].cell[1];
        v.iz = ev[i].cell[2];
      }
      break;
    }
  }
  return v;
}

int Stepper::next_array_of(int heads_array) const {
  if (heads_array < 0 || static_cast<std::size_t>(heads_array) >= next_of_heads_.size()) return -1;
  return next_of_heads_[heads_array];
}

std::vector<std::int32_t> Stepper::list_members(int heads_array, std::int64_t list) const {
  std::vector<std::int32_t> out;
  const int next = next_array_of(heads_array);
  if (next < 0 || list < 0 || static_cast<std::size_t>(list) >= state_[heads_array].size()) return out;
  const std::vector<std::int32_t>& next_array = state_[next];
  for (std::int32_t k = state_[heads_array][static_cast<std::size_t>(list)];
       k >= 0 && static_cast<std::size_t>(k) < next_array.size() && out.size() < next_array.size();
       k = next_array[static_cast<std::size_t>(k)]) {
    out.push_back(k);
  }
  return out;
}

int Stepper::array_id(const std::string& name) const { return trace_->array_id(name); }

}  // namespace nbscope

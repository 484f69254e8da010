#include "ui/stepper_session.hpp"

#include <algorithm>
#include <exception>
#include <iterator>

#include "check/diagnosis.hpp"
#include "core/error.hpp"

namespace nbscope::ui {

namespace {
// One 64-bit key per cell (-1 components included, so rows and layers have keys of their own).
std::uint64_t cell_key(const std::int32_t c[3]) {
  const auto part = [](std::int32_t v) { return static_cast<std::uint64_t>(static_cast<std::uint32_t>(v + 1) & 0x1FFFFFu); };
  return part(c[0]) | (part(c[1]) << 21) | (part(c[2]) << 42);
}
}  // namespace

StepperSession::StepperSession(StepperConfig config)
    : book_numbering(config.book_numbering), pending_step_(config.step) {}

StepperSession::Key StepperSession::key_of(const SimView& sim) {
  return Key{sim.scene_path, sim.algorithm, sim.frame_number(), sim.elements != nullptr ? sim.elements->size() : -1};
}

bool StepperSession::current_for(const SimView& sim) const { return captured_ && key_ == key_of(sim); }

bool StepperSession::holds_elements(int array) const {
  return array >= 0 && static_cast<std::size_t>(array) < element_valued_.size() && element_valued_[array];
}

void StepperSession::update(const SimView& sim, double dt_seconds, int ui_frame) {
  if (ui_frame == last_frame_count_) return;
  last_frame_count_ = ui_frame;
  // A configured step (headless --step K) shows whatever frame is on screen; otherwise only a
  // paused frame is recorded, so a running simulation does not pay for tracing every frame.
  const bool target_here = target_ && target_->frame == sim.frame_number();
  const bool fresh = sim.trace ? sim.trace->serial != held_serial_ : !(key_ == key_of(sim));
  if (wants_trace(sim.frame_number(), sim.paused) && sim.elements != nullptr && fresh) capture(sim);
  if (target_here && (key_ == key_of(sim))) apply_target(sim);
  if (captured_) stepper_.advance(dt_seconds);
  was_current_ = current_for(sim);
}

bool StepperSession::wants_trace(std::int64_t frame, bool paused) const {
  return paused || capture_requested_ || pending_step_.has_value() || (target_ && target_->frame == frame);
}

void StepperSession::set_target(const PairTarget& target) {
  target_ = target;
  target_status_.clear();
  target_location_.reset();
}

void StepperSession::apply_target(const SimView& sim) {
  const PairTarget t = *target_;
  target_.reset();
  const bool book = book_numbering;
  // A dump's atoms by id, with the row beside it where it differs (the Stepper counts rows).
  const std::vector<std::int64_t>* ids = sim.ids();  // the target's frame is the one shown (update)
  const auto id = [&](std::int64_t k) {
    const std::int64_t row = shown(k, book);
    return ids != nullptr && k >= 0 && k < static_cast<std::int64_t>(ids->size()) ? element_label((*ids)[static_cast<std::size_t>(k)], row)
                                                                                  : std::to_string(row);
  };
  if (!captured_) {
    target_status_ = "stepper: " + (message_.empty() ? std::string("nothing recorded for frame ") + std::to_string(t.frame) : message_);
    return;
  }
  const Elements& e = elements();
  if (t.pair.i < 0 || t.pair.j < 0 || t.pair.i >= e.size() || t.pair.j >= e.size() || !has_trace_grid()) {
    target_status_ = "stepper: the pair is not among this frame's elements";
    return;
  }
  Violation v;
  v.frame = t.frame;
  v.pair = t.pair;
  v.invariant = t.invariant;
  v.what = t.what;
  const Diagnosis d = diagnose_frame(v, *trace_, id, book);  // the trace the stepper walks
  target_location_ = d.at;
  if (d.event) stepper_.seek(*d.event + 1);
  focus_element = t.pair.i;
  breakpoint.kind = BreakKind::FirstPairOf;
  breakpoint.element = t.pair.i;
  target_status_ = d.text;
}

bool StepperSession::seek_touching(BreakKind kind, std::int32_t element, const std::array<std::int32_t, 2>& cell, int direction,
                                   std::int32_t layer) {
  if (!captured_) return false;
  Breakpoint b;
  b.kind = kind;
  b.element = element;
  b.cell[0] = cell[0];
  b.cell[1] = cell[1];
  b.cell[2] = layer;
  stepper_.pause();
  const bool moved = direction > 0 ? stepper_.run_to(b) : stepper_.run_back_to(b);
  const std::string what = kind == BreakKind::Element ? "element " + std::to_string(shown(element, book_numbering))
                                                      : "cell (" + std::to_string(shown(cell[0], book_numbering)) + "," +
                                                            std::to_string(shown(cell[1], book_numbering)) +
                                                            (layer >= 0 ? "," + std::to_string(shown(layer, book_numbering)) : "") + ")";
  status = moved ? "" : std::string("no ") + (direction > 0 ? "later" : "earlier") + " operation on " + what;
  return moved;
}

std::optional<Eigen::Vector2d> StepperSession::focus_point() const {
  const TraceEvent* e = stepper_.current();
  if (e == nullptr) return std::nullopt;
  if (e->element >= 0 && e->element < elements().size()) {
    if (e->op == TraceOp::TestPair && e->other >= 0 && e->other < elements().size())
      return Eigen::Vector2d(0.5 * (elements().x[e->element] + elements().x[e->other]), 0.5 * (elements().y[e->element] + elements().y[e->other]));
    return Eigen::Vector2d(elements().x[e->element], elements().y[e->element]);
  }
  if (has_trace_grid() && e->cell[0] >= 0 && e->cell[1] >= 0) {
    const double d = trace_->grid.cell_size;
    return Eigen::Vector2d(trace_->grid.origin[0] + d * (e->cell[0] + 0.5), trace_->grid.origin[1] + d * (e->cell[1] + 0.5));
  }
  return std::nullopt;
}

std::optional<std::int32_t> StepperSession::current_axis(int axis) const {
  constexpr std::size_t kLookBack = 256;  // a phase's first cell is never far back; the cost stays per frame
  if (!captured_ || elements().dim != 3 || stepper_.position() == 0) return std::nullopt;
  const auto& events = stepper_.events();
  const std::int64_t phase = stepper_.current_phase();
  const std::size_t start = phase >= 0 ? stepper_.phases()[static_cast<std::size_t>(phase)].event : 0;
  if (phase >= 0 && events[start].cell[axis] >= 0) return events[start].cell[axis];
  for (std::size_t i = stepper_.position(); i-- > start && stepper_.position() - i <= kLookBack;)
    if (events[i].cell[axis] >= 0) return events[i].cell[axis];
  return std::nullopt;
}

void StepperSession::capture(const SimView& sim) {
  const std::size_t keep_position = stepper_.position();
  if (!target_ || target_->frame != sim.frame_number()) {
    target_status_.clear();  // it described another frame
    target_location_.reset();
  }
  if (!sim.trace && sim.elements != nullptr) {
    capture_requested_ = true;  // the app makes the trace for the next frame (wants_trace); the held one stays
    return;
  }
  capture_requested_ = false;
  key_ = key_of(sim);
  captured_ = false;
  message_.clear();
  stepper_.clear();
  element_valued_.clear();
  first_write_.clear();
  cell_pushes_.clear();
  tests_of_element_ = -1;
  tests_.clear();
  algorithm_ = sim.algorithm;
  frame_ = sim.frame_number();
  if (const std::vector<std::int64_t>* ids = sim.ids()) ids_ = *ids;
  else ids_.clear();
  trace_ = sim.trace;
  held_serial_ = trace_ ? trace_->serial : 0;
  if (sim.elements == nullptr) {
    message_ = "no scene loaded";
    trace_.reset();
    return;
  }
  if (!trace_->refusal.empty()) {
    message_ = trace_->refusal;
    return;
  }
  try {
    // The frame loop's own trace, shared: the lists overlay draws the same record.
    stepper_.load(std::shared_ptr<const TraceLog>(trace_, &trace_->log));
  } catch (const Error& err) {
    stepper_.clear();
    message_ = err.what();
    return;
  }
  const auto& arrays = stepper_.trace().arrays();
  element_valued_.assign(arrays.size(), false);
  for (std::size_t a = 0; a < arrays.size(); ++a) {
    const int next = stepper_.next_array_of(static_cast<int>(a));
    if (next >= 0) element_valued_[a] = element_valued_[static_cast<std::size_t>(next)] = true;
    if (arrays[a].name == "order") element_valued_[a] = true;  // sort's permutation of element ids
  }
  const auto& events = stepper_.events();
  first_write_.resize(arrays.size());
  for (std::size_t a = 0; a < arrays.size(); ++a)
    if (stepper_.next_array_of(static_cast<int>(a)) < 0) first_write_[a].assign(arrays[a].initial.size(), 0);
  for (std::size_t i = 0; i < events.size(); ++i) {
    const TraceEvent& ev = events[i];
    if (ev.op == TraceOp::Push) cell_pushes_.emplace_back(cell_key(ev.cell), i);
    for (int w = 0; w < ev.write_count && w < 2; ++w) {
      auto& first = first_write_[static_cast<std::size_t>(ev.writes[w].array)];
      const auto index = static_cast<std::size_t>(ev.writes[w].index);
      if (index < first.size() && first[index] == 0) first[index] = static_cast<std::uint32_t>(i + 1);
    }
  }
  std::sort(cell_pushes_.begin(), cell_pushes_.end());
  captured_ = true;
  // The next frame keeps the place in the sequence, so stepping frame by frame compares like with like.
  stepper_.seek(pending_step_.value_or(keep_position));
}

std::string StepperSession::element_text(std::int64_t k) const {
  const std::int64_t row = shown(k, book_numbering);
  if (k < 0 || static_cast<std::size_t>(k) >= ids_.size()) return std::to_string(row);
  return element_label(ids_[static_cast<std::size_t>(k)], row);
}

bool StepperSession::is_set_after(int array, std::int64_t index, std::size_t position) const {
  if (array < 0 || static_cast<std::size_t>(array) >= first_write_.size()) return true;
  const auto& first = first_write_[static_cast<std::size_t>(array)];
  if (first.empty() || index < 0 || static_cast<std::size_t>(index) >= first.size()) return true;  // a heads array
  const std::uint32_t f = first[static_cast<std::size_t>(index)];
  return f != 0 && f <= position;
}

std::optional<StepperSession::ListRef> StepperSession::list_of_cell(const std::int32_t cell[3]) const {
  const std::uint64_t key = cell_key(cell);
  // The latest push onto the cell among the events applied so far.
  auto it = std::lower_bound(cell_pushes_.begin(), cell_pushes_.end(), std::make_pair(key, stepper_.position()));
  if (it == cell_pushes_.begin() || std::prev(it)->first != key) return std::nullopt;
  const TraceEvent& e = stepper_.events()[std::prev(it)->second];
  return ListRef{e.writes[1].array, e.writes[1].index, e.label};
}

const std::vector<StepperSession::TestedPair>& StepperSession::tests_of(std::int32_t k) {
  if (k != tests_of_element_) {
    tests_.clear();
    tests_of_element_ = k;
    const auto& events = stepper_.events();
    for (std::size_t i = 0; i < events.size(); ++i) {
      const TraceEvent& e = events[i];
      if (e.op != TraceOp::TestPair || (e.element != k && e.other != k)) continue;
      tests_.push_back(TestedPair{i, e.element == k ? e.other : e.element, e.contact});
    }
  }
  return tests_;
}

bool index_is_selector(const TracedArray& array, std::size_t dim) {
  if (array.shape.size() != 2) return false;
  if (dim == 0) return (array.name == "B" || array.name == "A") && array.shape[0] <= 5;
  return array.name == "child" && array.shape[1] == 2;
}

bool is_cell_matrix(const TracedArray& array, const Grid* grid) {
  if (grid == nullptr || array.shape.size() < 2 || array.shape.size() > 3 || index_is_selector(array, 0) || index_is_selector(array, 1))
    return false;
  for (std::size_t a = 0; a < array.shape.size(); ++a)
    if (array.shape[a] != grid->n[a]) return false;
  return true;
}

std::string entry_name(const TracedArray& array, std::int64_t flat, bool book) {
  std::string out = array.name;
  if (array.shape.size() <= 1) return out + "[" + std::to_string(shown(flat, book)) + "]";
  std::vector<std::int64_t> idx(array.shape.size());
  for (std::size_t d = array.shape.size(); d-- > 0;) {
    const std::int64_t side = std::max<std::int64_t>(array.shape[d], 1);
    idx[d] = flat % side;
    flat /= side;
  }
  for (std::size_t d = 0; d < idx.size(); ++d)
    out += "[" + std::to_string(shown(idx[d], book && !index_is_selector(array, d))) + "]";
  return out;
}

std::int64_t shown_value(const StepperSession& session, int array, std::int32_t value) {
  return session.holds_elements(array) ? shown(value, session.book_numbering) : value;
}

ElementEntries element_entries(const StepperSession& s, std::int32_t k) {
  const bool book = s.book_numbering;
  const Stepper& st = s.stepper();
  const auto& arrays = st.trace().arrays();
  std::vector<bool> is_next(arrays.size(), false);
  for (std::size_t a = 0; a < arrays.size(); ++a)
    if (const int n = st.next_array_of(static_cast<int>(a)); n >= 0) is_next[static_cast<std::size_t>(n)] = true;
  const auto entry = [&](std::size_t a, std::int64_t index) {
    const int id = static_cast<int>(a);
    return entry_name(arrays[a], index, book) + " = " +
           (s.is_set(id, index) ? std::to_string(shown_value(s, id, st.state()[a][static_cast<std::size_t>(index)]))
                                : std::string("\xC2\xB7"));
  };
  const auto add = [](std::string& list, const std::string& item) { list += (list.empty() ? "" : ",  ") + item; };
  ElementEntries out;
  if (k < 0 || k >= s.elements().size()) return out;
  for (std::size_t a = 0; a < arrays.size(); ++a) {
    const std::vector<std::int32_t>& values = st.state()[a];
    if (arrays[a].shape.size() != 1 || static_cast<std::int64_t>(values.size()) != s.elements().size()) continue;
    const int id = static_cast<int>(a);
    if (is_next[a]) {
      add(out.next, entry(a, k));
    } else if (st.next_array_of(id) >= 0) {
      continue;  // a heads array that happens to have N entries
    } else if (s.holds_elements(id)) {
      std::int64_t p = -1;
      for (std::size_t i = 0; i < values.size() && p < 0; ++i)
        if (values[i] == k && s.is_set(id, static_cast<std::int64_t>(i))) p = static_cast<std::int64_t>(i);
      add(out.position, p >= 0 ? entry(a, p) : "not in " + arrays[a].name + " yet");
    } else {
      add(out.own, entry(a, k));
    }
  }
  return out;
}

std::string describe_event(const StepperSession& session, const TraceEvent& e) {
  const bool book = session.book_numbering;
  const auto& arrays = session.stepper().trace().arrays();
  const auto id = [&](std::int64_t k) { return std::to_string(shown(k, book)); };
  const auto value = [&](int array, std::int32_t v) { return std::to_string(shown_value(session, array, v)); };
  const auto name = [&](const ArrayWrite& w) {
    return w.array >= 0 && static_cast<std::size_t>(w.array) < arrays.size() ? entry_name(arrays[w.array], w.index, book)
                                                                              : std::string("?");
  };
  const auto cell = [&] {
    std::string c = "(" + id(e.cell[0]) + "," + id(e.cell[1]);
    if (e.cell[2] >= 0) c += "," + id(e.cell[2]);
    return c + ")";
  };
  switch (e.op) {
    case TraceOp::Phase:
      return std::string("phase: ") + e.label + (e.index >= 0 ? " " + id(e.index) : std::string());
    case TraceOp::Push: {
      const ArrayWrite& next = e.writes[0];
      const ArrayWrite& head = e.writes[1];
      return "push k=" + session.element_text(e.element) + " onto " + e.label + " " + name(head) + ": " + name(next) + " = " +
             value(next.array, next.new_value) + ", " + name(head) + " = " + value(head.array, head.new_value);
    }
    case TraceOp::Clear: {
      const ArrayWrite& head = e.writes[0];
      return std::string("clear ") + e.label + " " + name(head) + " (head was " + value(head.array, head.old_value) +
             "): " + name(head) + " = -1";
    }
    case TraceOp::VisitCell:
      return "k=" + session.element_text(e.element) + ": visit cell " + cell() + " of the contact mask";
    case TraceOp::TestPair:
      return "test k=" + session.element_text(e.element) + " against " + session.element_text(e.other) + ": " +
             (e.contact ? "contact" : "no contact");
    default:
      break;
  }
  // Any other write (sort's keys and permutation, tree links): name, new value, old value ("unset"
  // when the entry had not been written before, as the Arrays panel says).
  const auto& events = session.stepper().events();
  const bool in_trace = !events.empty() && &e >= events.data() && &e < events.data() + events.size();
  const std::size_t at = in_trace ? static_cast<std::size_t>(&e - events.data()) : 0;
  std::string out = std::string(e.label) + ": ";
  for (int w = 0; w < e.write_count && w < 2; ++w) {
    const ArrayWrite& wr = e.writes[w];
    const bool was_set = !in_trace || session.is_set_after(wr.array, wr.index, at);
    if (w > 0) out += ", ";
    out += name(wr) + " = " + value(wr.array, wr.new_value) + " (was " + (was_set ? value(wr.array, wr.old_value) : "unset") + ")";
  }
  if (e.element >= 0) out += " for k=" + session.element_text(e.element);
  return out;
}

std::string phase_text(const StepperSession& session, std::size_t phase) {
  const Stepper& st = session.stepper();
  if (phase >= st.phases().size()) return "";
  const PhaseMark& mark = st.phases()[phase];
  const bool book = session.book_numbering;
  std::string name = mark.label;
  if (mark.index >= 0) name += " " + std::to_string(shown(mark.index, book));
  const TraceEvent& e = st.events()[mark.event];
  if (e.cell[1] >= 0 && e.cell[2] >= 0) name += ", layer " + std::to_string(shown(e.cell[2], book));  // a row of a 3D pass
  return name;
}

std::string array_shapes_text(const StepperSession& session) {
  const Grid* grid = session.grid();
  const std::int64_t n = session.elements().size();
  const auto& arrays = session.stepper().trace().arrays();
  std::string out;
  for (const TracedArray& a : arrays) {
    std::string text = a.name;
    for (std::size_t d = 0; d < a.shape.size(); ++d) {
      const std::int64_t extent = a.shape[d];
      std::string axis;
      if (index_is_selector(a, d)) {
        axis = std::to_string(extent);
      } else if (a.shape.size() == 1 && extent == n && session.stepper().next_array_of(session.stepper().array_id(a.name)) < 0) {
        axis = "N=" + std::to_string(extent);  // indexed by element
      } else if (grid != nullptr) {
        // The cell axis of this extent: the last index of a heads array is its own axis (C[nz],
        // B[..][ny], A[..][nx] in NBS 3D, whose lists run z, then y, then x; 2D's B[2][nx]); a matrix's are x, y, z.
        const int from_name = a.name == "C" && a.shape.size() == 1 ? 2 : a.name == "B" ? (session.elements().dim == 3 ? 1 : 0) : a.name == "A" ? 0 : -1;
        const int ax = a.shape.size() == 1 || index_is_selector(a, 0) ? from_name : static_cast<int>(d);
        if (ax >= 0 && ax < 3 && grid->n[ax] == extent) axis = std::string("n") + "xyz"[ax] + "=" + std::to_string(extent);
      }
      text += "[" + (axis.empty() ? std::to_string(extent) : axis) + "]";
    }
    out += (out.empty() ? "" : "  ") + text;
  }
  return out;
}

std::string idle_message(const StepperSession& session) {
  if (!session.message().empty()) return session.message();
  return "nothing recorded yet: pause (P) to record this frame's operations";
}

std::pair<std::int64_t, std::int64_t> window_range(std::int64_t length, std::int64_t focus, std::int64_t width) {
  if (length <= 0 || width <= 0) return {0, 0};
  if (length <= width) return {0, length};
  focus = std::clamp<std::int64_t>(focus, 0, length - 1);
  const std::int64_t begin = std::clamp<std::int64_t>(focus - width / 2, 0, length - width);
  return {begin, begin + width};
}

}  // namespace nbscope::ui

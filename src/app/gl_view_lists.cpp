// The lists overlay's part of GlView: the lists rebuilt from the frame loop's one trace (as they
// stand at the stepper's operation while it is mid-way), and what the overlay is told to highlight,
// filter and say in the legend.
#include "app/clock.hpp"
#include "check/recorded_lane.hpp"
#include "app/gl_view.hpp"

namespace nbscope {

namespace {
// Traces longer than this are replayed for the lists at most every kReplayIntervalMs while playing.
constexpr std::size_t kReplayEveryFrameUpTo = 200'000;
constexpr double kReplayIntervalMs = 150;
// The legend's lines are about this many characters wide: a longer reason wraps.
constexpr std::size_t kCaptionChars = 52;
}  // namespace

void GlView::update_lists(const FrameLoop& loop, const std::shared_ptr<const FrameTrace>& trace) {
  if (!state_.overlays.lists || !trace) {
    lists_.lists.clear();
    lists_.serial = 0;
    return;
  }
  // Mid-trace, the lists as they stand at the stepper's operation; else the finished ones.
  std::size_t upto = SIZE_MAX;
  const Stepper& st = stepper_->stepper();
  if (stepper_panels_open() && stepper_->has_capture() && stepper_->frame_trace() == trace && st.position() < st.size())
    upto = st.position();
  if (lists_.serial == trace->serial && lists_.upto == upto) return;
  // Each rebuild replays the trace from its start: while the stepper plays through a long trace,
  // at most a few rebuilds a second (the overlay catches up when playback stops).
  if (lists_.serial == trace->serial && st.playing() && trace->log.events().size() > kReplayEveryFrameUpTo &&
      ms_since(lists_.built_at) < kReplayIntervalMs)
    return;
  const auto t0 = Clock::now();
  lists_.built_at = t0;
  lists_.lists = traced_lists(trace->log, static_cast<std::size_t>(loop.source().elements().size()), upto);
  lists_.serial = trace->serial;
  lists_.upto = upto;
  cost_.trace_ms += ms_since(t0);
}

void GlView::describe_lists(const FrameLoop& loop, const std::shared_ptr<const FrameTrace>& trace,
                            render::OverlayScene& scene) const {
  const Elements& e = loop.source().elements();
  const bool book = state_.book_numbering;
  const auto num = [&](std::int64_t v) { return std::to_string(ui::shown(v, book)); };
  scene.list_filter = state_.list_filter.value_or(e.size() > render::kRowFilterAbove ? render::ListFilter::Row
                                                                                       : render::ListFilter::All);
  // The stepper's current operation, when it holds this frame's trace and is not at its end.
  const Stepper& st = stepper_->stepper();
  const bool stepping = stepper_panels_open() && stepper_->has_capture() && trace && stepper_->frame_trace() == trace &&
                        st.position() < st.size();
  std::optional<std::int32_t> stepper_row;
  if (stepping && st.current() != nullptr) {
    const TraceEvent& ev = *st.current();
    if (ev.op == TraceOp::Push) scene.active_list = std::make_pair(ev.writes[1].array, ev.writes[1].index);
    if (ev.op == TraceOp::Clear) scene.active_list = std::make_pair(ev.writes[0].array, ev.writes[0].index);
    if (ev.op == TraceOp::VisitCell || ev.op == TraceOp::TestPair)
      if (const auto l = stepper_->list_of_cell(ev.cell)) scene.active_list = std::make_pair(l->heads, l->list);
    if (ev.op == TraceOp::TestPair && ev.element >= 0 && ev.other >= 0) {
      scene.tested_pair = Pair{std::min(ev.element, ev.other), std::max(ev.element, ev.other)};
      scene.tested_contact = ev.contact;
    }
    const LoopVars v = st.loop_vars();
    if (e.dim == 3) {
      // NBS 3D's phases are of a layer (index iz) or of a row (index iy): the row is the phase's, not its index.
      stepper_row = stepper_->current_row();
    } else if (v.phase_index >= 0 || v.iy >= 0) {
      stepper_row = v.phase_index >= 0 ? v.phase_index : v.iy;
    }
  }
  // The row whose lists the Row filter keeps (render::list_focus_row: the stepper's mid-frame first).
  std::optional<std::int32_t> selected_row;
  if (state_.selected >= 0 && state_.selected < e.size()) selected_row = loop.result().selected().grid.cell(e.y[state_.selected], 1);
  scene.focus_row = render::list_focus_row(stepper_row, state_.hovered_cell, selected_row);
  if (!state_.overlays.lists) return;
  auto& caption = scene.lists_caption;
  if (!trace || lists_.lists.empty()) {
    const bool has_lists = algorithm_info(loop.pipeline().algorithm()).has_lists;
    const std::string why = trace && !trace->refusal.empty() ? trace->refusal
                            : !has_lists && !stepping ? "it keeps no heads or next arrays, only its tests"
                                                      : "";
    caption.push_back("lists: " + loop.pipeline().algorithm() + (stepping ? " has built none yet" : " builds none") + (why.empty() ? "" : ":"));
    // The reason, wrapped to the legend's width.
    std::string line;
    std::size_t start = 0;
    while (start < why.size()) {
      const std::size_t space = std::min(why.find(' ', start), why.size());
      const std::string word = why.substr(start, space - start);
      if (!line.empty() && line.size() + 1 + word.size() > kCaptionChars) {
        caption.push_back("  " + line);
        line.clear();
      }
      line += (line.empty() ? "" : " ") + word;
      start = space + 1;
    }
    if (!line.empty()) caption.push_back("  " + line);
    return;
  }
  if (stepping) caption.push_back("lists at operation " + std::to_string(st.position()) + " of " + std::to_string(st.size()) + " (Stepper)");
  switch (scene.list_filter) {
    case render::ListFilter::All: break;
    case render::ListFilter::Selected:
      caption.push_back(scene.selected >= 0 ? "lists holding element " + num(scene.selected)
                                            : "lists filter 'selected': click an element");
      break;
    case render::ListFilter::Row:
      caption.push_back(scene.focus_row ? "lists of row " + num(*scene.focus_row) + " (filter 'row': hover a row)"
                                        : e.size() <= render::kAllListsUpTo ? "all lists: hover a row or click an element for one row's"
                                                                            : "no lists drawn: hover a row or click an element to choose one");
      break;
  }
}

}  // namespace nbscope

// nbscope core: a plugin's trace table mapped into the TraceLog (plugin_call.hpp). The header's model
// is "call after the write": each declared array has a shadow copy, so a call that names entries
// reads their new values from the plugin's live array and their old ones from the shadow, records
// the write as it really happened (a buggy push that wrote next[k] = -1 is recorded so), and then
// updates the shadow. Every callback checks what it is told and never throws.
//
// The same table serves the walk check of an untraced checked frame (PluginCall::walks, log null):
// every call is still validated, visits and tests feed the check, and nothing is recorded. A call
// that breaks a rule ends the plugin's call there (end_at_breach), as a list closed on itself does.
#include <cassert>
#include <mutex>
#include <set>
#include <string_view>

#include "core/plugin_call.hpp"
#include "core/plugin_detector.hpp"

namespace nbscope {

namespace {

// Most entries one declared array may have (int32 indices in TraceEvent; within memory).
constexpr std::int64_t kMaxDeclaredEntries = std::int64_t{1} << 30;

std::string number(std::int64_t v) { return std::to_string(v); }

PluginCall& call_of(void* ctx) { return *static_cast<PluginCall*>(ctx); }

// The line as the TraceLog keeps it, or a breach when it is not one of the plugin's lines.
bool line_ok(PluginCall& call, const char* what, std::int32_t line) {
  if (line >= 0 && line < call.lines) return true;
  call.breach_with(std::string("trace ") + what + ": line " + number(line) + " is not one of the " + number(call.lines) +
                   " pseudocode lines");
  return false;
}

bool array_ok(PluginCall& call, const char* what, std::int32_t array) {
  if (array >= 0 && static_cast<std::size_t>(array) < call.arrays.size()) return true;
  call.breach_with(std::string("trace ") + what + ": array " + number(array) + " was not declared (" +
                   number(static_cast<std::int64_t>(call.arrays.size())) + " declared)");
  return false;
}

bool entry_ok(PluginCall& call, const char* what, const char* role, std::int32_t array, std::int64_t index) {
  const std::int64_t size = call.arrays[static_cast<std::size_t>(array)].size;
  if (index >= 0 && index < size) return true;
  call.breach_with(std::string("trace ") + what + ": " + role + " " + number(index) + " is outside array " +
                   number(array) + " of " + number(size) + " entries");
  return false;
}

bool element_ok(PluginCall& call, const char* what, std::int32_t k, bool none_allowed) {
  if ((k >= 0 && k < call.n) || (none_allowed && k == -1)) return true;
  call.breach_with(std::string("trace ") + what + ": element " + number(k) + " is out of range [0, " + number(call.n) + ")");
  return false;
}

// The write of entry `index` of `array`: old (the shadow) and new (live); the shadow takes the new.
std::pair<std::int32_t, std::int32_t> take_write(PluginCall& call, std::int32_t array, std::int64_t index) {
  PluginCall::Array& a = call.arrays[static_cast<std::size_t>(array)];
  const auto i = static_cast<std::size_t>(index);
  const std::int32_t old_value = a.shadow[i];
  a.shadow[i] = a.live[i];
  return {old_value, a.shadow[i]};
}

// "17 -> 42 -> 17": the list of `next` from k, as the plugin's live array holds it, up to k again.
std::string chain_from(const PluginCall& call, std::int32_t next, std::int32_t k) {
  const PluginCall::Array& a = call.arrays[static_cast<std::size_t>(next)];
  std::string out = number(k);
  std::int32_t at = k;
  for (int step = 0; step < 16; ++step) {
    if (at < 0 || at >= a.size) return out;
    at = a.live[at];
    out += " -> " + number(at);
    if (at == k || at == -1) return out;
  }
  return out + " -> ...";
}

// Notes the push of k onto slot `list` of heads array `heads`; true (the breach kept) when k is on that
// build of the list already: the list now closes on itself.
bool closes_list(PluginCall& call, const char* kind, std::int32_t heads, std::int64_t list, std::int32_t next, std::int32_t k) noexcept {
  try {
    auto& all = call.lists.heads;
    if (all.size() <= static_cast<std::size_t>(heads)) all.resize(static_cast<std::size_t>(heads) + 1);
    PluginCall::ListWatch::Heads& h = all[static_cast<std::size_t>(heads)];
    if (h.build.empty()) {
      h.build.assign(static_cast<std::size_t>(call.arrays[static_cast<std::size_t>(heads)].size), 0);
      h.slot_of.assign(static_cast<std::size_t>(call.n), -1);
      h.build_of.assign(static_cast<std::size_t>(call.n), 0);
    }
    const auto slot = static_cast<std::size_t>(list);
    const auto e = static_cast<std::size_t>(k);
    if (h.slot_of[e] == list && h.build_of[e] == h.build[slot]) {
      const std::string array = call.log != nullptr ? call.log->arrays()[static_cast<std::size_t>(heads)].name : "array " + number(heads);
      call.breach_with("cycle: " + cut_plugin_text(kind != nullptr && *kind != '\0' ? kind : "list") + " " + array + "[" + number(list) + "] runs " +
                       chain_from(call, next, k) + ": " + number(k) + " is pushed onto it a second time with no clear between " +
                       "(nbscope stopped the call: a walk of it would never end)");
      call.subject = Pair{k, k};
      call.cycle = true;
      return true;
    }
    h.slot_of[e] = list;
    h.build_of[e] = h.build[slot];
  } catch (...) {
    call.keep_exception();
  }
  return false;
}

// Notes the clear of slot `list` of heads array `heads`: a new build of that list begins.
void list_cleared(PluginCall& call, std::int32_t heads, std::int64_t list) noexcept {
  auto& all = call.lists.heads;
  if (static_cast<std::size_t>(heads) < all.size() && !all[static_cast<std::size_t>(heads)].build.empty())
    ++all[static_cast<std::size_t>(heads)].build[static_cast<std::size_t>(list)];
}

// Notes the test of `other` in k's current walk; true (the breach kept) when the walk met it before:
// the list it follows closes on itself.
bool walk_repeats(PluginCall& call, std::int32_t k, std::int32_t other) noexcept {
  PluginCall::ListWatch& w = call.lists;
  if (w.seen.empty() || call.walks.visitor != k) return false;
  const auto e = static_cast<std::size_t>(other);
  if (w.seen[e] != w.walk) {
    w.seen[e] = w.walk;
    if (w.walked.size() < PluginCall::ListWatch::kShown) w.walked.push_back(other);
    return false;
  }
  try {
    std::string chain;
    bool from = false;
    for (const std::int32_t m : w.walked) {
      from = from || m == other;
      if (from) chain += number(m) + " -> ";
    }
    call.breach_with("cycle: the walk of cell (" + number(call.walks.visited.ix) + "," + number(call.walks.visited.iy) + ")'s list for " +
                     number(k) + " runs " + (from ? chain : "... -> ") + number(other) +
                     ": the list closes on itself (nbscope stopped the call: the walk would never end)");
    call.subject = Pair{std::min(k, other), std::max(k, other)};
    call.cycle = true;
  } catch (...) {
    call.keep_exception();
  }
  return true;
}

// Ends the plugin's call at a trace call that broke a rule (the breach kept), as a cycle does: what the
// plugin does next runs on what it got wrong (an element out of range, an index past an array), most
// often into a crash that would hide the first bug. No object of the callback is alive here.
void end_at_breach(PluginCall& call) noexcept {
  if (call.escape != nullptr && !call.breach.empty() && !call.exception) call.stop_call();
}

// Runs `record` unless the call already stopped, keeping any exception it throws.
template <class F>
void guarded(PluginCall& call, F&& record) {
  if (call.stopped() || call.log == nullptr) return;
  try {
    record();
  } catch (...) {
    call.keep_exception();
  }
}

}  // namespace

const char* intern_plugin_label(const char* text) {
  if (text == nullptr) return "";
  static std::mutex mutex;
  static std::set<std::string, std::less<>> labels;  // nodes never move: c_str() stays valid
  std::string cut;
  std::string_view view(text);
  if (view.size() > kMaxPluginTextBytes) {  // a bounded label, however long the plugin's
    cut = cut_plugin_text(text);
    view = cut;
  }
  const std::lock_guard<std::mutex> lock(mutex);
  auto found = labels.find(view);
  if (found == labels.end()) found = labels.emplace(view).first;
  return found->c_str();
}

extern "C" {
static int nbscope_plugin_declare_array(void* ctx, const char* name, std::int32_t rank, const std::int64_t* shape,
                                        const std::int32_t* data) {
  PluginCall& call = call_of(ctx);
  if (call.stopped()) return -1;
  if (name == nullptr || *name == '\0') {  // the Arrays panel and dump name arrays by it
    call.breach_with(std::string("trace declare_array: array ") + number(static_cast<std::int64_t>(call.arrays.size())) +
                     "'s name is " + (name == nullptr ? "NULL" : "empty") + " (name it as the book does: heads, next, ...)");
    end_at_breach(call);
    return -1;
  }
  if (rank < 1 || rank > 3 || shape == nullptr) {
    call.breach_with("trace declare_array: rank " + number(rank) + (shape == nullptr ? " with no shape" : "") +
                     " (from 1 to 3, with a shape)");
    end_at_breach(call);
    return -1;
  }
  std::int64_t size = 1;
  for (std::int32_t a = 0; a < rank; ++a) {
    if (shape[a] < 0 || shape[a] > kMaxDeclaredEntries || size * shape[a] > kMaxDeclaredEntries) {
      call.breach_with("trace declare_array: shape entry " + number(a) + " is " + number(shape[a]) +
                       ", or the array is over " + number(kMaxDeclaredEntries) + " entries");
      end_at_breach(call);
      return -1;
    }
    size *= shape[a];
  }
  if (size > 0 && data == nullptr) {
    call.breach_with("trace declare_array: data is NULL for " + number(size) + " entries");
    end_at_breach(call);
    return -1;
  }
  const auto id = static_cast<int>(call.arrays.size());
  try {
    PluginCall::Array array{data, size, {}};
    if (call.log != nullptr) {
      const std::span<const std::int32_t> contents(data, static_cast<std::size_t>(size));
      const int logged = call.log->declare_array(cut_plugin_text(name), std::vector<std::int64_t>(shape, shape + rank), contents);
      assert(logged == id && "a plugin's arrays and the trace's are declared in step");
      (void)logged;
      array.shadow.assign(contents.begin(), contents.end());
    }
    call.arrays.push_back(std::move(array));
  } catch (...) {
    call.keep_exception();
  }
  return call.stopped() ? -1 : id;
}

static void nbscope_plugin_phase(void* ctx, std::int32_t line, const char* label, std::int32_t index) {
  PluginCall& call = call_of(ctx);
  if (call.stopped()) return;
  if (!line_ok(call, "phase", line)) return end_at_breach(call);
  guarded(call, [&] { call.log->phase(static_cast<std::uint8_t>(line), intern_plugin_label(label), index); });
  call.advance(TraceOp::Phase, line);
}

static void nbscope_plugin_push(void* ctx, std::int32_t line, const char* kind, std::int32_t heads, std::int64_t list,
                                std::int32_t next, std::int32_t k, std::int32_t ix, std::int32_t iy, std::int32_t iz) {
  PluginCall& call = call_of(ctx);
  if (call.stopped()) return;
  if (!line_ok(call, "push", line) || !array_ok(call, "push", heads) || !array_ok(call, "push", next) ||
      !entry_ok(call, "push", "list", heads, list) || !element_ok(call, "push", k, false) ||
      !entry_ok(call, "push", "element", next, k))
    return end_at_breach(call);
  guarded(call, [&] {
    const auto [old_next, new_next] = take_write(call, next, k);
    const auto [old_head, new_head] = take_write(call, heads, list);
    call.log->push_written(static_cast<std::uint8_t>(line), intern_plugin_label(kind), heads, list, next, k, old_head,
                           old_next, new_head, new_next, ix, iy, iz);
  });
  call.advance(TraceOp::Push, line);
  if (call.escape != nullptr && !call.stopped() && closes_list(call, kind, heads, list, next, k)) call.stop_call();
}

static void nbscope_plugin_clear(void* ctx, std::int32_t line, const char* kind, std::int32_t heads, std::int64_t list) {
  PluginCall& call = call_of(ctx);
  if (call.stopped()) return;
  if (!line_ok(call, "clear", line) || !array_ok(call, "clear", heads) || !entry_ok(call, "clear", "list", heads, list))
    return end_at_breach(call);
  guarded(call, [&] {
    const auto [old_head, new_head] = take_write(call, heads, list);
    call.log->clear_written(static_cast<std::uint8_t>(line), intern_plugin_label(kind), heads, list, old_head, new_head);
  });
  call.advance(TraceOp::Clear, line);
  list_cleared(call, heads, list);
}

static void nbscope_plugin_visit_cell(void* ctx, std::int32_t line, std::int32_t k, std::int32_t ix, std::int32_t iy,
                                      std::int32_t iz) {
  PluginCall& call = call_of(ctx);
  if (call.stopped()) return;
  if (!line_ok(call, "visit_cell", line) || !element_ok(call, "visit_cell", k, false)) return end_at_breach(call);
  call.walks.visitor = k;
  call.walks.visited = CellIndex{ix, iy};
  ++call.lists.walk;
  call.lists.walked.clear();
  guarded(call, [&] { call.log->visit_cell(static_cast<std::uint8_t>(line), k, ix, iy, iz); });
  call.advance(TraceOp::VisitCell, line);
}

static void nbscope_plugin_test_pair(void* ctx, std::int32_t line, std::int32_t k, std::int32_t other,
                                     std::int32_t contact) {
  PluginCall& call = call_of(ctx);
  if (call.stopped()) return;
  if (!line_ok(call, "test_pair", line) || !element_ok(call, "test_pair", k, false) || !element_ok(call, "test_pair", other, false))
    return end_at_breach(call);
  call.check_walk(k, other);
  guarded(call, [&] { call.log->test_pair(static_cast<std::uint8_t>(line), k, other, contact != 0); });
  call.advance(TraceOp::TestPair, line);
  if (call.escape != nullptr && walk_repeats(call, k, other)) call.stop_call();
}

static void nbscope_plugin_set(void* ctx, std::int32_t line, const char* label, std::int32_t array, std::int64_t index,
                               std::int32_t k) {
  PluginCall& call = call_of(ctx);
  if (call.stopped()) return;
  if (!line_ok(call, "set", line) || !array_ok(call, "set", array) || !entry_ok(call, "set", "index", array, index) ||
      !element_ok(call, "set", k, true))
    return end_at_breach(call);
  guarded(call, [&] {
    const auto [old_value, new_value] = take_write(call, array, index);
    call.log->set(static_cast<std::uint8_t>(line), intern_plugin_label(label), array, index, old_value, new_value, k);
  });
  call.advance(TraceOp::Set, line);
}
}  // extern "C"

nbscope_trace plugin_trace_table(PluginCall& call) {
  return nbscope_trace{&call,
                       nbscope_plugin_declare_array,
                       nbscope_plugin_phase,
                       nbscope_plugin_push,
                       nbscope_plugin_clear,
                       nbscope_plugin_visit_cell,
                       nbscope_plugin_test_pair,
                       nbscope_plugin_set};
}

}  // namespace nbscope

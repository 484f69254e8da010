// nbscope core: one call of a plugin's nbscope_detect as its callbacks see it (the ctx of the output
// and trace tables). Private to plugin_detector.cpp and plugin_trace.cpp.
#pragma once
#include <nbscope/detector.h>

#include <csetjmp>
#include <cstdint>
#include <exception>
#include <string>
#include <vector>

#include "core/detector.hpp"
#include "core/elements.hpp"
#include "core/grid.hpp"
#include "core/pairs.hpp"
#include "core/plugin_detector.hpp"
#include "core/trace.hpp"

namespace nbscope {

// What the callbacks of one nbscope_detect call share; the first breach stops every later callback.
struct PluginCall {
  // One declared array: where the plugin keeps it and what nbscope last knew it to hold.
  struct Array {
    const std::int32_t* live = nullptr;
    std::int64_t size = 0;
    std::vector<std::int32_t> shadow;  // traced: contents before the writes the plugin has not yet described
  };

  // The walk check (DetectOptions::check_walks): each test against the cell its walk visited.
  struct Walks {
    WalkCheck* out = nullptr;                           // null: not checked
    const Grid* grid = nullptr;                         // the grid's cell of an element, when asked
    const Elements* elements = nullptr;
    const std::int32_t* own_cells = nullptr;             // the plugin's out->cells (n * 2), or null
    std::int32_t visitor = -1;                           // the element of the last visit_cell
    CellIndex visited;                                   // and the cell it visited
  };

  // What the call's pushes and walks did so far, to stop it where a list closes on itself (a walk of
  // it would never end): an element pushed twice onto one build of a list, a walk meeting an element twice.
  struct ListWatch {
    struct Heads {
      std::vector<std::uint32_t> build;     // per slot: bumped by every clear
      std::vector<std::int64_t> slot_of;    // per element: the slot of its last push (-1: none)
      std::vector<std::uint32_t> build_of;  // and that slot's build then
    };
    std::vector<Heads> heads;             // by array id; empty until the array is pushed onto
    std::vector<std::uint32_t> seen;      // per element: the walk that last tested it
    std::uint32_t walk = 0;               // the current walk (one per visit_cell)
    std::vector<std::int32_t> walked;     // its elements so far, in order (the first kShown)
    static constexpr std::size_t kShown = 64;
  };

  // add_pair writes at `next` into `pairs`, sized to its capacity for the call (then cut to given()).
  // One test per pair: at `stop` (the end of the buffer, the pair limit, or `next` once stopped) a
  // call goes the slow way, which grows the buffer or says stop.
  PairList* pairs = nullptr;
  Pair* next = nullptr;
  Pair* stop = nullptr;
  std::size_t max_pairs = 0;
  std::int64_t n = 0;
  bool limit_hit = false;
  std::string failure;            // fail()'s message, cut (cut_plugin_text)
  std::string breach;             // the first broken rule, in words ("" while none)
  Pair subject{-1, -1};           // the elements it names, when they are in range
  std::size_t pairs_at_breach = 0;  // pairs given before it (checked after the call: one may break first)
  std::exception_ptr exception;   // an exception of nbscope's own (out of memory, a trace consumer's)
  TraceLog* log = nullptr;        // null when untraced
  std::int32_t lines = 0;         // the plugin's pseudocode lines in this dimension
  std::vector<Array> arrays;
  Walks walks;
  ListWatch lists;
  std::jmp_buf* escape = nullptr;  // where a call nbscope stops lands (call_detect in plugin_detector.cpp)
  bool cycle = false;              // the breach is a list closed on itself: nbscope stopped the call
  PluginProgress* progress = nullptr;  // advanced by every trace call (plugin_trace.cpp)
  std::int64_t operations = 0;         // trace calls so far
  std::int64_t max_operations = 0;     // more is a loop that does not end: the call is stopped (0: no limit)

  // One trace call of kind `op` at pseudocode line `line` was made (relaxed: read by a crash report).
  // Past max_operations the call is stopped there: a runaway loop, whose recording would fill memory.
  void advance(TraceOp op, std::int32_t line) noexcept {
    if (progress != nullptr) {
      progress->op.store(static_cast<std::int32_t>(op), std::memory_order_relaxed);
      progress->line.store(line, std::memory_order_relaxed);
      progress->operations.fetch_add(1, std::memory_order_relaxed);
    }
    if (++operations <= max_operations || max_operations == 0 || escape == nullptr || stopped()) return;
    runaway();
    stop_call();
  }
  // Keeps the breach of a call past max_operations (never throws).
  void runaway() noexcept {
    try {
      breach_with("runaway: " + std::to_string(operations) + " trace operations for " + std::to_string(n) +
                  " elements, more than the book's loops ever make (each pair tested once is n(n-1)/2): a loop that does "
                  "not end (nbscope stopped the call)");
    } catch (...) {
      keep_exception();
    }
  }

  // Notes a test of `other` by `k` that does not lie in the cell k's last visit walked (never throws).
  void check_walk(std::int32_t k, std::int32_t other) noexcept {
    if (walks.out == nullptr || walks.visitor != k) return;
    const CellIndex own = cell_of(other);
    if (own == walks.visited) return;
    ++walks.out->count;
    if (walks.out->first.size() < WalkCheck::kKept) walks.out->first.push_back(StrayTest{k, other, walks.visited, own, cell_of(k)});
  }
  // Element k's cell for the walk check: the plugin's own when it wrote one, else the grid's.
  [[nodiscard]] CellIndex cell_of(std::int32_t k) const noexcept {
    const auto at = static_cast<std::size_t>(k);
    if (walks.own_cells != nullptr && walks.own_cells[2 * at] >= 0 && walks.own_cells[2 * at + 1] >= 0)
      return CellIndex{walks.own_cells[2 * at], walks.own_cells[2 * at + 1]};
    const auto i = static_cast<Eigen::Index>(at);
    return CellIndex{walks.grid->cell(walks.elements->x[i], 0), walks.grid->cell(walks.elements->y[i], 1)};
  }

  // The pairs given so far.
  [[nodiscard]] std::size_t given() const { return pairs != nullptr ? static_cast<std::size_t>(next - pairs->data()) : 0; }
  // True once a breach or an exception ended the call's useful work.
  [[nodiscard]] bool stopped() const { return !breach.empty() || exception; }
  // Keeps `what` as the breach unless one is already kept (never throws).
  void breach_with(const std::string& what) noexcept {
    if (stopped()) return;
    stop = next;
    pairs_at_breach = given();
    try {
      breach = what;
    } catch (...) {
      exception = std::current_exception();
    }
  }
  // Ends the plugin's call now, back in call_detect (the breach says why). Only from a callback, with
  // no object of its own alive: the plugin's C frames and the callback's are left without unwinding.
  [[noreturn]] void stop_call() noexcept { std::longjmp(*escape, 1); }
  // Keeps the exception being handled (inside a catch block), unless one is already kept.
  void keep_exception() noexcept {
    stop = next;
    if (!exception) exception = std::current_exception();
  }
};

// The trace table whose ctx is `call` (plugin_trace.cpp).
nbscope_trace plugin_trace_table(PluginCall& call);

}  // namespace nbscope

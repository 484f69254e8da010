// Fuzz target: the plugin boundary (core/plugin_detector.hpp). Bytes drive an in-process test plugin
// whose nbscope_detect makes arbitrary calls — pairs in and out of range, repeated, i == j; trace
// declarations of any rank and shape; pushes, clears, sets, visits, tests and phases naming declared
// and undeclared arrays, entries inside and outside their shapes, lines past the pseudocode; cells in
// and out of the grid; any return status. The plugin keeps its own account of which calls break the
// rules of include/nbscope/detector.h, written independently of the adapter, and the target holds the
// adapter to it: a PluginError or a misbehaviour (docs/diagnosis.md) exactly when a rule was broken;
// otherwise the pairs the plugin gave, in its order, an event per trace call, and a trace whose replay
// ends on the plugin's real arrays. A list closed on itself (an element pushed onto one build of a list
// twice, a walk meeting an element twice) breaks a rule too: nbscope stops the call there.
#include <nbscope/detector.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/plugin_detector.hpp"
#include "fuzz_bytes.hpp"
#include "fuzz_check.hpp"

namespace {

using nbscope::Pair;
using nbscope::fuzz::Bytes;

// An index for something of `size` entries: mostly inside, sometimes just outside or extreme.
std::int64_t index_for(Bytes& in, std::int64_t size) {
  const std::uint8_t b = in.u8();
  if (b < 220) return size > 0 ? b % size : 0;
  static constexpr std::int64_t kOdd[] = {-1, -2, std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()};
  if (b < 224) return kOdd[b - 220];
  return size + (b - 224);  // size, size + 1, ...
}

constexpr const char* kLines[] = {"loop", "push", "mask", "test"};

// What one input asks of the plugin, and the plugin's own account of what it did.
struct Script {
  Bytes* in = nullptr;
  std::int64_t n = 0;
  bool cells_cap = false;
  bool broke_rule = false;             // a call the contract forbids was made
  std::vector<Pair> pairs_given;       // valid pairs, normalised, in order
  std::set<Pair> seen;
  std::size_t events = 0;              // trace calls that must become events
  std::vector<std::vector<std::int32_t>> arrays;  // the plugin's declared arrays (never reallocated)
  // Closed lists: per heads array, each element's last list and that list's build (clears) then.
  std::map<std::int64_t, std::map<std::int64_t, std::pair<std::int64_t, std::int64_t>>> last_push;
  std::map<std::pair<std::int64_t, std::int64_t>, std::int64_t> builds;  // (heads, list) -> clears so far
  std::int64_t visitor = -1;           // the element of the last visit, whose tests walk one list
  std::set<std::int64_t> walked;       // the elements its walk has met
};
Script* g_script = nullptr;

// A pair call; true when the plugin should go on.
bool give_pair(const nbscope_output* out, std::int32_t i, std::int32_t j) {
  Script& s = *g_script;
  const bool in_range = i >= 0 && i < s.n && j >= 0 && j < s.n;
  const Pair p{std::min(i, j), std::max(i, j)};
  if (!in_range || i == j || !s.seen.insert(p).second) s.broke_rule = true;
  else s.pairs_given.push_back(p);
  return out->add_pair(out->ctx, i, j) == 0 && !s.broke_rule;
}

// A traced operation on the plugin's arrays. Returns false once a rule is broken; a breaking trace call
// never returns (nbscope ends the plugin's call in it), so the account is kept before each call.
bool trace_op(Bytes& in, const nbscope_trace* t, std::uint8_t op) {
  Script& s = *g_script;
  const auto line = static_cast<std::int32_t>(index_for(in, 4));
  const bool line_ok = line >= 0 && line < 4;
  const auto declared = static_cast<std::int64_t>(s.arrays.size());
  auto array_ok = [&](std::int64_t a) { return a >= 0 && a < declared; };
  auto entry_ok = [&](std::int64_t a, std::int64_t i) {
    return array_ok(a) && i >= 0 && i < static_cast<std::int64_t>(s.arrays[static_cast<std::size_t>(a)].size());
  };
  auto element_ok = [&](std::int64_t k, bool none) { return (k >= 0 && k < s.n) || (none && k == -1); };
  auto entry = [&](std::int64_t a, std::int64_t i) -> std::int32_t& {
    return s.arrays[static_cast<std::size_t>(a)][static_cast<std::size_t>(i)];
  };
  bool ok = line_ok;
  switch (op) {
    case 0: {  // declare: rank and shape mostly sane
      if (s.arrays.size() == 4) return true;  // the plugin has room for 4 (reserved: they never move)
      const std::int32_t rank = static_cast<std::int32_t>(in.u8() % 5);  // 0 and 4: refused
      std::int64_t shape[4] = {0, 0, 0, 0};
      std::int64_t size = 1;
      bool negative = false;
      for (std::int32_t a = 0; a < rank && a < 4; ++a) {
        const std::uint8_t b = in.u8();
        shape[a] = b < 250 ? b % 9 : -1;
        negative = negative || shape[a] < 0;
        size *= shape[a];
      }
      ok = rank >= 1 && rank <= 3 && !negative;
      if (!ok) {
        s.broke_rule = true;  // before the call: nbscope ends the call inside it
        t->declare_array(t->ctx, "bad", rank, shape, nullptr);
        break;
      }
      std::vector<std::int32_t> data(static_cast<std::size_t>(size));
      for (std::int32_t& v : data) v = static_cast<std::int32_t>(in.u8()) - 1;
      s.arrays.push_back(std::move(data));
      const int id = t->declare_array(t->ctx, "A", rank, shape, s.arrays.back().data());
      if (id != static_cast<int>(s.arrays.size()) - 1) nbscope::fuzz::fuzz_fail("declare_array returned " + std::to_string(id));
      return true;
    }
    case 1: {  // push: writes next[k] and heads[list] (rightly or not), then says so
      const std::int64_t heads = index_for(in, declared), next = index_for(in, declared);
      const std::int64_t list = index_for(in, array_ok(heads) ? static_cast<std::int64_t>(s.arrays[static_cast<std::size_t>(heads)].size()) : 1);
      const std::int64_t k = index_for(in, s.n);
      ok = ok && array_ok(heads) && array_ok(next) && entry_ok(heads, list) && element_ok(k, false) && entry_ok(next, k);
      if (ok) {
        const bool right = in.u8() % 4 != 0;
        entry(next, k) = right ? entry(heads, list) : -1;
        entry(heads, list) = static_cast<std::int32_t>(k);
        // Onto the list it is on (no clear since): the list closes; nbscope stops the call in this push.
        const std::int64_t build = s.builds[{heads, list}];
        auto& last = s.last_push[heads];
        const auto before = last.find(k);
        if (before != last.end() && before->second == std::make_pair(list, build)) s.broke_rule = true;
        last[k] = {list, build};
      }
      s.broke_rule = s.broke_rule || !ok;  // known before the call: nbscope ends the call inside a breaking one
      t->push(t->ctx, line, "list", static_cast<std::int32_t>(heads), list, static_cast<std::int32_t>(next),
              static_cast<std::int32_t>(k), 0, 0, -1);
      break;
    }
    case 2: {  // clear
      const std::int64_t heads = index_for(in, declared);
      const std::int64_t list = index_for(in, array_ok(heads) ? static_cast<std::int64_t>(s.arrays[static_cast<std::size_t>(heads)].size()) : 1);
      ok = ok && entry_ok(heads, list);
      if (ok) {
        entry(heads, list) = -1;
        ++s.builds[{heads, list}];
      }
      s.broke_rule = s.broke_rule || !ok;  // known before the call: nbscope ends the call inside a breaking one
      t->clear(t->ctx, line, "list", static_cast<std::int32_t>(heads), list);
      break;
    }
    case 3: {  // set
      const std::int64_t array = index_for(in, declared);
      const std::int64_t index = index_for(in, array_ok(array) ? static_cast<std::int64_t>(s.arrays[static_cast<std::size_t>(array)].size()) : 1);
      const std::int64_t k = in.u8() % 2 == 0 ? -1 : index_for(in, s.n);
      ok = ok && entry_ok(array, index) && element_ok(k, true);
      if (ok) entry(array, index) = static_cast<std::int32_t>(in.u8()) - 1;
      s.broke_rule = s.broke_rule || !ok;  // known before the call: nbscope ends the call inside a breaking one
      t->set(t->ctx, line, "entry", static_cast<std::int32_t>(array), index, static_cast<std::int32_t>(k));
      break;
    }
    case 4: {  // visit a cell
      const std::int64_t k = index_for(in, s.n);
      ok = ok && element_ok(k, false);
      if (ok) {
        s.visitor = k;
        s.walked.clear();
      }
      s.broke_rule = s.broke_rule || !ok;  // known before the call: nbscope ends the call inside a breaking one
      t->visit_cell(t->ctx, line, static_cast<std::int32_t>(k), in.u8(), in.u8(), -1);
      break;
    }
    case 5: {  // test a pair
      const std::int64_t k = index_for(in, s.n), other = index_for(in, s.n);
      ok = ok && element_ok(k, false) && element_ok(other, false);
      // A walk that meets an element twice follows a list closed on itself: nbscope stops the call.
      if (ok && k == s.visitor && !s.walked.insert(other).second) s.broke_rule = true;
      s.broke_rule = s.broke_rule || !ok;  // known before the call: nbscope ends the call inside a breaking one
      t->test_pair(t->ctx, line, static_cast<std::int32_t>(k), static_cast<std::int32_t>(other), in.u8() % 2);
      break;
    }
    default:  // a phase
      s.broke_rule = s.broke_rule || !ok;  // known before the call: nbscope ends the call inside a breaking one
      t->phase(t->ctx, line, in.u8() % 2 == 0 ? "rows" : nullptr, static_cast<std::int32_t>(in.u8()) - 1);
      break;
  }
  if (!ok) {
    s.broke_rule = true;
    return false;
  }
  ++s.events;
  return true;
}

extern "C" int fuzz_plugin_detect(void** /*state*/, const nbscope_frame* f, const nbscope_output* out, const nbscope_trace* t) {
  Script& s = *g_script;
  Bytes& in = *s.in;
  for (int op = 0; op < 256 && !in.done(); ++op) {
    const std::uint8_t code = in.u8();
    if (code < 96) {
      const auto i = static_cast<std::int32_t>(index_for(in, f->n));
      const auto j = static_cast<std::int32_t>(index_for(in, f->n));
      if (!give_pair(out, i, j)) return 0;
    } else if (code < 250) {
      if (t != nullptr && !trace_op(in, t, static_cast<std::uint8_t>(code % 7))) return 0;
    } else if (code == 250) {  // fail
      s.broke_rule = true;
      out->fail(out->ctx, "the fuzz input said so");
      return 1;
    } else {
      break;
    }
  }
  if (s.cells_cap && f->dim == 2) {
    const std::uint8_t how = in.u8() % 4;  // 0: left at -1; 1: outside the grid; else inside
    if (how < 2 && f->n > 0) s.broke_rule = true;
    for (std::int64_t k = 0; k < f->n; ++k)
      for (int a = 0; a < 2; ++a)
        out->cells[k * 2 + a] = how == 0 ? -1 : how == 1 ? static_cast<std::int32_t>(f->cells[a]) : static_cast<std::int32_t>(k % f->cells[a]);
  }
  return 0;
}

extern "C" const nbscope_detector_info* fuzz_plugin_describe(void) { return nullptr; }  // never called: info is given

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  const std::uint8_t head = in.u8();
  const bool traced = (head & 1) != 0, cells = (head & 2) != 0;
  nbscope::Elements elements;
  elements.dim = 2;
  const std::int64_t n = 1 + in.u8() % 24;
  elements.resize(n);
  for (std::int64_t k = 0; k < n; ++k) {
    elements.x[k] = in.u8() * 0.5;
    elements.y[k] = in.u8() * 0.5;
    elements.r[k] = 0.5;
  }

  static const char* const lines[] = {kLines[0], kLines[1], kLines[2], kLines[3]};
  const nbscope_detector_info info{NBSCOPE_DETECTOR_API_VERSION, "fuzz", "the fuzz target's plugin",
                                   NBSCOPE_CAP_2D | NBSCOPE_CAP_TRACES | NBSCOPE_CAP_LISTS | (cells ? NBSCOPE_CAP_CELLS : 0u),
                                   lines, 4, nullptr, 0};
  nbscope::PluginSymbols symbols;
  symbols.library = "fuzz.so";
  symbols.describe = fuzz_plugin_describe;
  symbols.detect = fuzz_plugin_detect;
  nbscope::PluginDetector detector(symbols, info);

  Script script;
  script.in = &in;
  script.n = n;
  script.cells_cap = cells;
  script.arrays.reserve(4);
  g_script = &script;
  nbscope::PairList pairs;
  nbscope::TraceLog log;
  bool refused = false;
  try {
    if (traced) detector.detect_traced(elements, nbscope::DetectOptions{}, pairs, log);
    else detector.detect(elements, nbscope::DetectOptions{}, pairs);
  } catch (const nbscope::PluginError&) {
    refused = true;
  }
  refused = refused || detector.misbehaviour() != nullptr;  // a rule broken in a frame: its violation
  g_script = nullptr;

  FUZZ_CHECK(refused == script.broke_rule, std::string(refused ? "a plugin that kept every rule was refused"
                                                               : "a plugin that broke a rule was accepted"));
  if (refused) return 0;
  std::vector<Pair> expected = script.pairs_given;
  if (nbscope::fuzz::planted_fault() == "drop-pair" && !expected.empty()) expected.pop_back();
  FUZZ_CHECK(pairs == expected, "the pairs accepted are not the pairs the plugin gave (" + std::to_string(pairs.size()) +
                                    " vs " + std::to_string(expected.size()) + ")");
  if (!traced) return 0;
  FUZZ_CHECK(log.events().size() == script.events, "trace calls " + std::to_string(script.events) + " became " +
                                                       std::to_string(log.events().size()) + " events");
  const auto replayed = log.state_after(log.events().size());
  FUZZ_CHECK(replayed == script.arrays, std::string("the trace's replay does not end on the plugin's arrays"));
  if (cells) FUZZ_CHECK(detector.own_cells() != nullptr && detector.own_cells()->size() == static_cast<std::size_t>(n),
                        std::string("the plugin's cells were not kept"));
  return 0;
}

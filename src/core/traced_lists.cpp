#include "core/traced_lists.hpp"

#include <algorithm>
#include <map>
#include <tuple>

namespace nbscope {

namespace {

using State = std::vector<std::vector<std::int32_t>>;

// An open list: pushed onto since its last capture.
struct Open {
  std::int32_t phase_index = -1;
  std::int32_t phase_layer = -1;
  std::int32_t cell[3] = {-1, -1, -1};
  std::string kind;
};

std::vector<ElementId> walk(const State& state, int heads, std::int64_t slot, int next, std::size_t n, bool& cut) {
  std::vector<ElementId> chain;
  cut = false;
  if (heads < 0 || next < 0) return chain;
  const auto& h = state[static_cast<std::size_t>(heads)];
  const auto& nx = state[static_cast<std::size_t>(next)];
  if (slot < 0 || static_cast<std::size_t>(slot) >= h.size()) return chain;
  for (std::int32_t k = h[static_cast<std::size_t>(slot)]; k != -1; k = nx[static_cast<std::size_t>(k)]) {
    if (k < 0 || static_cast<std::size_t>(k) >= nx.size() || chain.size() > n) {
      cut = true;
      break;
    }
    chain.push_back(k);
  }
  return chain;
}

// Sort's runs of equal cell keys, from the final "order" permutation and the "ix"/"iy" arrays.
std::vector<TracedList> sort_runs(const TraceLog& log, const State& state) {
  int order = -1, ix = -1, iy = -1, iz = -1;
  for (std::size_t a = 0; a < log.arrays().size(); ++a) {
    const std::string& name = log.arrays()[a].name;
    if (name == "order") order = static_cast<int>(a);
    if (name == "ix") ix = static_cast<int>(a);
    if (name == "iy") iy = static_cast<int>(a);
    if (name == "iz") iz = static_cast<int>(a);
  }
  std::vector<TracedList> runs;
  if (order < 0 || ix < 0 || iy < 0) return runs;
  const auto& o = state[static_cast<std::size_t>(order)];
  auto key = [&](std::int32_t k, int a) {
    return a < 0 ? -1 : state[static_cast<std::size_t>(a)][static_cast<std::size_t>(k)];
  };
  for (std::size_t p = 0; p < o.size();) {
    TracedList run;
    run.kind = "run";
    run.heads_name = "order";
    run.heads_array = order;
    run.slot = static_cast<std::int64_t>(p);
    run.heads_shape = {static_cast<std::int64_t>(o.size())};
    const std::int32_t first = o[p];
    run.cell[0] = key(first, ix);
    run.cell[1] = key(first, iy);
    run.cell[2] = key(first, iz);
    while (p < o.size() && key(o[p], ix) == run.cell[0] && key(o[p], iy) == run.cell[1] &&
           key(o[p], iz) == run.cell[2])
      run.chain.push_back(o[p++]);
    runs.push_back(std::move(run));
  }
  return runs;
}

}  // namespace

bool is_row_below(const TracedArray& heads, std::int64_t slot) {
  return heads.name == "B" && heads.shape.size() == 2 && heads.shape[0] == 2 && slot >= heads.shape[1];
}

std::vector<TracedList> traced_lists(const TraceLog& log, std::size_t element_count, std::size_t upto) {
  State state;
  for (const TracedArray& a : log.arrays()) state.push_back(a.initial);
  std::vector<int> next_of(log.arrays().size(), -1);
  std::map<std::pair<int, std::int64_t>, Open> open;
  std::vector<TracedList> out;
  std::int32_t phase_index = -1;
  std::int32_t phase_layer = -1;

  auto capture = [&](int heads, std::int64_t slot, const Open& o) {
    TracedList l;
    l.kind = o.kind;
    l.heads_array = heads;
    l.heads_name = log.arrays()[static_cast<std::size_t>(heads)].name;
    l.slot = slot;
    l.phase_index = o.phase_index;
    l.phase_layer = o.phase_layer;
    std::copy(std::begin(o.cell), std::end(o.cell), std::begin(l.cell));
    const TracedArray& array = log.arrays()[static_cast<std::size_t>(heads)];
    l.heads_shape = array.shape;
    l.secondary = is_row_below(array, slot);
    const int next = next_of[static_cast<std::size_t>(heads)];
    if (next >= 0) l.next_name = log.arrays()[static_cast<std::size_t>(next)].name;
    l.chain = walk(state, heads, slot, next, element_count, l.cut);
    if (!l.chain.empty()) out.push_back(std::move(l));
  };

  const std::size_t count = std::min(upto, log.events().size());
  for (std::size_t i = 0; i < count; ++i) {
    const TraceEvent& e = log.events()[i];
    switch (e.op) {
      case TraceOp::Phase:
        phase_index = e.index;
        phase_layer = e.cell[2];
        break;
      case TraceOp::Push: {
        const int heads = e.writes[1].array;
        if (heads >= 0 && e.writes[0].array >= 0) next_of[static_cast<std::size_t>(heads)] = e.writes[0].array;
        const auto key = std::make_pair(heads, e.writes[1].index);
        if (!open.contains(key)) {
          Open o;
          o.phase_index = phase_index;
          o.phase_layer = phase_layer;
          std::copy(std::begin(e.cell), std::end(e.cell), std::begin(o.cell));
          o.kind = e.label;
          open.emplace(key, std::move(o));
        }
        break;
      }
      case TraceOp::Clear: {
        const auto key = std::make_pair(e.writes[0].array, e.writes[0].index);
        if (auto it = open.find(key); it != open.end()) {
          capture(key.first, key.second, it->second);
          open.erase(it);
        }
        break;
      }
      default: break;
    }
    TraceLog::apply(e, state);
  }
  for (const auto& [key, o] : open) capture(key.first, key.second, o);

  // Sort's runs exist once its permutation is complete (no write to it remains).
  if (out.empty()) {
    bool order_done = true;
    for (std::size_t i = count; i < log.events().size() && order_done; ++i)
      for (int w = 0; w < log.events()[i].write_count && w < 2; ++w) {
        const int a = log.events()[i].writes[w].array;
        if (a >= 0 && log.arrays()[static_cast<std::size_t>(a)].name == "order") order_done = false;
      }
    if (order_done) out = sort_runs(log, state);
  }
  std::stable_sort(out.begin(), out.end(), [](const TracedList& a, const TracedList& b) {
    return std::tie(a.heads_array, a.phase_index, a.slot) < std::tie(b.heads_array, b.phase_index, b.slot);
  });
  return out;
}

}  // namespace nbscope

#include "ui/layer_lists.hpp"

#include <algorithm>

#include "ui/model.hpp"

namespace nbscope::ui {

namespace {
// Chains from `heads` through `next`, each walk bounded by the element count.
void walk_chains(ZLists& z, const std::vector<std::int32_t>& next) {
  z.chains.assign(z.heads.size(), {});
  const auto n = static_cast<std::int32_t>(next.size());
  for (std::size_t iz = 0; iz < z.heads.size(); ++iz) {
    for (std::int32_t k = z.heads[iz]; k >= 0 && k < n && static_cast<std::int32_t>(z.chains[iz].size()) < n;
         k = next[static_cast<std::size_t>(k)])
      z.chains[iz].push_back(k);
  }
}

// The ids of NBS 3D's z-list arrays: C (heads, one per layer) and Z (next, one per element).
bool zlist_arrays(const TraceLog& log, int& c, int& z) {
  c = log.array_id("C");
  z = log.array_id("Z");
  return c >= 0 && z >= 0 && log.arrays()[static_cast<std::size_t>(c)].shape.size() == 1;
}
}  // namespace

std::optional<ZLists> zlists_from_state(const TraceLog& log, const ArrayState& state) {
  int c = -1, zid = -1;
  if (!zlist_arrays(log, c, zid) || static_cast<std::size_t>(std::max(c, zid)) >= state.size()) return std::nullopt;
  ZLists z;
  z.source = ZLists::Source::Stepper;
  z.heads = state[static_cast<std::size_t>(c)];
  walk_chains(z, state[static_cast<std::size_t>(zid)]);
  return z;
}

std::optional<ZLists> zlists_from_trace(const TraceLog& log) {
  int c = -1, zid = -1;
  if (!zlist_arrays(log, c, zid)) return std::nullopt;
  ZLists z;
  z.source = ZLists::Source::Trace;
  z.heads = log.arrays()[static_cast<std::size_t>(c)].initial;
  std::vector<std::int32_t> next = log.arrays()[static_cast<std::size_t>(zid)].initial;
  // Z is never cleared: its last writes are the finished links. A head's last value before its
  // Clear is the finished list's head.
  for (const TraceEvent& e : log.events()) {
    for (int w = 0; w < e.write_count && w < 2; ++w) {
      const ArrayWrite& wr = e.writes[w];
      const auto i = static_cast<std::size_t>(wr.index);
      if (wr.array == zid && i < next.size()) next[i] = wr.new_value;
      if (wr.array == c && i < z.heads.size()) z.heads[i] = e.op == TraceOp::Clear ? wr.old_value : wr.new_value;
    }
  }
  walk_chains(z, next);
  return z;
}

ZLists zlists_from_layers(const LayerSlice& slice) {
  ZLists z;
  z.source = ZLists::Source::Layers;
  z.heads.assign(static_cast<std::size_t>(std::max(slice.count, 0)), -1);
  std::vector<std::int32_t> next(slice.element_layer.size(), -1);
  for (std::size_t k = 0; k < slice.element_layer.size(); ++k) {
    const auto iz = static_cast<std::size_t>(slice.element_layer[k]);
    if (iz >= z.heads.size()) continue;
    next[k] = z.heads[iz];  // Z[k] = C[iz]; C[iz] = k
    z.heads[iz] = static_cast<std::int32_t>(k);
  }
  walk_chains(z, next);
  return z;
}

std::string zlist_text(const ZLists& z, std::int32_t layer, bool book, std::size_t max_shown) {
  if (layer < 0 || static_cast<std::size_t>(layer) >= z.heads.size()) return "";
  const auto iz = static_cast<std::size_t>(layer);
  const std::vector<std::int32_t>& chain = z.chains[iz];
  std::string text = "C[" + std::to_string(shown(layer, book)) + "] = " + std::to_string(shown(z.heads[iz], book));
  if (chain.empty()) return text + ": empty";
  text += ": ";
  for (std::size_t i = 0; i < chain.size() && i < max_shown; ++i) text += std::to_string(shown(chain[i], book)) + " -> ";
  return text + (chain.size() > max_shown ? "..." : "-1");
}

}  // namespace nbscope::ui

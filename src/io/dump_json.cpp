// Index: helpers (arrays by name, snapshots, lists as [k, next] pairs) | one function per
// algorithm (screen, tree, sort, nbs 2D, nbs 3D) | dump_json | format_dump.
#include "io/dump_json.hpp"

#include <algorithm>
#include <cstring>
#include <vector>

#include "core/error.hpp"
#include "core/lists.hpp"
#include "core/tree.hpp"

namespace nbscope {

namespace {

using json = nlohmann::ordered_json;
using State = std::vector<std::vector<std::int32_t>>;

int array_id(const TraceLog& log, const char* name) {
  for (std::size_t i = 0; i < log.arrays().size(); ++i)
    if (log.arrays()[i].name == name) return static_cast<int>(i);
  throw Error(std::string("dump: internal: the trace has no array '") + name + "'");
}

bool is_phase(const TraceEvent& e, const char* label) {
  return e.op == TraceOp::Phase && std::strcmp(e.label, label) == 0;
}

// The arrays right before the first phase labelled `label` (after the whole run if there is none).
State state_before(const TraceLog& log, const char* label) {
  std::size_t i = 0;
  while (i < log.events().size() && !is_phase(log.events()[i], label)) ++i;
  return log.state_after(i);
}

// A flat row-major array as nested JSON arrays of `shape`.
json nested(const std::vector<std::int32_t>& flat, const std::vector<std::int64_t>& shape, std::size_t axis = 0,
            std::size_t offset = 0) {
  json out = json::array();
  std::size_t stride = 1;
  for (std::size_t a = axis + 1; a < shape.size(); ++a) stride *= static_cast<std::size_t>(shape[a]);
  for (std::int64_t i = 0; i < shape[axis]; ++i) {
    const std::size_t at = offset + static_cast<std::size_t>(i) * stride;
    if (axis + 1 == shape.size()) {
      out.push_back(flat[at]);
    } else {
      out.push_back(nested(flat, shape, axis + 1, at));
    }
  }
  return out;
}

// The non-empty lists among heads[first + i] for the touched i: heads as [i, head] pairs and the
// next array of their elements as [k, next[k]] pairs, in list order.
void sparse_lists(const std::vector<std::int32_t>& heads, const std::vector<std::int32_t>& next,
                  std::vector<std::int64_t> touched, std::int64_t first, std::int64_t count, json& out_heads,
                  json& out_next) {
  out_heads = json::array();
  out_next = json::array();
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  for (std::int64_t t : touched) {
    if (t < first || t >= first + count) continue;
    const std::int32_t head = heads[static_cast<std::size_t>(t)];
    if (head == -1) continue;
    out_heads.push_back(json::array({t - first, head}));
    std::size_t steps = 0;
    for (std::int32_t k = head; k != -1 && steps <= next.size(); k = next[k], ++steps)
      out_next.push_back(json::array({k, next[k]}));
  }
}

void dump_screen(const TraceLog& log, json& j) {
  const int c = array_id(log, "C"), e = array_id(log, "E");
  const State s = state_before(log, phase_label::kContacts);
  j["heads"] = nested(s[c], log.arrays()[c].shape);
  j["next"] = s[e];
}

void dump_tree(const TraceLog& log, const Grid& g, json& j) {
  const int child = array_id(log, "child"), head = array_id(log, "HEAD"), e = array_id(log, "E");
  const State s = state_before(log, phase_label::kContacts);
  j["nodes"] = s[head].size();
  json leaves = json::array();
  for (const TreeLeaf& leaf : tree_leaves(g, s[child], s[head])) {
    json cell = json::array(), lo = json::array(), hi = json::array();
    for (int a = 0; a < g.dim; ++a) {
      cell.push_back(leaf.cell[a]);
      lo.push_back(g.origin[a] + g.cell_size * leaf.cell[a]);
      hi.push_back(g.origin[a] + g.cell_size * (leaf.cell[a] + 1));
    }
    leaves.push_back(json{{"node", leaf.node}, {"cell", cell}, {"bounds", json::array({lo, hi})}, {"head", leaf.head}});
  }
  j["leaves"] = leaves;
  j["next"] = s[e];
}

void dump_sort(const TraceLog& log, int dim, json& j) {
  const char* names[3] = {"ix", "iy", "iz"};
  int ids[3] = {-1, -1, -1};
  for (int a = 0; a < dim; ++a) ids[a] = array_id(log, names[a]);
  const int order = array_id(log, "order");
  const State s = state_before(log, phase_label::kContacts);
  json keys = json::array();
  for (std::int32_t k : s[order]) {
    json key = json::array();
    for (int a = 0; a < dim; ++a) key.push_back(s[ids[a]][k]);
    keys.push_back(key);
  }
  j["keys"] = keys;
  j["order"] = s[order];
  for (int a = 0; a < dim; ++a) j[names[a]] = s[ids[a]];
}

// nbs 2D: the y-lists when complete, then each row's x-lists (B[0]) when its contacts begin.
void dump_nbs_2d(const TraceLog& log, const Grid& g, json& j) {
  const int yh = array_id(log, "y_heads"), yn = array_id(log, "Y"), b = array_id(log, "B"), xn = array_id(log, "X");
  const State ys = state_before(log, phase_label::kClearYLists);
  j["y_heads"] = ys[yh];
  j["y_next"] = ys[yn];
  json rows = json::array();
  State s = log.state_after(0);
  std::vector<std::int64_t> touched;
  for (const TraceEvent& ev : log.events()) {
    if (is_phase(ev, phase_label::kXListsOfRow)) touched.clear();
    if (is_phase(ev, phase_label::kContactsOfRow)) {
      json heads, next;
      sparse_lists(s[b], s[xn], touched, 0, g.n[0], heads, next);
      rows.push_back(json{{"iy", ev.index}, {"x_heads", heads}, {"x_next", next}});
    }
    if (ev.op == TraceOp::Push && ev.writes[1].array == b) touched.push_back(ev.writes[1].index);
    TraceLog::apply(ev, s);
  }
  j["rows"] = rows;
}

// nbs 3D: the z-lists when complete; per layer its y-lists (B[0]) and per row its x-lists (A[0]).
void dump_nbs_3d(const TraceLog& log, const Grid& g, json& j) {
  const int c = array_id(log, "C"), z = array_id(log, "Z"), b = array_id(log, "B"), y = array_id(log, "Y"),
            a = array_id(log, "A"), x = array_id(log, "X");
  const State zs = state_before(log, phase_label::kClearZLists);
  j["z_heads"] = zs[c];
  j["z_next"] = zs[z];
  json layers = json::array(), rows = json::array();
  State s = log.state_after(0);
  std::vector<std::int64_t> touched_y, touched_x;
  for (const TraceEvent& ev : log.events()) {
    if (is_phase(ev, phase_label::kYListsOfLayer)) {
      touched_y.clear();
      rows = json::array();
    }
    if (is_phase(ev, phase_label::kXListsOfRow)) touched_x.clear();
    if (is_phase(ev, phase_label::kContactsOfRow)) {
      json heads, next;
      sparse_lists(s[a], s[x], touched_x, 0, g.n[0], heads, next);
      rows.push_back(json{{"iy", ev.cell[1]}, {"x_heads", heads}, {"x_next", next}});
    }
    if (is_phase(ev, phase_label::kClearYListsOfLayer)) {
      json heads, next;
      sparse_lists(s[b], s[y], touched_y, 0, g.n[1], heads, next);
      std::sort(rows.begin(), rows.end(), [](const json& p, const json& q) { return p["iy"] < q["iy"]; });
      layers.push_back(json{{"iz", ev.index}, {"y_heads", heads}, {"y_next", next}, {"rows", rows}});
    }
    if (ev.op == TraceOp::Push && ev.writes[1].array == b) touched_y.push_back(ev.writes[1].index);
    if (ev.op == TraceOp::Push && ev.writes[1].array == a) touched_x.push_back(ev.writes[1].index);
    TraceLog::apply(ev, s);
  }
  j["layers"] = layers;
}

void format_value(const json& v, int indent, std::string& out);

bool all_numbers(const json& v) {
  return std::all_of(v.begin(), v.end(), [](const json& e) { return e.is_number(); });
}

// Arrays of numbers, and arrays of short arrays of numbers ([ix, head] pairs), stay on one line.
bool one_line(const json& v) {
  if (!v.is_array()) return !v.is_object() || v.empty();
  return std::all_of(v.begin(), v.end(), [](const json& e) {
    return e.is_number() || (e.is_array() && e.size() <= 3 && all_numbers(e));
  });
}

// One line: "[1, 2, [3, -1]]".
std::string inline_text(const json& v) {
  if (!v.is_array()) return v.dump();
  std::string out = "[";
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + inline_text(v[i]);
  return out + "]";
}

void format_value(const json& v, int indent, std::string& out) {
  const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
  if (one_line(v)) {
    out += inline_text(v);
    return;
  }
  const bool object = v.is_object();
  out += object ? "{\n" : "[\n";
  std::size_t i = 0;
  for (auto it = v.begin(); it != v.end(); ++it, ++i) {
    out += pad;
    if (object) out += json(it.key()).dump() + ": ";
    format_value(*it, indent + 2, out);
    out += i + 1 < v.size() ? ",\n" : "\n";
  }
  out += std::string(static_cast<std::size_t>(indent), ' ') + (object ? "}" : "]");
}

}  // namespace

json dump_json(const DumpSource& src) {
  if (src.elements == nullptr || src.trace == nullptr) throw Error("dump: internal: nothing to dump");
  const Elements& e = *src.elements;
  const TraceLog& log = *src.trace;
  json j;
  j["algorithm"] = src.algorithm;
  j["dim"] = e.dim;
  j["elements"] = e.size();
  j["pairs"] = src.pairs;
  if (src.grid != nullptr) {
    const Grid& g = *src.grid;
    j["cell_size"] = g.cell_size;
    json origin = json::array();
    for (int a = 0; a < g.dim; ++a) origin.push_back(g.origin[a]);
    j["origin"] = origin;
    j["nx"] = g.n[0];
    j["ny"] = g.n[1];
    if (g.dim == 3) j["nz"] = g.n[2];
  }
  j["own_bytes"] = src.own_bytes;
  json bytes = json::object();
  for (const TracedArray& a : log.arrays()) {
    std::int64_t count = 1;
    for (std::int64_t s : a.shape) count *= s;
    bytes[a.name] = count * static_cast<std::int64_t>(sizeof(std::int32_t));
  }
  j["bytes"] = bytes;
  if (log.arrays().empty() || src.grid == nullptr) return j;  // no book arrays (brute, box2d): counts only

  // Each algorithm has its own arrays, so its own keys (DESIGN.md "Command line", `dump`).
  if (src.algorithm == "screen") {
    dump_screen(log, j);
  } else if (src.algorithm == "tree") {
    dump_tree(log, *src.grid, j);
  } else if (src.algorithm == "sort") {
    dump_sort(log, e.dim, j);
  } else if (src.algorithm == "nbs" && e.dim == 3) {
    dump_nbs_3d(log, *src.grid, j);
  } else if (src.algorithm == "nbs") {
    dump_nbs_2d(log, *src.grid, j);
  }
  return j;
}

std::string format_dump(const json& v) {
  std::string out;
  format_value(v, 0, out);
  out += "\n";
  return out;
}

}  // namespace nbscope

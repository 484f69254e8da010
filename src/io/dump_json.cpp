// Index: helpers (arrays by name, snapshots) | the streamed text (buffer, objects, arrays, lists as
// [k, next] pairs) | one function per algorithm (screen, tree, sort, nbs 2D, nbs 3D) | write_dump |
// dump_json | format_dump.
#include "io/dump_json.hpp"

#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <charconv>
#include <cstring>
#include <ostream>
#include <span>
#include <sstream>
#include <string_view>
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

// `name`'s id in `cache` once the run has declared it (-1 until then).
int declared(const TraceLog& log, const char* name, int& cache) {
  if (cache < 0)
    for (std::size_t i = 0; i < log.arrays().size(); ++i)
      if (log.arrays()[i].name == name) cache = static_cast<int>(i);
  return cache;
}

bool is_phase(const TraceEvent& e, const char* label) {
  return e.op == TraceOp::Phase && std::strcmp(e.label, label) == 0;
}

// ---- the streamed text -----------------------------------------------------------------------
//
// The dump is written as it is computed, in format_dump's layout (objects one key a line, arrays of
// numbers and of short number arrays on one line), so that no document of the whole dump is built:
// for 5 million elements that document took several GB, the arrays themselves a few hundred MB.

// Text to `out` through a buffer written in chunks.
class DumpText {
 public:
  explicit DumpText(std::ostream& out) : out_(out) { buf_.reserve(kChunk + 256); }
  ~DumpText() = default;
  DumpText(const DumpText&) = delete;
  DumpText& operator=(const DumpText&) = delete;

  DumpText& operator<<(std::string_view text) {
    buf_.append(text);
    if (buf_.size() >= kChunk) flush();
    return *this;
  }
  DumpText& integer(std::int64_t v) {
    char num[24];
    const auto r = std::to_chars(num, num + sizeof num, v);
    return *this << std::string_view(num, static_cast<std::size_t>(r.ptr - num));
  }
  // As nlohmann's serializer writes a double ("1.0", "0.1", "1e-05"): the layout of earlier dumps.
  DumpText& real(double v) { return *this << json(v).dump(); }
  DumpText& string(const std::string& v) { return *this << json(v).dump(); }
  void flush() {
    out_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    buf_.clear();
  }

 private:
  static constexpr std::size_t kChunk = std::size_t{1} << 16;
  std::ostream& out_;
  std::string buf_;
};

// An object written key by key: "{\n", each key on its own line at indent + 2, "\n" + indent + "}".
class ObjectText {
 public:
  ObjectText(DumpText& text, int indent) : text_(text), indent_(indent) { text_ << "{\n"; }
  ~ObjectText() = default;
  ObjectText(const ObjectText&) = delete;
  ObjectText& operator=(const ObjectText&) = delete;
  // Starts the value of `name`; the caller writes it.
  DumpText& key(const std::string& name) {
    text_ << (count_++ ? ",\n" : "") << std::string(static_cast<std::size_t>(indent_ + 2), ' ');
    return text_.string(name) << ": ";
  }
  [[nodiscard]] int inner() const { return indent_ + 2; }
  void close() { text_ << "\n" << std::string(static_cast<std::size_t>(indent_), ' ') << "}"; }

 private:
  DumpText& text_;
  int indent_;
  int count_ = 0;
};

// "[1, 2, 3]".
void int_array(DumpText& text, std::span<const std::int32_t> values) {
  text << "[";
  for (std::size_t i = 0; i < values.size(); ++i) (i ? text << ", " : text).integer(values[i]);
  text << "]";
}

// "[[a, b], [c, d]]": [i, head] and [k, next] pairs.
void pair_array(DumpText& text, std::span<const std::array<std::int64_t, 2>> pairs) {
  text << "[";
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    text << (i ? ", [" : "[");
    text.integer(pairs[i][0]) << ", ";
    text.integer(pairs[i][1]) << "]";
  }
  text << "]";
}

// A flat row-major array as nested arrays of `shape`, laid out as format_dump lays out the document:
// an array whose items are numbers, or arrays of at most three numbers, on one line, else one item a line.
void nested(DumpText& text, const std::vector<std::int32_t>& flat, const std::vector<std::int64_t>& shape, int indent,
            bool one_line = false, std::size_t axis = 0, std::size_t offset = 0) {
  std::size_t stride = 1;
  for (std::size_t a = axis + 1; a < shape.size(); ++a) stride *= static_cast<std::size_t>(shape[a]);
  const auto count = static_cast<std::size_t>(shape[axis]);
  if (axis + 1 == shape.size()) {
    int_array(text, std::span<const std::int32_t>(flat).subspan(offset, count));
    return;
  }
  one_line = one_line || count == 0 || shape[axis + 1] == 0 || (axis + 2 == shape.size() && shape[axis + 1] <= 3);
  text << (one_line ? "[" : "[\n");
  const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
  for (std::size_t i = 0; i < count; ++i) {
    if (one_line) {
      if (i) text << ", ";
    } else {
      text << pad;
    }
    nested(text, flat, shape, indent + 2, one_line, axis + 1, offset + i * stride);
    if (!one_line) text << (i + 1 < count ? ",\n" : "\n");
  }
  if (!one_line) text << std::string(static_cast<std::size_t>(indent), ' ');
  text << "]";
}

// Items written one a line, each by the caller: "[\n" + items at indent + 2 + "\n" + indent + "]",
// or "[]" when there is none.
class ListText {
 public:
  ListText(DumpText& text, int indent) : text_(text), indent_(indent) {}
  ~ListText() = default;
  ListText(const ListText&) = delete;
  ListText& operator=(const ListText&) = delete;
  // Starts an item; the caller writes it at indent inner().
  void item() { text_ << (count_++ ? ",\n" : "[\n") << std::string(static_cast<std::size_t>(indent_ + 2), ' '); }
  [[nodiscard]] int inner() const { return indent_ + 2; }
  void close() { text_ << (count_ ? "\n" + std::string(static_cast<std::size_t>(indent_), ' ') + "]" : std::string("[]")); }

 private:
  DumpText& text_;
  int indent_;
  int count_ = 0;
};

// The non-empty lists among heads[first + i] for the touched i: heads as [i, head] pairs and the
// next array of their elements as [k, next[k]] pairs, in list order.
struct SparseLists {
  std::vector<std::array<std::int64_t, 2>> heads, next;
};
SparseLists sparse_lists(const std::vector<std::int32_t>& heads, const std::vector<std::int32_t>& next,
                         std::vector<std::int64_t> touched, std::int64_t first, std::int64_t count) {
  SparseLists out;
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  for (std::int64_t t : touched) {
    if (t < first || t >= first + count) continue;
    const std::int32_t head = heads[static_cast<std::size_t>(t)];
    if (head == -1) continue;
    out.heads.push_back({t - first, head});
    std::size_t steps = 0;
    for (std::int32_t k = head; k != -1 && steps <= next.size(); k = next[k], ++steps) out.next.push_back({k, next[k]});
  }
  return out;
}

// One row's x-lists: {"iy": ..., "x_heads": [...], "x_next": [...]}.
struct RowLists {
  std::int64_t iy = 0;
  SparseLists lists;
};
void row_object(DumpText& text, const RowLists& row, int indent) {
  ObjectText o(text, indent);
  o.key("iy").integer(row.iy);
  pair_array(o.key("x_heads"), row.lists.heads);
  pair_array(o.key("x_next"), row.lists.next);
  o.close();
}

// nbs 3D: one layer's y-lists (B[0]) and its rows' x-lists (A[0]).
struct LayerLists {
  std::int64_t iz = 0;
  SparseLists lists;
  std::vector<RowLists> rows;  // in iy order
};

}  // namespace

// ---- DumpCollector --------------------------------------------------------------------------
//
// What each algorithm shows (docs/formats.md "Arrays JSON"): screen, tree and sort their arrays
// right before the contacts phase; nbs 2D the y-lists before they are cleared and each row's x-lists
// (B[0]) when its contacts begin; nbs 3D the z-lists before they are cleared, per layer its y-lists
// (B[0]) and per row its x-lists (A[0]). The events are applied to one copy of the arrays as they
// come; a snapshot is taken at the phase shown, and the lists of each row when it is reached.

struct DumpCollector::Impl {
  std::string algorithm;
  int dim = 2;
  const char* shown_at = "";     // the phase whose state the dump's arrays are
  State state;                   // every declared array as the events so far leave it
  std::optional<State> snapshot;  // the state right before the first `shown_at` phase
  // nbs: the ids of the list arrays (-1 until declared), the list heads each row (layer) touched.
  int b = -1, xn = -1, a = -1, x = -1, y_id = -1;
  std::vector<std::int64_t> touched, touched_y, touched_x;
  std::vector<RowLists> rows;        // 2D: every row's; 3D: the current layer's
  std::vector<LayerLists> layers;    // 3D

  bool nbs() const { return algorithm == "nbs"; }
  static std::int64_t width(const TraceLog& log, int id) { return log.arrays()[static_cast<std::size_t>(id)].shape.back(); }

  void event(const TraceLog& log, const TraceEvent& ev) {
    while (state.size() < log.arrays().size()) state.push_back(log.arrays()[state.size()].initial);
    if (!snapshot && is_phase(ev, shown_at)) snapshot = state;
    if (nbs() && dim == 3) {
      nbs_3d(log, ev);
    } else if (nbs()) {
      nbs_2d(log, ev);
    }
    TraceLog::apply(ev, state);
  }

  void nbs_2d(const TraceLog& log, const TraceEvent& ev) {
    declared(log, "B", b);
    declared(log, "X", xn);
    if (is_phase(ev, phase_label::kXListsOfRow)) touched.clear();
    if (is_phase(ev, phase_label::kContactsOfRow))
      rows.push_back({ev.index, sparse_lists(state[b], state[xn], touched, 0, width(log, b))});
    if (ev.op == TraceOp::Push && b >= 0 && ev.writes[1].array == b) touched.push_back(ev.writes[1].index);
  }

  void nbs_3d(const TraceLog& log, const TraceEvent& ev) {
    const int y = declared(log, "Y", y_id);
    declared(log, "B", b);
    declared(log, "A", a);
    declared(log, "X", x);
    if (is_phase(ev, phase_label::kYListsOfLayer)) {
      touched_y.clear();
      rows.clear();
    }
    if (is_phase(ev, phase_label::kXListsOfRow)) touched_x.clear();
    if (is_phase(ev, phase_label::kContactsOfRow))
      rows.push_back({ev.cell[1], sparse_lists(state[a], state[x], touched_x, 0, width(log, a))});
    if (is_phase(ev, phase_label::kClearYListsOfLayer)) {
      std::stable_sort(rows.begin(), rows.end(), [](const RowLists& p, const RowLists& q) { return p.iy < q.iy; });
      layers.push_back({ev.index, sparse_lists(state[b], state[y], touched_y, 0, width(log, b)), rows});
    }
    if (ev.op == TraceOp::Push && b >= 0 && ev.writes[1].array == b) touched_y.push_back(ev.writes[1].index);
    if (ev.op == TraceOp::Push && a >= 0 && ev.writes[1].array == a) touched_x.push_back(ev.writes[1].index);
  }

  // The arrays as shown: the snapshot, or the state after the whole run when the phase never came.
  const State& shown() const { return snapshot ? *snapshot : state; }
};

DumpCollector::DumpCollector(std::string algorithm, int dim) : impl_(std::make_unique<Impl>()) {
  impl_->algorithm = std::move(algorithm);
  impl_->dim = dim;
  impl_->shown_at = impl_->nbs() ? (dim == 3 ? phase_label::kClearZLists : phase_label::kClearYLists) : phase_label::kContacts;
}
DumpCollector::~DumpCollector() = default;

void DumpCollector::event(const TraceLog& log, const TraceEvent& e) { impl_->event(log, e); }

namespace {

void dump_screen(const TraceLog& log, const State& s, ObjectText& j) {
  const int c = array_id(log, "C"), e = array_id(log, "E");
  nested(j.key("heads"), s[c], log.arrays()[c].shape, j.inner());
  int_array(j.key("next"), s[e]);
}

void dump_tree(const TraceLog& log, const State& s, const Grid& g, ObjectText& j) {
  const int child = array_id(log, "child"), head = array_id(log, "HEAD"), e = array_id(log, "E");
  j.key("nodes").integer(static_cast<std::int64_t>(s[head].size()));
  DumpText& text = j.key("leaves");
  ListText leaves(text, j.inner());
  for (const TreeLeaf& leaf : tree_leaves(g, s[child], s[head])) {
    leaves.item();
    ObjectText o(text, leaves.inner());
    o.key("node").integer(leaf.node);
    int_array(o.key("cell"), std::span<const std::int32_t>(leaf.cell, static_cast<std::size_t>(g.dim)));
    o.key("bounds") << "[";
    for (int side = 0; side < 2; ++side) {
      text << (side ? ", [" : "[");
      for (int a = 0; a < g.dim; ++a) (a ? text << ", " : text).real(g.origin[a] + g.cell_size * (leaf.cell[a] + side));
      text << "]";
    }
    text << "]";
    o.key("head").integer(leaf.head);
    o.close();
  }
  leaves.close();
  int_array(j.key("next"), s[e]);
}

void dump_sort(const TraceLog& log, const State& s, int dim, ObjectText& j) {
  const char* names[3] = {"ix", "iy", "iz"};
  int ids[3] = {-1, -1, -1};
  for (int a = 0; a < dim; ++a) ids[a] = array_id(log, names[a]);
  const int order = array_id(log, "order");
  DumpText& text = j.key("keys") << "[";
  for (std::size_t i = 0; i < s[order].size(); ++i) {
    const std::int32_t k = s[order][i];
    text << (i ? ", [" : "[");
    for (int a = 0; a < dim; ++a) (a ? text << ", " : text).integer(s[ids[a]][k]);
    text << "]";
  }
  text << "]";
  int_array(j.key("order"), s[order]);
  for (int a = 0; a < dim; ++a) int_array(j.key(names[a]), s[ids[a]]);
}

void dump_nbs_2d(const TraceLog& log, const State& ys, const std::vector<RowLists>& rows, ObjectText& j) {
  int_array(j.key("y_heads"), ys[array_id(log, "y_heads")]);
  int_array(j.key("y_next"), ys[array_id(log, "Y")]);
  DumpText& text = j.key("rows");
  ListText list(text, j.inner());
  for (const RowLists& row : rows) {
    list.item();
    row_object(text, row, list.inner());
  }
  list.close();
}

void dump_nbs_3d(const TraceLog& log, const State& zs, const std::vector<LayerLists>& layers, ObjectText& j) {
  int_array(j.key("z_heads"), zs[array_id(log, "C")]);
  int_array(j.key("z_next"), zs[array_id(log, "Z")]);
  DumpText& text = j.key("layers");
  ListText list(text, j.inner());
  for (const LayerLists& l : layers) {
    list.item();
    ObjectText layer(text, list.inner());
    layer.key("iz").integer(l.iz);
    pair_array(layer.key("y_heads"), l.lists.heads);
    pair_array(layer.key("y_next"), l.lists.next);
    ListText row_list(layer.key("rows"), layer.inner());
    for (const RowLists& row : l.rows) {
      row_list.item();
      row_object(text, row, row_list.inner());
    }
    row_list.close();
    layer.close();
  }
  list.close();
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

void DumpCollector::write(const DumpSource& src, std::ostream& out) const {
  if (src.elements == nullptr || src.trace == nullptr) throw Error("dump: internal: nothing to dump");
  const Elements& e = *src.elements;
  const TraceLog& log = *src.trace;
  DumpText text(out);
  ObjectText j(text, 0);
  j.key("algorithm").string(src.algorithm);
  j.key("dim").integer(e.dim);
  j.key("elements").integer(e.size());
  j.key("pairs").integer(static_cast<std::int64_t>(src.pairs));
  if (src.grid != nullptr) {
    const Grid& g = *src.grid;
    j.key("cell_size").real(g.cell_size);
    j.key("origin") << "[";
    for (int a = 0; a < g.dim; ++a) (a ? text << ", " : text).real(g.origin[a]);
    text << "]";
    j.key("nx").integer(g.n[0]);
    j.key("ny").integer(g.n[1]);
    if (g.dim == 3) j.key("nz").integer(g.n[2]);
  }
  j.key("own_bytes").integer(static_cast<std::int64_t>(src.own_bytes));
  // Bytes of each array by name (a name declared twice keeps its first place and its last size).
  std::vector<std::pair<std::string, std::int64_t>> bytes;
  for (const TracedArray& a : log.arrays()) {
    std::int64_t count = 1;
    for (std::int64_t s : a.shape) count *= s;
    const std::int64_t size = count * static_cast<std::int64_t>(sizeof(std::int32_t));
    const auto same = std::find_if(bytes.begin(), bytes.end(), [&](const auto& b) { return b.first == a.name; });
    if (same != bytes.end()) {
      same->second = size;
    } else {
      bytes.emplace_back(a.name, size);
    }
  }
  if (bytes.empty()) {
    j.key("bytes") << "{}";
  } else {
    ObjectText o(j.key("bytes"), j.inner());
    for (const auto& [name, size] : bytes) o.key(name).integer(size);
    o.close();
  }
  // No book arrays (brute, box2d): counts only. Otherwise each algorithm has its own arrays, so its
  // own keys (docs/formats.md "Arrays JSON").
  if (!log.arrays().empty() && src.grid != nullptr) {
    const Impl& c = *impl_;
    if (src.algorithm == "screen") {
      dump_screen(log, c.shown(), j);
    } else if (src.algorithm == "tree") {
      dump_tree(log, c.shown(), *src.grid, j);
    } else if (src.algorithm == "sort") {
      dump_sort(log, c.shown(), e.dim, j);
    } else if (src.algorithm == "nbs" && e.dim == 3) {
      dump_nbs_3d(log, c.shown(), c.layers, j);
    } else if (src.algorithm == "nbs") {
      dump_nbs_2d(log, c.shown(), c.rows, j);
    }
  }
  j.close();
  text << "\n";
  text.flush();
}

void write_dump(const DumpSource& source, std::ostream& out) {
  if (source.elements == nullptr || source.trace == nullptr) throw Error("dump: internal: nothing to dump");
  DumpCollector collector(source.algorithm, source.elements->dim);
  for (const TraceEvent& e : source.trace->events()) collector.event(*source.trace, e);
  collector.write(source, out);
}

json dump_json(const DumpSource& source) {
  std::ostringstream text;
  write_dump(source, text);
  return json::parse(text.str());
}

std::string format_dump(const json& v) {
  std::string out;
  format_value(v, 0, out);
  out += "\n";
  return out;
}

}  // namespace nbscope

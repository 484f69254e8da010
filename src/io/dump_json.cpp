// Index: helpers (arrays by name, snapshots) | the streamed text (buffer, objects, arrays, lists as
// [k, next] pairs, a nest's objects) | DumpCollector | one function per form of the schema (a
// family's heads, a tree's leaves, sort's arrays) | write | write_dump | dump_json | format_dump.
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

#include "core/array_schema.hpp"
#include "core/error.hpp"
#include "core/lists.hpp"
#include "core/tree.hpp"

namespace nbscope {

namespace {

using json = nlohmann::ordered_json;
using State = std::vector<std::vector<std::int32_t>>;

int array_id(const TraceLog& log, const char* name) {
  const int id = log.array_id(name);
  if (id < 0) throw Error(std::string("dump: internal: the trace has no array '") + name + "'");
  return id;
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

// The lists of one object of a nest (core/array_schema.hpp: an nbs row or 3D layer): its cell
// index, its lists and the objects of the nest inside it (a layer's rows), in index order.
struct NestLists {
  std::int64_t index = 0;
  SparseLists lists;
  std::vector<NestLists> inner;
};

// `items` as the value of `nests.front().key` in `parent`: one object a line, each
// {index_key, heads_key, next_key[, the inner nest's key]}.
void nest_list(DumpText& text, ObjectText& parent, std::span<const array_schema::Nest> nests, const std::vector<NestLists>& items) {
  const array_schema::Nest& nest = nests.front();
  ListText list(parent.key(nest.key), parent.inner());
  for (const NestLists& item : items) {
    list.item();
    ObjectText o(text, list.inner());
    o.key(nest.index_key).integer(item.index);
    pair_array(o.key(nest.family.heads_key), item.lists.heads);
    pair_array(o.key(nest.family.next_key), item.lists.next);
    if (nests.size() > 1) nest_list(text, o, nests.subspan(1), item.inner);
    o.close();
  }
  list.close();
}

}  // namespace

// ---- DumpCollector --------------------------------------------------------------------------
//
// What each algorithm shows (docs/formats.md "Arrays JSON"; core/array_schema.hpp): its arrays right before
// the layout's phase `shown_at` (screen, tree and sort: the contacts; nbs: the y-lists (z-lists in 3D)
// before they are cleared) and the lists of each nest's objects when they are complete (nbs: each
// row's x-lists, B[0] or A[0]; 3D: each layer's y-lists, B[0]). The events are applied to one copy
// of the arrays as they come; a snapshot is taken at the phase shown, the lists of a nest's object
// at its end phase.

struct DumpCollector::Impl {
  const array_schema::Layout* layout = nullptr;  // nullptr: no book arrays (brute, box2d)
  const char* shown_at = "";     // the phase whose state the dump's arrays are
  State state;                   // every declared array as the events so far leave it
  std::optional<State> snapshot;  // the state right before the first `shown_at` phase
  // Per nest (outermost first): the ids of its lists' traced arrays (-1 until declared), the heads
  // its current object touched, the objects completed inside the current outer one.
  struct Level {
    int heads = -1, next = -1;
    std::vector<std::int64_t> touched;
    std::vector<NestLists> done;
  };
  std::vector<Level> levels;

  static std::int64_t width(const TraceLog& log, int id) { return log.arrays()[static_cast<std::size_t>(id)].shape.back(); }

  void event(const TraceLog& log, const TraceEvent& ev) {
    while (state.size() < log.arrays().size()) state.push_back(log.arrays()[state.size()].initial);
    if (!snapshot && is_phase(ev, shown_at)) snapshot = state;
    for (std::size_t d = 0; d < levels.size(); ++d) nest_event(log, ev, d);
    TraceLog::apply(ev, state);
  }

  // Nest d's object begins (its heads and its inner objects start afresh), ends (its lists are kept
  // with its inner objects, in index order), or a push onto its heads.
  void nest_event(const TraceLog& log, const TraceEvent& ev, std::size_t d) {
    const array_schema::Nest& nest = layout->nests[d];
    Level& level = levels[d];
    declared(log, nest.family.heads_trace, level.heads);
    declared(log, nest.family.next_trace, level.next);
    if (is_phase(ev, nest.begin_phase)) {
      level.touched.clear();
      for (std::size_t i = d + 1; i < levels.size(); ++i) levels[i].done.clear();
    }
    if (is_phase(ev, nest.end_phase)) {
      NestLists item{ev.index, sparse_lists(state[level.heads], state[level.next], level.touched, 0, width(log, level.heads)), {}};
      if (d + 1 < levels.size()) {
        item.inner = levels[d + 1].done;
        std::stable_sort(item.inner.begin(), item.inner.end(), [](const NestLists& p, const NestLists& q) { return p.index < q.index; });
      }
      level.done.push_back(std::move(item));
    }
    if (ev.op == TraceOp::Push && level.heads >= 0 && ev.writes[1].array == level.heads) level.touched.push_back(ev.writes[1].index);
  }

  // The arrays as shown: the snapshot, or the state after the whole run when the phase never came.
  const State& shown() const { return snapshot ? *snapshot : state; }
};

DumpCollector::DumpCollector(std::string algorithm, int dim) : impl_(std::make_unique<Impl>()) {
  impl_->layout = array_schema::find_layout(algorithm, dim);
  impl_->shown_at = impl_->layout != nullptr ? impl_->layout->shown_at : phase_label::kContacts;
  if (impl_->layout != nullptr) impl_->levels.resize(impl_->layout->nests.size());
}
DumpCollector::~DumpCollector() = default;

void DumpCollector::event(const TraceLog& log, const TraceEvent& e) { impl_->event(log, e); }

namespace {

// A tree's node count and leaves [{node, cell, bounds, head}].
void dump_leaves(const TraceLog& log, const State& s, const Grid& g, const array_schema::Family& f, ObjectText& j) {
  const int child = array_id(log, array_schema::kTreeChildTrace), head = array_id(log, f.heads_trace);
  j.key(array_schema::kNodesKey).integer(static_cast<std::int64_t>(s[head].size()));
  DumpText& text = j.key(f.heads_key);
  ListText leaves(text, j.inner());
  for (const TreeLeaf& leaf : tree_leaves(g, s[child], s[head])) {
    leaves.item();
    ObjectText o(text, leaves.inner());
    o.key(array_schema::kLeafNodeKey).integer(leaf.node);
    int_array(o.key(array_schema::kLeafCellKey), std::span<const std::int32_t>(leaf.cell, static_cast<std::size_t>(g.dim)));
    o.key("bounds") << "[";
    for (int side = 0; side < 2; ++side) {
      text << (side ? ", [" : "[");
      for (int a = 0; a < g.dim; ++a) (a ? text << ", " : text).real(g.origin[a] + g.cell_size * (leaf.cell[a] + side));
      text << "]";
    }
    text << "]";
    o.key(array_schema::kLeafHeadKey).integer(leaf.head);
    o.close();
  }
  leaves.close();
}

// sort's keys, order and each element's cell index (the traced arrays of the same names).
void dump_sort(const TraceLog& log, const State& s, int dim, ObjectText& j) {
  const array_schema::SortArraysSchema& k = array_schema::kSort;
  int ids[3] = {-1, -1, -1};
  for (int a = 0; a < dim; ++a) ids[a] = array_id(log, k.axis_keys[a]);
  const int order = array_id(log, k.order_key);
  DumpText& text = j.key(k.keys_key) << "[";
  for (std::size_t i = 0; i < s[order].size(); ++i) {
    const std::int32_t e = s[order][i];
    text << (i ? ", [" : "[");
    for (int a = 0; a < dim; ++a) (a ? text << ", " : text).integer(s[ids[a]][e]);
    text << "]";
  }
  text << "]";
  int_array(j.key(k.order_key), s[order]);
  for (int a = 0; a < dim; ++a) int_array(j.key(k.axis_keys[a]), s[ids[a]]);
}

// A family at the document's top: its heads as the layout lays them out, then its next array.
void dump_family(const TraceLog& log, const State& s, const Grid& g, const array_schema::Family& f, ObjectText& j) {
  const int heads = array_id(log, f.heads_trace);
  switch (f.form) {
    case array_schema::HeadsForm::Cells: nested(j.key(f.heads_key), s[heads], log.arrays()[heads].shape, j.inner()); break;
    case array_schema::HeadsForm::Leaves: dump_leaves(log, s, g, f, j); break;
    case array_schema::HeadsForm::Dense:
    case array_schema::HeadsForm::Pairs: int_array(j.key(f.heads_key), s[heads]); break;
  }
  int_array(j.key(f.next_key), s[array_id(log, f.next_trace)]);
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
  if (src.ids != nullptr && !src.ids->empty()) {
    j.key("ids") << "[";
    for (std::size_t k = 0; k < src.ids->size(); ++k) (k ? text << ", " : text).integer((*src.ids)[k]);
    text << "]";
  }
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
  // No book arrays (brute, box2d): counts only. Otherwise the keys of the algorithm's layout
  // (core/array_schema.hpp), in its order.
  const array_schema::Layout* layout = array_schema::find_layout(src.algorithm, e.dim);
  if (!log.arrays().empty() && src.grid != nullptr && layout != nullptr) {
    const State& shown = impl_->shown();
    for (const array_schema::Family& f : layout->families) dump_family(log, shown, *src.grid, f, j);
    if (layout->sort) dump_sort(log, shown, e.dim, j);
    if (!layout->nests.empty() && !impl_->levels.empty()) nest_list(text, j, layout->nests, impl_->levels.front().done);
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

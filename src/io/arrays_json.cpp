// Index: Reader (typed access with JSON paths) | one builder per form of heads in the schema
// (core/array_schema.hpp: cells, pairs and the nests holding them, dense, leaves) | sort | header
// keys | ArraysJson::arrays (the layout's families, sort, nests) | read/parse.
#include "io/arrays_json.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <type_traits>
#include <vector>

#include "core/array_schema.hpp"
#include "core/error.hpp"
#include "io/arrays_json_tree.hpp"
#include "io/excerpt.hpp"

namespace nbscope {

namespace {

using Value = arrays_tree::Value;
using array_schema::Family;
using array_schema::Nest;
using verify::ListFamily;
using verify::UserList;

std::string at(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

// A JSON path as text, or as a function that writes it: the loops over every entry pass functions,
// so a path is only written when a message needs it.
template <class Path>
std::string text_of(const Path& path) {
  if constexpr (std::is_invocable_v<const Path&>) {
    return path();
  } else {
    return std::string(path);
  }
}
std::string key(const std::string& path, const char* name) { return path + "." + name; }

// Typed access to the document; every failure names the file and the value's JSON path.
class Reader {
 public:
  Reader(const std::string& where, int base, std::int64_t n) : where_(where), base_(base), n_(n) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const { throw Error(where_ + ": " + path + ": " + what); }

  Value member(const Value& object, const std::string& path, const char* name, const char* meaning) const {
    const auto it = object.find(name);
    if (!it) fail(path, std::string("no \"") + name + "\" key (" + meaning + ")");
    return *it;
  }
  template <class Path>
  Value array(const Value& v, const Path& path, std::optional<std::int64_t> length = {}, const char* of = "") const {
    if (!v.is_array()) fail(text_of(path), std::string(type(v)) + ", but an array is expected");
    if (length && static_cast<std::int64_t>(v.size()) != *length)
      fail(text_of(path), std::to_string(v.size()) + " entries, but " + of + " is " + std::to_string(*length));
    return v;
  }
  template <class Path>
  std::int64_t integer(const Value& v, const Path& path) const {
    if (v.is_array()) fail(text_of(path), "an array, but a number is expected (arrays of another dimension?)");
    if (!v.is_number_integer()) fail(text_of(path), std::string(type(v)) + ", but a whole number is expected");
    const std::int64_t i = v.integer();
    if (i < std::numeric_limits<std::int32_t>::min() || i > std::numeric_limits<std::int32_t>::max())
      fail(text_of(path), std::to_string(i) + " is beyond 32 bits (the book's arrays are int32)");
    return i;
  }
  // An element index (or -1) as the file writes it, shifted to 0-based. A negative one other than
  // -1 is a wrong entry that verify reports, except the few at the bottom of int32 that would
  // collide with verify's own markers (kZeroInBase1 and the one for an entry not given).
  template <class Path>
  std::int32_t element(const Value& v, const Path& path) const {
    const std::int64_t i = integer(v, path);
    if (i == -1) return -1;
    if (i - base_ < std::numeric_limits<std::int32_t>::min() + 2)
      fail(text_of(path), std::to_string(i) + " is a negative index other than -1: elements count from " + std::to_string(base_) +
                              ", and -1 ends a list");
    if (base_ == 1 && i == 0) return verify::kZeroInBase1;
    return static_cast<std::int32_t>(i - base_);
  }
  // A cell index on an axis of `n` cells, shifted to 0-based; outside the grid is bad input (a slot, not a value).
  template <class Path>
  std::int32_t cell(const Value& v, const Path& path, std::int64_t n, const char* axis) const {
    const std::int64_t i = integer(v, path) - base_;
    if (i < 0 || i >= n)
      fail(text_of(path), std::to_string(i + base_) + " is not a" + (axis[0] == 'i' ? "n " : " ") + axis + " of the grid (" +
           std::to_string(base_) + ".." + std::to_string(n - 1 + base_) + ")");
    return static_cast<std::int32_t>(i);
  }
  // A dense next array of N entries.
  std::vector<std::int32_t> next_array(const Value& v, const std::string& path) const {
    array(v, path, n_, "N, the number of elements,");
    std::vector<std::int32_t> out(v.size());
    std::size_t k = 0;
    for (const Value e : v) {
      out[k] = element(e, [&] { return at(path, k); });
      ++k;
    }
    return out;
  }
  // Sparse [slot, head] or [k, next] pairs.
  template <class Path>
  Value pair(const Value& v, const Path& path) const {
    if (!v.is_array() || v.size() != 2) fail(text_of(path), "not a pair [index, value]");
    return v;
  }
  int base() const { return base_; }
  std::int64_t n() const { return n_; }

 private:
  static const char* type(const Value& v) {
    if (v.is_object()) return "an object";
    if (v.is_array()) return "an array";
    if (v.is_string()) return "a string";
    if (v.is_boolean()) return "a boolean";
    if (v.is_null()) return "null";
    return "a fraction";
  }
  std::string where_;
  int base_;
  std::int64_t n_;
};

const char* const kCellAxes[3] = {"ix", "iy", "iz"};
const char* const kCellCounts[3] = {"nx", "ny", "nz"};

// A family's names, form and order as the schema gives them (core/array_schema.hpp).
ListFamily family_of(const Family& s) {
  ListFamily f;
  f.heads_name = s.heads_name;
  f.next_name = s.next_name;
  f.heads_form = s.form;
  f.ascending = s.ascending;
  return f;
}

// ---- HeadsForm::Cells (screen): heads [ix][iy]([iz]), a dense next array ----
ListFamily cells_family(const Reader& r, const Value& doc, const Grid& g, const Family& s) {
  ListFamily f = family_of(s);
  f.next_path = key("$", s.next_key);
  f.heads_path = key("$", s.heads_key);
  const int dim = g.dim;
  for (int a = 0; a < dim; ++a) f.heads_shape.push_back(g.n[a]);
  const Value heads = r.member(doc, "$", s.heads_key, s.heads_meaning);
  // Walk the nest axis by axis, checking each level's length.
  struct Level {
    Value v;
    std::array<std::int32_t, 3> cell;  // the indices so far (-1 below this level)
  };
  const auto path_of = [&](const std::array<std::int32_t, 3>& cell) {
    std::string p = f.heads_path;
    for (std::int32_t i : cell)
      if (i >= 0) p = at(p, static_cast<std::size_t>(i));
    return p;
  };
  std::vector<Level> level{{heads, {-1, -1, -1}}};
  for (int a = 0; a < dim; ++a) {
    std::vector<Level> deeper;
    for (const Level& l : level) {
      r.array(l.v, [&] { return path_of(l.cell); }, g.n[a], kCellCounts[a]);
      std::int32_t i = 0;
      for (const Value v : l.v) {
        Level d{v, l.cell};
        d.cell[a] = i++;
        if (a + 1 < dim) {
          deeper.push_back(d);
          continue;
        }
        const std::int32_t head = r.element(d.v, [&] { return path_of(d.cell); });
        if (head == -1) continue;
        UserList list;
        list.slot = g.flat(d.cell[0], d.cell[1], dim == 3 ? d.cell[2] : 0);
        list.head = head;
        list.cell = d.cell;
        f.lists.push_back(std::move(list));
      }
    }
    level = std::move(deeper);
  }
  f.next = r.next_array(r.member(doc, "$", s.next_key, s.next_meaning), f.next_path);
  return f;
}

// ---- HeadsForm::Pairs (nbs rows, 3D layers): [slot, head] pairs, [k, next[k]] pairs ----
// The slot is the cell index on the family's axis (of `n` cells).
ListFamily sparse_family(const Reader& r, const Value& object, const std::string& path, const Family& s, std::int64_t n) {
  ListFamily f = family_of(s);
  f.sparse = true;
  f.heads_shape = {n};
  const std::string hp = key(path, s.heads_key);
  f.heads_path = hp;
  const int axis = s.axis;
  const Value heads = r.array(r.member(object, path, s.heads_key, s.heads_meaning), hp);
  f.lists.reserve(heads.size());
  std::size_t i = 0;
  for (const Value item : heads) {
    const auto p = [&](std::size_t j) { return at(at(hp, i), j); };
    const Value h = r.pair(item, [&] { return at(hp, i); });
    UserList list;
    list.cell[axis] = r.cell(h[0], [&] { return p(0); }, n, kCellAxes[axis]);
    list.slot = list.cell[axis];
    list.head = r.element(h[1], [&] { return p(1); });
    if (list.head != -1) {
      list.entry = static_cast<std::int32_t>(i);
      f.lists.push_back(std::move(list));
    }
    ++i;
  }
  f.next_path = key(path, s.next_key);
  const Value next = r.array(r.member(object, path, s.next_key, s.next_meaning), f.next_path);
  f.next_pairs.reserve(next.size());
  i = 0;
  for (const Value item : next) {
    const auto p = [&](std::size_t j) { return at(at(f.next_path, i), j); };
    const Value e = r.pair(item, [&] { return at(f.next_path, i); });
    f.next_pairs.push_back({r.element(e[0], [&] { return p(0); }), r.element(e[1], [&] { return p(1); })});
    ++i;
  }
  return f;
}

// "{iz, y_heads, y_next, rows}": what an object of the first of `nests` holds.
std::string nest_fields(std::span<const Nest> nests) {
  const Nest& n = nests.front();
  std::string out = std::string("{") + n.index_key + ", " + n.family.heads_key + ", " + n.family.next_key;
  if (nests.size() > 1) out += std::string(", ") + nests[1].key;
  return out + "}";
}

// The objects of the first of `nests` in `object` (nbs rows, 3D layers holding rows), one family
// each, scoped to its cell index within `scope`; optional: the outer lists alone can be checked.
void build_nests(const Reader& r, const Value& object, const std::string& path, const Grid& g, std::span<const Nest> nests,
                 const std::array<std::int32_t, 3>& scope, verify::UserArrays& out) {
  const Nest& nest = nests.front();
  const auto items = object.find(nest.key);
  if (!items) return;
  const std::string np = key(path, nest.key);
  r.array(*items, np);
  std::size_t i = 0;
  for (const Value item : *items) {
    const std::string p = at(np, i++);
    if (!item.is_object()) r.fail(p, "not an object " + nest_fields(nests));
    const std::int32_t index = r.cell(r.member(item, p, nest.index_key, (std::string("the ") + nest.word).c_str()),
                                      key(p, nest.index_key), g.n[nest.axis], nest.word);
    ListFamily f = sparse_family(r, item, p, nest.family, g.n[nest.family.axis]);
    f.scope = scope;
    f.scope[nest.axis] = index;
    const std::array<std::int32_t, 3> inner = f.scope;
    out.families.push_back(std::move(f));
    if (nests.size() > 1) build_nests(r, item, p, g, nests.subspan(1), inner, out);
  }
}

// ---- HeadsForm::Dense (nbs y-lists in 2D, z-lists in 3D): a head per cell index on the family's axis ----
ListFamily dense_family(const Reader& r, const Value& doc, const Grid& g, const Family& s) {
  const int axis = s.axis;
  ListFamily f = family_of(s);
  f.heads_shape = {g.n[axis]};
  const std::string hp = key("$", s.heads_key);
  f.heads_path = hp;
  const Value heads = r.array(r.member(doc, "$", s.heads_key, s.heads_meaning), hp, g.n[axis], kCellCounts[axis]);
  std::size_t i = 0;
  for (const Value h : heads) {
    UserList l;
    l.slot = static_cast<std::int64_t>(i);
    l.head = r.element(h, [&] { return at(hp, i); });
    if (l.head != -1) {
      l.cell[axis] = static_cast<std::int32_t>(i);
      f.lists.push_back(std::move(l));
    }
    ++i;
  }
  f.next_path = key("$", s.next_key);
  f.next = r.next_array(r.member(doc, "$", s.next_key, s.next_meaning), f.next_path);
  return f;
}

// ---- HeadsForm::Leaves (tree): leaves [{node, cell, head}], a dense next array ----
ListFamily leaves_family(const Reader& r, const Value& doc, const Grid& g, const Family& s) {
  namespace k = array_schema;
  ListFamily f = family_of(s);
  f.heads_path = key("$", s.heads_key);
  const Value leaves = r.array(r.member(doc, "$", s.heads_key, s.heads_meaning), f.heads_path);
  std::int64_t nodes = 0;
  if (const auto it = doc.find(k::kNodesKey)) nodes = r.integer(*it, key("$", k::kNodesKey));
  const std::string leaf_fields = std::string("{") + k::kLeafNodeKey + ", " + k::kLeafCellKey + ", " + k::kLeafHeadKey + "}";
  std::size_t i = 0;
  for (const Value leaf : leaves) {
    const std::string p = at(f.heads_path, i++);
    if (!leaf.is_object()) r.fail(p, "not an object " + leaf_fields);
    UserList l;
    l.slot = r.integer(r.member(leaf, p, k::kLeafNodeKey, (std::string("its index in ") + s.heads_name).c_str()), key(p, k::kLeafNodeKey)) -
             r.base();
    if (l.slot < 0) r.fail(key(p, k::kLeafNodeKey), "not a node index (from " + std::to_string(r.base()) + ")");
    nodes = std::max(nodes, l.slot + 1);
    const std::string cp = key(p, k::kLeafCellKey);
    const Value cell = r.array(r.member(leaf, p, k::kLeafCellKey, "[ix, iy(, iz)]"), cp, g.dim, "dim");
    for (int a = 0; a < g.dim; ++a) l.cell[a] = r.cell(cell[static_cast<std::size_t>(a)], at(cp, static_cast<std::size_t>(a)), g.n[a], kCellAxes[a]);
    l.head = r.element(r.member(leaf, p, k::kLeafHeadKey, (std::string("its ") + s.heads_name).c_str()), key(p, k::kLeafHeadKey));
    l.entry = static_cast<std::int32_t>(i - 1);
    if (l.head != -1) f.lists.push_back(std::move(l));
  }
  f.heads_shape = {std::max<std::int64_t>(nodes, 1)};
  f.next_path = key("$", s.next_key);
  f.next = r.next_array(r.member(doc, "$", s.next_key, s.next_meaning), f.next_path);
  return f;
}

// A family at the document's top, by the form of its heads.
ListFamily document_family(const Reader& r, const Value& doc, const Grid& g, const Family& s) {
  switch (s.form) {
    case array_schema::HeadsForm::Cells: return cells_family(r, doc, g, s);
    case array_schema::HeadsForm::Dense: return dense_family(r, doc, g, s);
    case array_schema::HeadsForm::Leaves: return leaves_family(r, doc, g, s);
    case array_schema::HeadsForm::Pairs: break;
  }
  return sparse_family(r, doc, "$", s, g.n[s.axis]);
}

// ---- sort: keys, order, ix, iy (iz) ----
void build_sort(const Reader& r, const Value& doc, const Grid& g, verify::UserArrays& out) {
  verify::SortArrays s;
  const array_schema::SortArraysSchema& names = array_schema::kSort;
  const auto cell_value = [&](const Value& v, const auto& p) {
    const std::int64_t i = r.integer(v, p) - r.base();
    return static_cast<std::int32_t>(std::clamp<std::int64_t>(i, -2, std::numeric_limits<std::int32_t>::max()));
  };
  const Value keys = r.array(r.member(doc, "$", names.keys_key, "the cell of each sorted position"), key("$", names.keys_key), r.n(), "N");
  std::size_t p = 0;
  for (const Value item : keys) {
    const Value k = r.array(item, [&] { return at(key("$", names.keys_key), p); }, g.dim, "dim");
    std::array<std::int32_t, 3> cell{-1, -1, -1};
    for (int a = 0; a < g.dim; ++a) {
      const auto i = static_cast<std::size_t>(a);
      cell[a] = cell_value(k[i], [&] { return at(at(key("$", names.keys_key), p), i); });
    }
    s.keys.push_back(cell);
    ++p;
  }
  const Value order = r.array(r.member(doc, "$", names.order_key, "the element at each sorted position"), key("$", names.order_key), r.n(), "N");
  p = 0;
  for (const Value v : order) {
    s.order.push_back(r.element(v, [&] { return at(key("$", names.order_key), p); }));
    ++p;
  }
  for (int a = 0; a < g.dim; ++a) {
    const std::string path = key("$", names.axis_keys[a]);
    const Value v = r.array(r.member(doc, "$", names.axis_keys[a], "each element's integerised coordinate"), path, r.n(), "N");
    std::size_t k = 0;
    for (const Value c : v) {
      s.cell_of[a].push_back(cell_value(c, [&] { return at(path, k); }));
      ++k;
    }
  }
  out.sort = std::move(s);
}

std::int64_t positive(const Reader& r, const Value& doc, const char* name) {
  const std::int64_t v = r.integer(*doc.find(name), std::string("$.") + name);
  if (v < 1) r.fail(std::string("$.") + name, std::to_string(v) + " cells: at least 1 is needed");
  return v;
}

// The header keys of a document read whole.
ArraysJson with_header(std::shared_ptr<const arrays_tree::Tree> tree, const std::string& where) {
  ArraysJson a;
  a.path = where;
  a.doc = std::move(tree);
  const Value doc = a.doc->root();
  const Reader r(where, 0, 0);
  if (!doc.is_object())
    r.fail("$", "not an object: ARRAYS.json is the object `nbscope dump` writes ({\"algorithm\": ..., \"heads\": ...})");
  if (doc.contains("bodies") || doc.contains("frames"))
    r.fail("$", "a scene or a report, not arrays: ARRAYS.json is the object `nbscope dump` writes");
  if (const auto it = doc.find("algorithm")) {
    if (!it->is_string()) r.fail("$.algorithm", "not a string");
    a.algorithm = it->text();
    // Quoted in later messages and window titles: a name, not a document (the tree keeps 128 bytes).
    if (a.algorithm->size() > 64) r.fail("$.algorithm", "\"" + excerpt(*a.algorithm) + "\" is not an algorithm's name");
  }
  if (const auto v = doc.find("dim")) {
    const std::int64_t d = r.integer(*v, "$.dim");
    if (d != 2 && d != 3) r.fail("$.dim", std::to_string(d) + ", but 2 or 3 is expected");
    a.dim = static_cast<int>(d);
  }
  if (const auto v = doc.find("base")) {
    const std::int64_t b = r.integer(*v, "$.base");
    if (b != 0 && b != 1) r.fail("$.base", std::to_string(b) + ", but 0 (C, C++) or 1 (the book, Fortran) is expected");
    a.base = static_cast<int>(b);
  }
  if (const auto v = doc.find("elements")) {
    a.elements = r.integer(*v, "$.elements");
    if (*a.elements < 0) r.fail("$.elements", "a negative number of elements");
  }
  if (const auto d = doc.find("cell_size")) {
    if (!d->is_number() || !std::isfinite(d->number()) || d->number() <= 0) r.fail("$.cell_size", "not a positive finite number");
    a.grid.cell_size = d->number();
  }
  const int dim = a.dim.value_or(2);
  if (const auto o = doc.find("origin")) {
    if (!o->is_array() || (o->size() != 2 && o->size() != 3)) r.fail("$.origin", "not [x, y] or [x, y, z]");
    std::array<double, 3> origin{0, 0, 0};
    for (std::size_t i = 0; i < o->size(); ++i) {
      const Value c = (*o)[i];
      if (!c.is_number() || !std::isfinite(c.number())) r.fail(at("$.origin", i), "not a finite number");
      origin[i] = c.number();
    }
    if (a.dim && static_cast<int>(o->size()) != dim)
      r.fail("$.origin", std::to_string(o->size()) + " coordinates, but \"dim\" is " + std::to_string(dim));
    a.grid.origin = origin;
  }
  const bool nx = doc.contains("nx"), ny = doc.contains("ny"), nz = doc.contains("nz");
  if (nx || ny || nz) {
    if (!nx || !ny) r.fail(nx ? "$.ny" : "$.nx", "missing: nx and ny (nz in 3D) pin the grid together");
    std::array<std::int64_t, 3> cells{positive(r, doc, "nx"), positive(r, doc, "ny"), nz ? positive(r, doc, "nz") : 1};
    a.grid.cells = cells;
    a.has_cells = true;
  }
  return a;
}

}  // namespace

verify::UserArrays ArraysJson::arrays(const std::string& name, const Grid& g, std::int64_t n, int base_used) const {
  const Reader r(path, base_used, n);
  verify::UserArrays out;
  out.algorithm = name;
  out.dim = g.dim;
  out.base = base_used;
  if (!doc) throw Error(path + ": the arrays were taken already");  // a programming error, said as one line
  const Value root = doc->root();
  const array_schema::Layout* layout = array_schema::find_layout(name, g.dim);
  if (layout == nullptr)
    throw Error("--algorithm: verify checks the arrays of " + array_schema::algorithms_text() + " ('" + name + "' keeps no book arrays)");
  for (const Family& f : layout->families) out.families.push_back(document_family(r, root, g, f));
  if (layout->sort) build_sort(r, root, g, out);
  if (!layout->nests.empty()) build_nests(r, root, "$", g, layout->nests, {-1, -1, -1}, out);
  return out;
}

ArraysJson parse_arrays_json(const std::string& text, const std::string& where) {
  return with_header(arrays_tree::parse_text(text, where), where);
}

ArraysJson read_arrays_json(const std::string& path) {
  return with_header(arrays_tree::read_file(path, kMaxArraysBytes), path);
}

}  // namespace nbscope

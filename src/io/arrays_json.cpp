// Index: Reader (typed access with JSON paths) | header keys | one builder per algorithm (screen,
// nbs 2D, nbs 3D, tree, sort) | ArraysJson::arrays | read/parse.
#include "io/arrays_json.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "core/error.hpp"
#include "io/arrays_json_tree.hpp"
#include "io/excerpt.hpp"

namespace nbscope {

namespace {

using Value = arrays_tree::Value;
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

// ---- screen: heads [ix][iy]([iz]) = C, next = E ----
void build_screen(const Reader& r, const Value& doc, const Grid& g, verify::UserArrays& out) {
  ListFamily f;
  f.heads_name = "C";
  f.next_name = "E";
  f.next_path = "$.next";
  f.heads_path = "$.heads";
  f.heads_form = verify::HeadsForm::Cells;
  const int dim = g.dim;
  for (int a = 0; a < dim; ++a) f.heads_shape.push_back(g.n[a]);
  const Value heads = r.member(doc, "$", "heads", "the screen array C[nx][ny] of list heads");
  const char* axes[3] = {"nx", "ny", "nz"};
  // Walk the nest axis by axis, checking each level's length.
  struct Level {
    Value v;
    std::array<std::int32_t, 3> cell;  // the indices so far (-1 below this level)
  };
  const auto path_of = [](const std::array<std::int32_t, 3>& cell) {
    std::string p = "$.heads";
    for (std::int32_t i : cell)
      if (i >= 0) p = at(p, static_cast<std::size_t>(i));
    return p;
  };
  std::vector<Level> level{{heads, {-1, -1, -1}}};
  for (int a = 0; a < dim; ++a) {
    std::vector<Level> deeper;
    for (const Level& l : level) {
      r.array(l.v, [&] { return path_of(l.cell); }, g.n[a], axes[a]);
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
  f.next = r.next_array(r.member(doc, "$", "next", "E, the next array"), "$.next");
  out.families.push_back(std::move(f));
}

// A family of lists whose heads are given as [slot, head] pairs (NBS rows, 3D layers): the slot is
// the cell index on `axis` (of `n` cells); the next array as [k, next[k]] pairs.
ListFamily sparse_family(const Reader& r, const Value& object, const std::string& path, const char* heads_key,
                         const char* next_key, const char* heads_name, const char* next_name, int axis, std::int64_t n) {
  ListFamily f;
  f.sparse = true;
  f.heads_name = heads_name;
  f.next_name = next_name;
  f.heads_shape = {n};
  const std::string hp = key(path, heads_key);
  f.heads_path = hp;
  f.heads_form = verify::HeadsForm::Pairs;
  const Value heads = r.array(r.member(object, path, heads_key, "[index, head] of each non-empty list"), hp);
  f.lists.reserve(heads.size());
  std::size_t i = 0;
  for (const Value item : heads) {
    const auto p = [&](std::size_t j) { return at(at(hp, i), j); };
    const Value h = r.pair(item, [&] { return at(hp, i); });
    UserList list;
    list.cell[axis] = r.cell(h[0], [&] { return p(0); }, n, axis == 0 ? "ix" : axis == 1 ? "iy" : "iz");
    list.slot = list.cell[axis];
    list.head = r.element(h[1], [&] { return p(1); });
    if (list.head != -1) {
      list.entry = static_cast<std::int32_t>(i);
      f.lists.push_back(std::move(list));
    }
    ++i;
  }
  f.next_path = key(path, next_key);
  const Value next = r.array(r.member(object, path, next_key, "[k, next[k]] of each element on the lists"), f.next_path);
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

// The x-lists of `rows` (2D: of the whole grid; 3D: of layer iz), one family per row.
void build_rows(const Reader& r, const Value& object, const std::string& path, const Grid& g, std::int32_t iz,
                bool ascending, verify::UserArrays& out) {
  const auto rows = object.find("rows");
  if (!rows) return;  // rows are optional: the y-lists alone can be checked
  const std::string rp = key(path, "rows");
  r.array(*rows, rp);
  std::size_t i = 0;
  for (const Value row : *rows) {
    const std::string p = at(rp, i++);
    if (!row.is_object()) r.fail(p, "not an object {iy, x_heads, x_next}");
    const std::int32_t iy = r.cell(r.member(row, p, "iy", "the row"), key(p, "iy"), g.n[1], "row");
    ListFamily f = sparse_family(r, row, p, "x_heads", "x_next", "x_heads", "X", 0, g.n[0]);
    f.scope = {-1, iy, iz};
    f.ascending = ascending;
    out.families.push_back(std::move(f));
  }
}

// The lists of one axis over the whole grid, their heads one per cell index (nbs: y-lists per row in
// 2D, z-lists per layer in 3D): "y_heads"/"y_next" or "z_heads"/"z_next".
ListFamily axis_lists(const Reader& r, const Value& doc, const Grid& g, int axis) {
  const bool y = axis == 1;
  ListFamily f;
  f.heads_name = y ? "y_heads" : "z_heads";
  f.next_name = y ? "Y" : "Z";
  f.heads_shape = {g.n[axis]};
  const std::string hp = "$." + f.heads_name;
  f.heads_path = hp;
  f.heads_form = verify::HeadsForm::Dense;
  const Value heads = r.array(r.member(doc, "$", f.heads_name.c_str(), y ? "the heads of the y-lists, one per row" : "the heads of the z-lists, one per layer"),
                              hp, g.n[axis], y ? "ny" : "nz");
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
  f.next_path = y ? "$.y_next" : "$.z_next";
  f.next = r.next_array(r.member(doc, "$", y ? "y_next" : "z_next", y ? "Y, the next array of the y-lists" : "Z, the next array of the z-lists"),
                        f.next_path);
  return f;
}

// ---- nbs 2D: y_heads, y_next, rows ----
void build_nbs_2d(const Reader& r, const Value& doc, const Grid& g, verify::UserArrays& out) {
  out.families.push_back(axis_lists(r, doc, g, 1));
  build_rows(r, doc, "$", g, -1, true, out);  // x-lists: pushed walking a y-list from its highest id down
}

// ---- nbs 3D: z_heads, z_next, layers [{iz, y_heads, y_next, rows}] ----
void build_nbs_3d(const Reader& r, const Value& doc, const Grid& g, verify::UserArrays& out) {
  out.families.push_back(axis_lists(r, doc, g, 2));
  const auto layers = doc.find("layers");
  if (!layers) return;
  r.array(*layers, "$.layers");
  std::size_t i = 0;
  for (const Value layer : *layers) {
    const std::string p = at("$.layers", i++);
    if (!layer.is_object()) r.fail(p, "not an object {iz, y_heads, y_next, rows}");
    const std::int32_t iz = r.cell(r.member(layer, p, "iz", "the layer"), key(p, "iz"), g.n[2], "layer");
    ListFamily y = sparse_family(r, layer, p, "y_heads", "y_next", "y_heads", "Y", 1, g.n[1]);
    y.scope = {-1, -1, iz};
    y.ascending = true;  // pushed walking a z-list from its highest id down
    out.families.push_back(std::move(y));
    build_rows(r, layer, p, g, iz, false, out);  // pushed walking a y-list that rises
  }
}

// ---- tree: leaves [{node, cell, head}], next = E ----
void build_tree(const Reader& r, const Value& doc, const Grid& g, verify::UserArrays& out) {
  ListFamily f;
  f.heads_name = "HEAD";
  f.next_name = "E";
  f.heads_path = "$.leaves";
  f.heads_form = verify::HeadsForm::Leaves;
  const Value leaves = r.array(r.member(doc, "$", "leaves", "every leaf with its node, cell and HEAD"), "$.leaves");
  std::int64_t nodes = 0;
  if (const auto it = doc.find("nodes")) nodes = r.integer(*it, "$.nodes");
  const char* axes[3] = {"ix", "iy", "iz"};
  std::size_t i = 0;
  for (const Value leaf : leaves) {
    const std::string p = at("$.leaves", i++);
    if (!leaf.is_object()) r.fail(p, "not an object {node, cell, head}");
    UserList l;
    l.slot = r.integer(r.member(leaf, p, "node", "its index in HEAD"), key(p, "node")) - r.base();
    if (l.slot < 0) r.fail(key(p, "node"), "not a node index (from " + std::to_string(r.base()) + ")");
    nodes = std::max(nodes, l.slot + 1);
    const Value cell = r.array(r.member(leaf, p, "cell", "[ix, iy(, iz)]"), key(p, "cell"), g.dim, "dim");
    for (int a = 0; a < g.dim; ++a) l.cell[a] = r.cell(cell[static_cast<std::size_t>(a)], at(key(p, "cell"), static_cast<std::size_t>(a)), g.n[a], axes[a]);
    l.head = r.element(r.member(leaf, p, "head", "its HEAD"), key(p, "head"));
    l.entry = static_cast<std::int32_t>(i - 1);
    if (l.head != -1) f.lists.push_back(std::move(l));
  }
  f.heads_shape = {std::max<std::int64_t>(nodes, 1)};
  f.next_path = "$.next";
  f.next = r.next_array(r.member(doc, "$", "next", "E, the next array"), "$.next");
  out.families.push_back(std::move(f));
}

// ---- sort: keys, order, ix, iy (iz) ----
void build_sort(const Reader& r, const Value& doc, const Grid& g, verify::UserArrays& out) {
  verify::SortArrays s;
  const char* names[3] = {"ix", "iy", "iz"};
  const auto cell_value = [&](const Value& v, const auto& p) {
    const std::int64_t i = r.integer(v, p) - r.base();
    return static_cast<std::int32_t>(std::clamp<std::int64_t>(i, -2, std::numeric_limits<std::int32_t>::max()));
  };
  const Value keys = r.array(r.member(doc, "$", "keys", "the cell of each sorted position"), "$.keys", r.n(), "N");
  std::size_t p = 0;
  for (const Value item : keys) {
    const Value k = r.array(item, [&] { return at("$.keys", p); }, g.dim, "dim");
    std::array<std::int32_t, 3> cell{-1, -1, -1};
    for (int a = 0; a < g.dim; ++a) {
      const auto i = static_cast<std::size_t>(a);
      cell[a] = cell_value(k[i], [&] { return at(at("$.keys", p), i); });
    }
    s.keys.push_back(cell);
    ++p;
  }
  const Value order = r.array(r.member(doc, "$", "order", "the element at each sorted position"), "$.order", r.n(), "N");
  p = 0;
  for (const Value v : order) {
    s.order.push_back(r.element(v, [&] { return at("$.order", p); }));
    ++p;
  }
  for (int a = 0; a < g.dim; ++a) {
    const std::string path = std::string("$.") + names[a];
    const Value v = r.array(r.member(doc, "$", names[a], "each element's integerised coordinate"), path, r.n(), "N");
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
  if (name == "screen") {
    build_screen(r, root, g, out);
  } else if (name == "nbs" && g.dim == 3) {
    build_nbs_3d(r, root, g, out);
  } else if (name == "nbs") {
    build_nbs_2d(r, root, g, out);
  } else if (name == "tree") {
    build_tree(r, root, g, out);
  } else if (name == "sort") {
    build_sort(r, root, g, out);
  } else {
    throw Error("--algorithm: verify checks the arrays of screen, nbs, tree and sort ('" + name + "' keeps no book arrays)");
  }
  return out;
}

ArraysJson parse_arrays_json(const std::string& text, const std::string& where) {
  return with_header(arrays_tree::parse_text(text, where), where);
}

ArraysJson read_arrays_json(const std::string& path) {
  return with_header(arrays_tree::read_file(path, kMaxArraysBytes), path);
}

}  // namespace nbscope

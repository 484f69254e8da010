// The arrays of every algorithm (core/array_schema.hpp): one table, read by the dump, the arrays
// reader and verify.
#include "core/array_schema.hpp"

#include <algorithm>
#include <cstring>

#include "core/lists.hpp"

namespace nbscope::array_schema {

namespace {

// The x-lists of one row: [ix, head] pairs and [k, X[k]] pairs.
Family x_lists(const char* heads_trace, bool ascending) {
  return {.form = HeadsForm::Pairs, .heads_key = "x_heads", .next_key = "x_next", .heads_name = "x_heads", .next_name = "X",
          .heads_trace = heads_trace, .next_trace = "X", .axis = 0, .ascending = ascending,
          .heads_meaning = "[index, head] of each non-empty list", .next_meaning = "[k, next[k]] of each element on the lists"};
}

Nest rows(const char* heads_trace, bool ascending) {
  return {.key = "rows", .index_key = "iy", .axis = 1, .word = "row", .family = x_lists(heads_trace, ascending),
          .begin_phase = phase_label::kXListsOfRow, .end_phase = phase_label::kContactsOfRow};
}

std::vector<Layout> make_layouts() {
  std::vector<Layout> out;
  out.push_back({.algorithm = "screen", .dim = 0, .shown_at = phase_label::kContacts,
                 .families = {{.form = HeadsForm::Cells, .heads_key = "heads", .next_key = "next", .heads_name = "C", .next_name = "E",
                               .heads_trace = "C", .next_trace = "E", .axis = -1, .ascending = false,
                               .heads_meaning = "the screen array C[nx][ny] of list heads", .next_meaning = "E, the next array"}},
                 .nests = {}, .sort = false});
  // nbs 2D: the y-lists of the whole grid; each row's x-lists (B[0]), pushed walking a y-list from its highest id down.
  out.push_back({.algorithm = "nbs", .dim = 2, .shown_at = phase_label::kClearYLists,
                 .families = {{.form = HeadsForm::Dense, .heads_key = "y_heads", .next_key = "y_next", .heads_name = "y_heads",
                               .next_name = "Y", .heads_trace = "y_heads", .next_trace = "Y", .axis = 1, .ascending = false,
                               .heads_meaning = "the heads of the y-lists, one per row", .next_meaning = "Y, the next array of the y-lists"}},
                 .nests = {rows("B", true)}, .sort = false});
  // nbs 3D: the z-lists; per layer its y-lists (B[0], pushed walking a z-list from its highest id
  // down) and per row its x-lists (A[0], pushed walking a y-list that rises).
  Nest layers{.key = "layers", .index_key = "iz", .axis = 2, .word = "layer",
              .family = {.form = HeadsForm::Pairs, .heads_key = "y_heads", .next_key = "y_next", .heads_name = "y_heads", .next_name = "Y",
                         .heads_trace = "B", .next_trace = "Y", .axis = 1, .ascending = true,
                         .heads_meaning = "[index, head] of each non-empty list", .next_meaning = "[k, next[k]] of each element on the lists"},
              .begin_phase = phase_label::kYListsOfLayer, .end_phase = phase_label::kClearYListsOfLayer};
  out.push_back({.algorithm = "nbs", .dim = 3, .shown_at = phase_label::kClearZLists,
                 .families = {{.form = HeadsForm::Dense, .heads_key = "z_heads", .next_key = "z_next", .heads_name = "z_heads",
                               .next_name = "Z", .heads_trace = "C", .next_trace = "Z", .axis = 2, .ascending = false,
                               .heads_meaning = "the heads of the z-lists, one per layer", .next_meaning = "Z, the next array of the z-lists"}},
                 .nests = {layers, rows("A", false)}, .sort = false});
  out.push_back({.algorithm = "tree", .dim = 0, .shown_at = phase_label::kContacts,
                 .families = {{.form = HeadsForm::Leaves, .heads_key = "leaves", .next_key = "next", .heads_name = "HEAD", .next_name = "E",
                               .heads_trace = "HEAD", .next_trace = "E", .axis = -1, .ascending = false,
                               .heads_meaning = "every leaf with its node, cell and HEAD", .next_meaning = "E, the next array"}},
                 .nests = {}, .sort = false});
  out.push_back({.algorithm = "sort", .dim = 0, .shown_at = phase_label::kContacts, .families = {}, .nests = {}, .sort = true});
  return out;
}

void add_key(std::vector<std::string_view>& keys, std::string_view key) {
  if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
}

}  // namespace

std::span<const Layout> layouts() {
  static const std::vector<Layout> all = make_layouts();
  return all;
}

const Layout* find_layout(std::string_view algorithm, int dim) {
  for (const Layout& l : layouts())
    if (algorithm == l.algorithm && (l.dim == 0 || l.dim == dim)) return &l;
  return nullptr;
}

std::vector<std::string> algorithms() {
  std::vector<std::string> out;
  for (const Layout& l : layouts())
    if (std::find(out.begin(), out.end(), l.algorithm) == out.end()) out.emplace_back(l.algorithm);
  return out;
}

std::string algorithms_text(const char* last_word) {
  const std::vector<std::string> names = algorithms();
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? std::string(" ") + last_word + " " : ", ";
    out += names[i];
  }
  return out;
}

std::vector<std::string_view> document_keys() {
  std::vector<std::string_view> keys;
  for (const char* k : kHeaderKeys) add_key(keys, k);
  for (const Layout& l : layouts()) {
    for (const Family& f : l.families) {
      add_key(keys, f.heads_key);
      add_key(keys, f.next_key);
      if (f.form == HeadsForm::Leaves)
        for (const char* k : {kNodesKey, kLeafNodeKey, kLeafCellKey, kLeafHeadKey}) add_key(keys, k);
    }
    for (const Nest& n : l.nests)
      for (const char* k : {n.key, n.index_key, n.family.heads_key, n.family.next_key}) add_key(keys, k);
    if (l.sort) {
      add_key(keys, kSort.keys_key);
      add_key(keys, kSort.order_key);
      for (const char* k : kSort.axis_keys) add_key(keys, k);
    }
  }
  return keys;
}

}  // namespace nbscope::array_schema

// nbscope core: the one description of each algorithm's arrays as `nbscope dump` writes them and
// `nbscope verify --arrays` reads them (docs/formats.md "Arrays JSON"): the document's keys,
// which are heads and which next arrays, how heads are laid out, the book's names for messages,
// the traced arrays the dump copies, and the book's order within a list. Plain data: the writer
// (io/dump_json.cpp), the reader (io/arrays_json.cpp, io/arrays_json_tree.cpp) and the check
// (app/verify_run.cpp, core/verify.hpp) all walk it, none keeps its own list of names.
//
//   screen:  heads [ix][iy]([iz]) = C, next = E
//   tree:    nodes, leaves [{node, cell, bounds, head}], next = E
//   sort:    keys (cell of each sorted position), order (element at each sorted position), ix, iy (iz)
//   nbs 2D:  y_heads, y_next, rows [{iy, x_heads [[ix, head]], x_next [[k, X[k]]]}]
//   nbs 3D:  z_heads, z_next, layers [{iz, y_heads [[iy, head]], y_next [[k, Y[k]]], rows [...]}]
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace nbscope::array_schema {

// How a family's heads are laid out in the document.
enum class HeadsForm : std::uint8_t {
  Cells,   // one head per cell, nested by axis: "$.heads[4][6]"
  Dense,   // one head per cell index on one axis: "$.y_heads[3]"
  Pairs,   // [slot, head] pairs of the non-empty lists only, the head at [entry][1]: "$.rows[2].x_heads[0][1]"
  Leaves,  // one object per tree leaf, {node, cell, head}: "$.leaves[5].head"
};

// One family of lists: heads and the next array they share.
struct Family {
  HeadsForm form = HeadsForm::Dense;
  const char* heads_key = "";      // the document's key: "heads", "y_heads", "x_heads", "leaves"
  const char* next_key = "";       // "next", "y_next", "x_next", "z_next"
  const char* heads_name = "";     // the book's name, in messages: "C", "HEAD", "y_heads", "x_heads", "z_heads"
  const char* next_name = "";      // "E", "Y", "X", "Z"
  const char* heads_trace = "";    // the traced array (core/trace.hpp) the dump copies the heads from
  const char* next_trace = "";     // ... and the next array from
  int axis = -1;                   // Dense, Pairs: the cell axis a head's slot indexes (0 x, 1 y, 2 z)
  bool ascending = false;          // the book's order in a list: ids rise from the head (else fall)
  const char* heads_meaning = "";  // what the heads are, for "no \"KEY\" key (MEANING)"
  const char* next_meaning = "";
};

// A level of objects that each hold one list family of one cell index: nbs's rows, 3D's layers.
struct Nest {
  const char* key = "";        // "rows", "layers"
  const char* index_key = "";  // "iy", "iz": the object's cell index
  int axis = 1;                // the axis index_key is on
  const char* word = "";       // "row", "layer", in messages
  Family family;               // its lists: Pairs
  // The phases (core/lists.hpp phase_label) of the traced run between which an object's lists are
  // built: they start afresh at begin_phase and are complete at end_phase, whose index is the object's.
  const char* begin_phase = "";
  const char* end_phase = "";
};

// The keys of a tree leaf's object (HeadsForm::Leaves) and the node count beside the leaves.
inline constexpr const char* kNodesKey = "nodes";
inline constexpr const char* kLeafNodeKey = "node";
inline constexpr const char* kLeafCellKey = "cell";
inline constexpr const char* kLeafHeadKey = "head";
// The traced arrays tree_leaves() reads the leaves from (core/tree.hpp).
inline constexpr const char* kTreeChildTrace = "child";

// sort's arrays: no lists, a permutation and each element's integerised cell.
struct SortArraysSchema {
  const char* keys_key = "keys";    // the cell of each sorted position
  const char* order_key = "order";  // the element at each sorted position (also the traced array)
  const char* axis_keys[3] = {"ix", "iy", "iz"};  // each element's cell index (also the traced arrays)
};
inline constexpr SortArraysSchema kSort{};

// The arrays of one algorithm in one dimension.
struct Layout {
  const char* algorithm = "";       // "screen", "nbs", "tree", "sort"
  int dim = 0;                      // 2 or 3; 0: either
  const char* shown_at = "";        // the phase (core/lists.hpp phase_label) whose state the dump shows
  std::vector<Family> families;     // at the document's top, in the dump's key order
  std::vector<Nest> nests;          // outermost first: rows, or layers holding rows
  bool sort = false;                // sort's arrays (kSort) follow
};

// Every layout, in the order algorithms are listed (screen, nbs 2D, nbs 3D, tree, sort).
std::span<const Layout> layouts();
// The layout of `algorithm` in `dim`, or nullptr for one without book arrays (brute, box2d, ...).
const Layout* find_layout(std::string_view algorithm, int dim);
// The algorithms with arrays, each once: "screen", "nbs", "tree", "sort".
std::vector<std::string> algorithms();
// Those names as a sentence: "screen, nbs, tree and sort" (`last_word` "or": "... tree or sort").
std::string algorithms_text(const char* last_word = "and");

// The header keys an arrays file may give, in the dump's order ("base" the reader's alone).
inline constexpr const char* kHeaderKeys[] = {"algorithm", "dim", "base", "elements", "cell_size", "origin", "nx", "ny", "nz"};
// Every key of any layout: the header's, then each family's, nest's, leaf's and sort's, each once.
std::vector<std::string_view> document_keys();

}  // namespace nbscope::array_schema

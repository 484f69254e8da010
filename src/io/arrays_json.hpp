// nbscope io: ARRAYS.json in — a user's heads and next arrays in the schema `nbscope dump` writes
// (core/array_schema.hpp, docs/formats.md "Arrays JSON"), read for `nbscope verify --arrays`.
//
// Read in two steps, because the shape of the heads arrays depends on the grid, and the grid may
// come from the flags, from the file's own keys or from the elements: read_arrays_json() streams the
// document into a compact tree (io/arrays_json_tree.hpp: 8 bytes a value, the limits checked as it
// reads) and checks its header keys; ArraysJson::arrays() then builds the families of lists for a grid
// and N elements, refusing wrong shapes. Every error names the file and the JSON path of the bad
// value: "arrays.json: $.rows[2].x_heads[0]: ...". Keys a dump has but verify does not need (pairs,
// own_bytes, bytes, leaves' bounds) are ignored.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "core/grid.hpp"
#include "core/verify.hpp"
#include "io/arrays_json_tree.hpp"

namespace nbscope {

// Largest ARRAYS.json read (a 1e6-element NBS dump with every row is about 60 MB).
inline constexpr std::size_t kMaxArraysBytes = std::size_t{1} << 30;

class ArraysJson {
 public:
  std::string path;                      // as given
  std::optional<std::string> algorithm;  // "algorithm"
  std::optional<int> dim;                // "dim": 2 or 3
  std::optional<int> base;               // "base": 0 or 1 (absent: 0)
  std::optional<std::int64_t> elements;  // "elements": N
  GridOptions grid;                      // "cell_size", "origin", "nx", "ny", "nz" where given
  bool has_cells = false;                // all of nx, ny (nz in 3D) given

  // The families of lists (or sort's arrays) of `algorithm` for `grid` and `n` elements, indices
  // shifted by `base` to 0-based. Throws Error("<path>: <json path>: what") on a missing key, a
  // wrong type, an array of the wrong length (heads not nx x ny, next not N), another dimension,
  // a cell or row outside the grid, a number that is not an int32.
  [[nodiscard]] verify::UserArrays arrays(const std::string& algorithm, const Grid& grid, std::int64_t n, int base) const;

  // The document as read (io/arrays_json_tree.hpp): reset it once arrays() has built what verify needs.
  std::shared_ptr<const arrays_tree::Tree> doc;
};

// Reads `path` as it streams (never the whole text at once) and checks its header keys' types and values (algorithm one of screen, nbs, tree,
// sort; dim 2 or 3; base 0 or 1; elements >= 0; cell_size > 0; origin `dim` numbers; nx, ny, nz >= 1).
// Throws Error("<path>:<line>: JSON syntax error ...") or Error("<path>: <json path>: what").
ArraysJson read_arrays_json(const std::string& path);
// The same from memory; `where` names it.
ArraysJson parse_arrays_json(const std::string& text, const std::string& where);

}  // namespace nbscope

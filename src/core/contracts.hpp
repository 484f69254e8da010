// nbscope core: the contracts of the book's list algorithms, checked operation by operation along
// one traced detection (docs/diagnosis.md). A general bug breaks a contract somewhere before any pair
// is lost; the first operation where one breaks is the frame's diagnosis, and the pair-level
// findings (core/locate.hpp) are the detail under it.
//
// Index: Contract (the rules) | BrokenContract (the first break) | ContractNames | first_broken_contract.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/frame_trace.hpp"
#include "core/pairs.hpp"

namespace nbscope {

// One rule of docs/diagnosis.md "Contracts". The lists' rules apply to traces that push onto lists,
// the mask's to traces that visit cells, the tests' to every trace that tests pairs.
enum class Contract : std::uint8_t {
  FirstLevelOnce,  // every element goes onto exactly one first-level list (2D: y-list, 3D: z-list)
  ListCell,        // an element goes only onto lists keyed to its own cell
  ListLink,        // a push links k to the list's head as the frame built it (no stale, cut or wrong link)
  ListTwice,       // an element goes onto one build of a list once (twice makes a cycle)
  ClearWrites,     // a clear leaves the head at -1
  RowProcessed,    // every row that holds elements has its cell lists built and its contacts tested
  CellList,        // every element goes onto the list of its own cell (2D: x-list, 3D: x-list of its row)
  MaskInGrid,      // the mask visits cells of the grid only
  MaskNeighbours,  // the mask visits only the cells next to k's own
  MaskHalf,        // a half mask (the book's) visits only its own half: never a neighbour its mirror relates
  MaskRelates,     // for every neighbour offset, the mask visits it or its opposite (every cell pair is related)
  MaskCell,        // k's mask visits each of its mask cells that exists and holds elements, once
  WalkCell,        // a walk of a visited cell's list meets only elements of that cell
  ListComplete,    // a cell's list holds every element of the cell when a mask walks it
  WalkComplete,    // a walk tests every element of the list it walks
  TestSelf,        // no element is tested against itself
  TestAnswer,      // each test answers the exact contact test (under --touching)
  TestOnce,        // each pair is tested once
  TestReported,    // a test that answered "contact" is reported as a pair
  HeadsCleared,    // every head the frame set is -1 again when it ends (the next frame's lists start empty)
  Cycle,           // no list closes on itself (nbscope stops the call where one does: its walk would never end)
  ApiRule,         // the plugin API's rules: pairs in range, never (k, k), never twice; trace calls naming
                   // declared arrays, entries and elements; every cell written (a Misbehaviour)
};
// Its short name in reports: "first-level-once", "list-cell", "list-link", ..., "test-reported".
[[nodiscard]] const char* contract_name(Contract c);
// The rule in one sentence, as docs/diagnosis.md states it.
[[nodiscard]] const char* contract_rule(Contract c);

// The first operation of a trace where a contract breaks.
struct BrokenContract {
  Contract contract = Contract::ListLink;
  std::size_t event = 0;     // index into the trace's events (0-based): the operation to show
  bool after = false;        // the break came after `event` (a misbehaviour: the call that was refused)
  Pair subject{-1, -1};      // the element(s) it names (k, k) or (k, m); -1 when it names none
  std::string text;          // what broke, in one sentence naming the elements, cells and lists
  std::vector<Pair> cost;    // contacts it cost, where known (the first few)
  std::int64_t cost_count = 0;  // all of them (cost holds the first kMaxCostListed)
};
inline constexpr std::size_t kMaxCostListed = 3;

// How a sentence names an element (its row: book number, atom id, or the row) and a cell index.
struct ContractNames {
  std::function<std::string(std::int64_t)> element = [](std::int64_t k) { return std::to_string(k); };
  bool book_numbering = false;  // cells numbered from 1
};

// The first broken contract of `trace` (a recorded detection: its events, arrays, elements, grid and
// pairs, and its misbehaviour), or none when every contract holds. O(events + elements * 3^dim).
[[nodiscard]] std::optional<BrokenContract> first_broken_contract(const FrameTrace& trace, const ContractNames& names = {});

// A misbehaviour as the ApiRule break it is, after the last of `operations` recorded before it.
[[nodiscard]] BrokenContract api_rule_break(const Misbehaviour& m);

}  // namespace nbscope

// nbscope core: each contract's name and its rule in one sentence (contracts.hpp), as docs/diagnosis.md's
// table states them.
#include "core/contracts.hpp"

namespace nbscope {

const char* contract_name(Contract c) {
  switch (c) {
    case Contract::FirstLevelOnce: return "first-level-once";
    case Contract::ListCell: return "list-cell";
    case Contract::ListLink: return "list-link";
    case Contract::ListTwice: return "list-twice";
    case Contract::ClearWrites: return "clear-writes";
    case Contract::RowProcessed: return "row-processed";
    case Contract::CellList: return "cell-list";
    case Contract::MaskInGrid: return "mask-in-grid";
    case Contract::MaskNeighbours: return "mask-neighbours";
    case Contract::MaskHalf: return "mask-half";
    case Contract::MaskRelates: return "mask-relates";
    case Contract::MaskCell: return "mask-cell";
    case Contract::WalkCell: return "walk-cell";
    case Contract::ListComplete: return "list-complete";
    case Contract::WalkComplete: return "walk-complete";
    case Contract::TestSelf: return "test-self";
    case Contract::TestAnswer: return "test-answer";
    case Contract::TestOnce: return "test-once";
    case Contract::TestReported: return "test-reported";
    case Contract::HeadsCleared: return "heads-cleared";
    case Contract::Cycle: return "cycle";
    case Contract::ApiRule: return "api-rule";
  }
  return "?";
}

const char* contract_rule(Contract c) {
  switch (c) {
    case Contract::FirstLevelOnce: return "every element goes onto exactly one first-level list (2D: y-list, 3D: z-list)";
    case Contract::ListCell: return "an element goes only onto lists keyed to its own cell";
    case Contract::ListLink: return "a push links the element to the head its list had in this frame";
    case Contract::ListTwice: return "an element goes onto one build of a list once";
    case Contract::ClearWrites: return "a clear leaves the head at -1";
    case Contract::RowProcessed: return "every row that holds elements gets its cell lists built and its contacts tested";
    case Contract::CellList: return "every element goes onto the list of its own cell";
    case Contract::MaskInGrid: return "the contact mask visits cells of the grid only";
    case Contract::MaskNeighbours: return "the contact mask visits only the cells next to the element's own";
    case Contract::MaskHalf: return "a half mask visits only its own half of the neighbours (the book's: the cells before the element's own)";
    case Contract::MaskRelates: return "for every neighbour offset the mask visits it or its opposite";
    case Contract::MaskCell: return "each element's mask visits every mask cell that exists and holds elements, once";
    case Contract::WalkCell: return "the walk of a visited cell's list meets only elements of that cell";
    case Contract::ListComplete: return "a cell's list holds every element of the cell when a mask walks it";
    case Contract::WalkComplete: return "a walk tests every element of the list it walks";
    case Contract::TestSelf: return "no element is tested against itself";
    case Contract::TestAnswer: return "each test answers the exact contact test";
    case Contract::TestOnce: return "each pair is tested once";
    case Contract::TestReported: return "a test that answered contact is reported as a pair";
    case Contract::HeadsCleared: return "every head the frame set is -1 again when it ends";
    case Contract::Cycle: return "no list closes on itself";
    case Contract::ApiRule:
      return "the plugin API's rules hold: pairs in range, never (k, k), never twice; trace calls name declared arrays, "
             "entries and elements; every cell is written";
  }
  return "?";
}

}  // namespace nbscope

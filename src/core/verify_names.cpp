// `nbscope verify`'s names in the book's terms (core/verify.hpp): problem kinds, slots ("C[4][6]"),
// cells, scopes ("row 3: "), indices as the file wrote them and the JSON paths of list heads.
#include <algorithm>

#include "core/verify.hpp"

namespace nbscope::verify {

const char* problem_kind_name(ProblemKind kind) {
  switch (kind) {
    case ProblemKind::OutOfRange: return "out of range";
    case ProblemKind::Cycle: return "cycle";
    case ProblemKind::TwoLists: return "repeated";
    case ProblemKind::NotListed: return "dropped";
    case ProblemKind::WrongList: return "wrong list";
    case ProblemKind::NotGiven: return "not given";
    case ProblemKind::WrongOrder: return "order";
    case ProblemKind::WrongCell: return "wrong cell";
  }
  return "?";
}

std::string file_index(std::int64_t value, int base) {
  if (value == kZeroInBase1) return "0";
  if (value == -1) return "-1";
  return std::to_string(value + base);
}

std::string list_where(const ListFamily& family, const UserList& l) {
  const auto index = [](std::int64_t i) { return "[" + std::to_string(i) + "]"; };
  switch (family.heads_form) {
    case HeadsForm::Cells: {
      std::string p = family.heads_path;
      for (std::int32_t c : l.cell)
        if (c >= 0) p += index(c);
      return p;
    }
    case HeadsForm::Dense: return family.heads_path + index(l.slot);
    case HeadsForm::Pairs: return family.heads_path + index(l.entry) + "[1]";
    case HeadsForm::Leaves: return family.heads_path + index(l.entry) + ".head";
  }
  return family.heads_path;
}

std::string slot_name(const ListFamily& family, std::int64_t slot, int base) {
  std::string out = family.heads_name;
  std::vector<std::int64_t> index(family.heads_shape.size(), 0);
  for (std::size_t a = index.size(); a-- > 0;) {
    const std::int64_t n = std::max<std::int64_t>(family.heads_shape[a], 1);
    index[a] = slot % n;
    slot /= n;
  }
  if (index.empty()) index.push_back(slot);
  for (std::int64_t i : index) out += "[" + std::to_string(i + base) + "]";
  return out;
}

std::string cell_name(const std::array<std::int32_t, 3>& cell, int dim, int base) {
  std::string out = "(";
  for (int a = 0; a < dim; ++a) out += (a ? "," : "") + std::to_string(cell[a] + base);
  return out + ")";
}

std::string scope_prefix(const ListFamily& family, int base) {
  const auto& s = family.scope;
  if (s[1] >= 0 && s[2] >= 0) return "row " + std::to_string(s[1] + base) + " of layer " + std::to_string(s[2] + base) + ": ";
  if (s[1] >= 0) return "row " + std::to_string(s[1] + base) + ": ";
  if (s[2] >= 0) return "layer " + std::to_string(s[2] + base) + ": ";
  return "";
}

}  // namespace nbscope::verify

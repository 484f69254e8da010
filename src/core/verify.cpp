// Index: ElementCells (each element's cell, with the neighbour across a boundary it lies on
// within rounding) | Checker: problems, one family's walk (heads in range, links in range, cycles,
// repeats, wrong lists, dropped elements, order), sort's arrays | verify_arrays.
#include "core/verify.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <span>

namespace nbscope::verify {

namespace {

// Each element's cell per axis, as [lo, hi]: one cell, or two when the centre lies within rounding
// of the boundary between them (the user's code may round the other way; both are right).
class ElementCells {
 public:
  ElementCells(const Elements& e, const Grid& g) : dim_(e.dim), n_(e.size()) {
    for (int a = 0; a < dim_; ++a) {
      lo_[a].resize(static_cast<std::size_t>(n_));
      hi_[a].resize(static_cast<std::size_t>(n_));
      at_[a].resize(static_cast<std::size_t>(n_));
      const Eigen::ArrayXd& v = e.axis(a);
      for (std::int64_t k = 0; k < n_; ++k) {
        const auto i = static_cast<std::size_t>(k);
        at_[a][i] = g.cell(v[k], a);
        const double c = (v[k] - g.origin[a]) / g.cell_size;
        const double eps = kBoundaryTolerance * std::max(1.0, std::fabs(c));
        lo_[a][i] = std::min(at_[a][i], clamp(std::floor(c - eps), g.n[a]));
        hi_[a][i] = std::max(at_[a][i], clamp(std::floor(c + eps), g.n[a]));
      }
    }
  }
  // True when element k may lie in cell index `c` on axis a (c == -1: the axis is not fixed).
  [[nodiscard]] bool fits(ElementId k, int a, std::int32_t c) const {
    const auto i = static_cast<std::size_t>(k);
    return c < 0 || (lo_[a][i] <= c && c <= hi_[a][i]);
  }
  // True when k may lie in `cell` on every axis it fixes.
  [[nodiscard]] bool fits(ElementId k, const std::array<std::int32_t, 3>& cell) const {
    for (int a = 0; a < dim_; ++a)
      if (!fits(k, a, cell[a])) return false;
    return true;
  }
  // True when k's cell on every axis `scope` fixes is that one without doubt (no boundary within rounding).
  [[nodiscard]] bool surely_in(ElementId k, const std::array<std::int32_t, 3>& scope) const {
    const auto i = static_cast<std::size_t>(k);
    for (int a = 0; a < dim_; ++a)
      if (scope[a] >= 0 && (lo_[a][i] != scope[a] || hi_[a][i] != scope[a])) return false;
    return true;
  }
  // The cell nbscope integerises k into (eq. 3.76).
  [[nodiscard]] std::array<std::int32_t, 3> cell(ElementId k) const {
    std::array<std::int32_t, 3> c{-1, -1, -1};
    for (int a = 0; a < dim_; ++a) c[a] = at_[a][static_cast<std::size_t>(k)];
    return c;
  }

 private:
  static std::int32_t clamp(double c, std::int64_t n) {
    if (!(c >= 0)) return 0;
    if (c >= static_cast<double>(n)) return static_cast<std::int32_t>(n - 1);
    return static_cast<std::int32_t>(c);
  }
  int dim_;
  std::int64_t n_;
  std::vector<std::int32_t> at_[3], lo_[3], hi_[3];
};

class Checker {
 public:
  Checker(const Elements& e, const Grid& g, const UserArrays& user, bool exact)
      : e_(e), g_(g), user_(user), exact_(exact), cells_(e, g), n_(e.size()),
        owner_(static_cast<std::size_t>(n_), -1), next_(static_cast<std::size_t>(n_), kUnset),
        entry_(static_cast<std::size_t>(n_), -1) {}

  ArraysVerdict run() {
    // One walked list per list at most: reserved whole, so that a million of them are not copied at the peak.
    std::size_t lists = 0;
    for (const ListFamily& f : user_.families) lists += f.lists.size();
    out_.lists.reserve(lists);
    for (std::size_t f = 0; f < user_.families.size(); ++f) walk_family(static_cast<int>(f));
    if (user_.sort) check_sort(*user_.sort);
    return std::move(out_);
  }

 private:
  static constexpr std::int32_t kUnset = std::numeric_limits<std::int32_t>::min() + 1;

  // ---- problems ----
  void add(Problem p) {
    ++out_.problem_count;
    if (out_.problems.size() < kMaxKeptProblems) out_.problems.push_back(std::move(p));
  }
  // A problem of the lists' content, found walking `f`: it breaks the contract its kind maps to there.
  void add(Problem p, const ListFamily& f) {
    p.contract = contract_broken_by(p.kind, f);
    add(std::move(p));
  }
  [[nodiscard]] std::string el(ElementId k) const { return std::to_string(k + user_.base); }
  [[nodiscard]] std::string value(std::int64_t v) const { return file_index(v, user_.base); }
  [[nodiscard]] bool in_range(std::int64_t v) const { return v >= 0 && v < n_; }
  [[nodiscard]] std::string range_text() const {
    if (n_ == 0) return "there are no elements";
    return "elements are " + el(0) + ".." + el(static_cast<ElementId>(n_ - 1)) + ", and -1 ends a list";
  }
  // Where element k lies, in the terms of a family whose lists fix `axes` (plus its scope).
  [[nodiscard]] std::string place(ElementId k, const ListFamily& f, const std::array<std::int32_t, 3>& fixed) const {
    const auto c = cells_.cell(k);
    bool x = false, y = false, z = false;
    for (const auto& s : {fixed, f.scope}) {
      x = x || s[0] >= 0;
      y = y || s[1] >= 0;
      z = z || (e_.dim == 3 && s[2] >= 0);
    }
    if (x) return "cell " + cell_name(c, e_.dim, user_.base);
    if (y && z) return "row " + std::to_string(c[1] + user_.base) + " of layer " + std::to_string(c[2] + user_.base);
    if (y) return "row " + std::to_string(c[1] + user_.base);
    if (z) return "layer " + std::to_string(c[2] + user_.base);
    return "cell " + cell_name(c, e_.dim, user_.base);
  }
  [[nodiscard]] std::string next_path(const ListFamily& f, ElementId k) const {
    if (!f.sparse) return f.next_path + "[" + std::to_string(k) + "]";
    return f.next_path + "[" + std::to_string(entry_[static_cast<std::size_t>(k)]) + "][1]";
  }

  // ---- one family ----
  void walk_family(int fi) {
    const ListFamily& f = user_.families[static_cast<std::size_t>(fi)];
    const std::string pre = scope_prefix(f, user_.base);
    load_next(f, fi, pre);
    std::map<std::array<std::int32_t, 3>, int> list_of_cell;
    for (std::size_t li = 0; li < f.lists.size(); ++li) {
      const UserList& l = f.lists[li];
      bool outside = false;
      for (int a = 0; a < e_.dim; ++a) outside = outside || l.cell[a] >= g_.n[a];
      if (outside) {
        add({ProblemKind::OutOfRange, pre + slot_name(f, l.slot, user_.base) + " is the list of cell " +
             cell_name(l.cell, e_.dim, user_.base) + ", outside the grid of " + grid_text(), list_where(f, l), {}, {}, fi, static_cast<int>(li)});
      }
      const auto [it, fresh] = list_of_cell.emplace(l.cell, static_cast<int>(li));
      if (!fresh) {
        const UserList& first = f.lists[static_cast<std::size_t>(it->second)];
        add({ProblemKind::TwoLists, pre + slot_name(f, l.slot, user_.base) + " and " + slot_name(f, first.slot, user_.base) +
             " are both the list of cell " + cell_name(l.cell, e_.dim, user_.base), list_where(f, l), {}, {}, fi, static_cast<int>(li)});
      }
    }
    touched_.clear();
    cut_.assign(f.lists.size(), false);
    for (std::size_t li = 0; li < f.lists.size(); ++li) walk_list(f, fi, static_cast<int>(li), pre);
    report_dropped(f, fi, pre, list_of_cell);
    if (!f.sparse) {
      for (std::int64_t k = 0; k < std::min(n_, static_cast<std::int64_t>(f.next.size())); ++k) {
        const std::int32_t v = f.next[static_cast<std::size_t>(k)];
        if (owner_[static_cast<std::size_t>(k)] == -1 && v != -1 && !in_range(v)) {
          add({ProblemKind::OutOfRange, pre + f.next_name + "[" + el(static_cast<ElementId>(k)) + "] = " + value(v) +
               ", but " + range_text(), next_path(f, static_cast<ElementId>(k)), {static_cast<ElementId>(k)}, {}, fi, -1});
        }
      }
    }
    for (ElementId k : touched_) owner_[static_cast<std::size_t>(k)] = -1;
    unload_next(f);
  }

  // The family's next array into next_ (sparse pairs: their entries, repeats and bad k reported).
  void load_next(const ListFamily& f, int fi, const std::string& pre) {
    if (!f.sparse) return;
    for (std::size_t p = 0; p < f.next_pairs.size(); ++p) {
      const auto [k, v] = f.next_pairs[p];
      const auto where = [&] { return f.next_path + "[" + std::to_string(p) + "][0]"; };
      if (!in_range(k)) {
        add({ProblemKind::OutOfRange, pre + "[" + value(k) + ", " + value(v) + "] gives " + f.next_name + "[" + value(k) +
             "], but " + range_text(), where(), {}, {}, fi, -1});
        continue;
      }
      const auto i = static_cast<std::size_t>(k);
      if (next_[i] != kUnset) {
        add({ProblemKind::TwoLists, pre + f.next_name + "[" + el(k) + "] is given twice (" + f.next_path + "[" +
             std::to_string(entry_[i]) + "] and [" + std::to_string(p) + "])", where(), {k}, {}, fi, -1});
        continue;
      }
      next_[i] = v;
      entry_[i] = static_cast<std::int32_t>(p);
    }
  }
  void unload_next(const ListFamily& f) {
    for (const auto& [k, v] : f.next_pairs)
      if (in_range(k)) next_[static_cast<std::size_t>(k)] = kUnset;
  }
  [[nodiscard]] std::int32_t next_of(const ListFamily& f, ElementId k) const {
    const auto i = static_cast<std::size_t>(k);
    if (f.sparse) return next_[i];
    return i < f.next.size() ? f.next[i] : kUnset;
  }

  // "C[4][6] -> 3 -> 1 -> 3": the chain from the head, long ones shortened in the middle.
  [[nodiscard]] std::string path_text(const ListFamily& f, const UserList& l, const std::vector<ElementId>& chain,
                                      std::int64_t last) const {
    std::string s = slot_name(f, l.slot, user_.base);
    const std::size_t n = chain.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (n > 8 && i == 3) {
        s += " -> ... (" + std::to_string(n - 6) + " more)";
        i = n - 3;
      }
      s += " -> " + el(chain[i]);
    }
    return last == kUnset ? s : s + " -> " + value(last);
  }

  void walk_list(const ListFamily& f, int fi, int li, const std::string& pre) {
    const UserList& l = f.lists[static_cast<std::size_t>(li)];
    WalkedList walked{fi, li, {}, false};
    std::vector<ElementId>& chain = walked.chain;
    const auto head = [&] { return pre + slot_name(f, l.slot, user_.base); };  // named only for a message
    ElementId prev = -1;
    std::int32_t k = l.head;
    bool ordered = true;
    while (k != -1) {
      // The entry that led here, the head or next[prev], named only when a problem needs it.
      const auto from_text = [&] { return prev == -1 ? head() : pre + f.next_name + "[" + el(prev) + "]"; };
      const auto where_text = [&] { return prev == -1 ? list_where(f, l) : next_path(f, prev); };
      if (!in_range(k)) {
        add({ProblemKind::OutOfRange, from_text() + " = " + value(k) + ", but " + range_text(), where_text(), {}, {}, fi, li}, f);
        walked.cut = true;
        break;
      }
      const auto i = static_cast<std::size_t>(k);
      if (owner_[i] == li) {
        add({ProblemKind::Cycle, pre + path_text(f, l, chain, k) + ": a cycle (" + f.next_name + "[" + el(prev) + "] = " +
             el(k) + " leads back)", where_text(), {k}, std::pair{prev, k}, fi, li}, f);
        walked.cut = true;
        break;
      }
      if (owner_[i] != -1) {
        const UserList& other = f.lists[static_cast<std::size_t>(owner_[i])];
        add({ProblemKind::TwoLists, from_text() + " = " + el(k) + ", but element " + el(k) + " is already on " +
             slot_name(f, other.slot, user_.base) + "'s list (an element is on one list only)", where_text(), {k}, std::pair{prev, k}, fi, li}, f);
        walked.cut = true;
        break;
      }
      owner_[i] = li;
      touched_.push_back(k);
      chain.push_back(k);
      if (!cells_.fits(k, l.cell) || !cells_.fits(k, f.scope)) {
        std::string text = from_text() + " = " + el(k) + ", but element " + el(k) + " lies in " + place(k, f, l.cell);
        if (prev == -1) {
          text += ", not in " + place_of_list(f, l);
        } else {
          text += " and element " + el(prev) + " in " + place(prev, f, l.cell);
        }
        add({ProblemKind::WrongList, text, where_text(), {k}, std::pair{prev, k}, fi, li}, f);
      }
      if (prev != -1 && ordered && (f.ascending ? k < prev : k > prev)) {
        ordered = false;
        if (exact_) {
          add({ProblemKind::WrongOrder, head() + " -> ... -> " + el(prev) + " -> " + el(k) + ": " + el(k) + " follows " + el(prev) +
               ", but in the book's order ids " + (f.ascending ? "rise" : "fall") + " along " + order_reason(f),
               where_text(), {k}, std::pair{prev, k}, fi, li}, f);
        } else {
          ++out_.other_order_lists;
        }
      }
      const std::int32_t nk = next_of(f, k);
      if (nk == kUnset) {
        add({ProblemKind::NotGiven, pre + path_text(f, l, chain, kUnset) + ", but " + f.next_name + "[" +
             el(k) + "] is not given in " + f.next_path, f.next_path, {k}, {}, fi, li}, f);
        walked.cut = true;
        break;
      }
      prev = k;
      k = nk;
    }
    cut_[static_cast<std::size_t>(li)] = walked.cut;
    if (!chain.empty() || walked.cut) out_.lists.push_back(std::move(walked));
  }

  [[nodiscard]] std::string place_of_list(const ListFamily& f, const UserList& l) const {
    std::array<std::int32_t, 3> c = l.cell;
    for (int a = 0; a < 3; ++a)
      if (c[a] < 0) c[a] = f.scope[a];
    if (c[0] >= 0) return "cell " + cell_name(c, e_.dim, user_.base);
    if (c[1] >= 0 && e_.dim == 3 && c[2] >= 0)
      return "row " + std::to_string(c[1] + user_.base) + " of layer " + std::to_string(c[2] + user_.base);
    if (c[1] >= 0) return "row " + std::to_string(c[1] + user_.base);
    return "layer " + std::to_string(c[2] + user_.base);
  }

  [[nodiscard]] static std::string order_reason(const ListFamily& f) {
    if (f.ascending) return "this list (it is pushed at the head while a list running from the highest id down is walked)";
    return "a list (each element is pushed at the head in element order)";
  }

  [[nodiscard]] std::string grid_text() const {
    std::string s = std::to_string(g_.n[0]);
    for (int a = 1; a < e_.dim; ++a) s += " x " + std::to_string(g_.n[a]);
    return s + " cells";
  }

  // Every element the family must hold, on no list of it: named with the list of its cell.
  void report_dropped(const ListFamily& f, int fi, const std::string& pre,
                      const std::map<std::array<std::int32_t, 3>, int>& list_of_cell) {
    // The axes the family's lists fix (the same for all of them; none if it has no list).
    std::array<bool, 3> fixes{false, false, false};
    for (const UserList& l : f.lists)
      for (int a = 0; a < 3; ++a) fixes[a] = fixes[a] || l.cell[a] >= 0;
    std::map<int, std::vector<ElementId>> cut_off;  // per cut list: its cell's elements on no list
    for (ElementId k : members(f.scope)) {
      if (owner_[static_cast<std::size_t>(k)] != -1) continue;
      if (!cells_.surely_in(k, f.scope)) continue;
      std::array<std::int32_t, 3> key = cells_.cell(k);
      for (int a = 0; a < 3; ++a)
        if (!fixes[a]) key[a] = -1;
      std::string text = pre + "element " + el(k) + " is on no list, but lies in " + place(k, f, key);
      const auto it = list_of_cell.find(key);
      // Behind a cycle, a repeat or a bad index the rest of a list is unknown: its elements on no
      // list are named once, together, as cut off that list (report_cut_off).
      if (it != list_of_cell.end() && cut_[static_cast<std::size_t>(it->second)]) {
        cut_off[it->second].push_back(k);
        continue;
      }
      if (it == list_of_cell.end()) {
        text += fixes[0] || fixes[1] || fixes[2] ? ", whose list is empty" : "";
      } else {
        const UserList& l = f.lists[static_cast<std::size_t>(it->second)];
        text += ": " + slot_name(f, l.slot, user_.base) + " misses it";
      }
      add({ProblemKind::NotListed, text, f.next_path, {k}, {}, fi, it == list_of_cell.end() ? -1 : it->second}, f);
    }
    for (auto& [li, ids] : cut_off) report_cut_off(f, fi, li, pre, std::move(ids));
  }

  // "C[4][6]: 2 elements after the cut, 0 and 1, are on no list": the elements of a cut list's cell
  // that no list holds, named (the first few) so that the walk's stop does not hide them.
  void report_cut_off(const ListFamily& f, int fi, int li, const std::string& pre, std::vector<ElementId> ids) {
    constexpr std::size_t kNamed = 8;
    const std::size_t n = ids.size();
    std::string names;
    for (std::size_t i = 0; i < std::min(n, kNamed); ++i) {
      const bool last = i + 1 == n;
      names += (i == 0 ? "" : last ? " and " : ", ") + el(ids[i]);
    }
    if (n > kNamed) names += " and " + std::to_string(n - kNamed) + " more";
    const UserList& l = f.lists[static_cast<std::size_t>(li)];
    const std::string count = n == 1 ? "1 element" : std::to_string(n) + " elements";
    add({ProblemKind::NotListed, pre + slot_name(f, l.slot, user_.base) + ": " + count + " after the cut, " + names +
         (n == 1 ? ", is" : ", are") + " on no list", f.next_path, std::move(ids), {}, fi, li}, f);
  }

  // The elements whose cell matches `scope` on every axis it fixes: all, or one bucket of an
  // index by row/layer built once (a family per NBS row must not cost N each).
  std::span<const ElementId> members(const std::array<std::int32_t, 3>& scope) {
    if (all_.empty() && n_ > 0) {
      all_.resize(static_cast<std::size_t>(n_));
      for (ElementId k = 0; k < n_; ++k) all_[static_cast<std::size_t>(k)] = k;
    }
    const int mode = (scope[0] >= 0 ? 1 : 0) | (scope[1] >= 0 ? 2 : 0) | (scope[2] >= 0 ? 4 : 0);
    if (mode == 0) return all_;
    Index& index = index_[mode];
    const auto key_of = [&](const std::array<std::int32_t, 3>& c) {
      std::array<std::int32_t, 3> k{-1, -1, -1};
      for (int a = 0; a < 3; ++a)
        if (mode & (1 << a)) k[a] = c[a];
      return k;
    };
    if (index.ids.empty() && n_ > 0) {
      index.ids = all_;
      index.keys.resize(static_cast<std::size_t>(n_));
      for (ElementId k = 0; k < n_; ++k) index.keys[static_cast<std::size_t>(k)] = key_of(cells_.cell(k));
      std::stable_sort(index.ids.begin(), index.ids.end(), [&](ElementId a, ElementId b) {
        return index.keys[static_cast<std::size_t>(a)] < index.keys[static_cast<std::size_t>(b)];
      });
      std::vector<std::array<std::int32_t, 3>> sorted(index.ids.size());
      for (std::size_t i = 0; i < sorted.size(); ++i) sorted[i] = index.keys[static_cast<std::size_t>(index.ids[i])];
      index.keys = std::move(sorted);
    }
    const auto [lo, hi] = std::equal_range(index.keys.begin(), index.keys.end(), key_of(scope));
    return std::span<const ElementId>(index.ids).subspan(static_cast<std::size_t>(lo - index.keys.begin()),
                                                          static_cast<std::size_t>(hi - lo));
  }

  // ---- sort (its keys as core/array_schema.hpp names them) ----
  static constexpr const char* kKeys = array_schema::kSort.keys_key;
  static constexpr const char* kOrder = array_schema::kSort.order_key;
  // "$.order[7]": the JSON path of entry p of a sort array.
  static std::string sort_path(const char* key, std::size_t p) { return "$." + std::string(key) + "[" + std::to_string(p) + "]"; }
  void check_sort(const SortArrays& s) {
    const int dim = e_.dim;
    const auto& names = array_schema::kSort.axis_keys;
    for (int a = 0; a < dim; ++a) {
      for (std::size_t k = 0; k < std::min(s.cell_of[a].size(), static_cast<std::size_t>(n_)); ++k) {
        const auto id = static_cast<ElementId>(k);
        if (!cells_.fits(id, a, s.cell_of[a][k]) || s.cell_of[a][k] < 0)
          add({ProblemKind::WrongCell, std::string(names[a]) + "[" + el(id) + "] = " + value(s.cell_of[a][k]) + ", but element " +
               el(id) + " lies in cell " + cell_name(cells_.cell(id), dim, user_.base), sort_path(names[a], k), {id}, {}, -1, -1});
      }
    }
    std::vector<std::int32_t> position(static_cast<std::size_t>(n_), -1);
    // The reader gives keys and order N entries each; shorter keys leave the rest of order unchecked.
    for (std::size_t p = 0; p < std::min(s.order.size(), s.keys.size()); ++p) {
      const std::int32_t k = s.order[p];
      const std::string where = sort_path(kOrder, p);
      const std::string at = std::string(kOrder) + "[" + std::to_string(p + static_cast<std::size_t>(user_.base)) + "]";
      if (!in_range(k)) {
        add({ProblemKind::OutOfRange, at + " = " + value(k) + ", but elements are " + el(0) + ".." + el(static_cast<ElementId>(n_ - 1)),
             where, {}, {}, -1, -1});
        continue;
      }
      auto& seen = position[static_cast<std::size_t>(k)];
      if (seen != -1) {
        add({ProblemKind::TwoLists, at + " = " + el(k) + ", but element " + el(k) + " is already at " + kOrder + "[" +
             std::to_string(seen + user_.base) + "]", where, {k}, {}, -1, -1});
        continue;
      }
      seen = static_cast<std::int32_t>(p);
      const auto& key = s.keys[p];
      if (!cells_.fits(k, key))
        add({ProblemKind::WrongCell, std::string(kKeys) + "[" + std::to_string(p + static_cast<std::size_t>(user_.base)) + "] = " +
             cell_name(key, dim, user_.base) + ", but " + at + " = element " + el(k) + " lies in cell " +
             cell_name(cells_.cell(k), dim, user_.base), sort_path(kKeys, p), {k}, {}, -1, -1});
      if (p > 0) check_sorted(s, p, dim);
    }
    for (ElementId k = 0; k < n_; ++k)
      if (position[static_cast<std::size_t>(k)] == -1)
        add({ProblemKind::NotListed, "element " + el(k) + " is not in order (it lies in cell " +
             cell_name(cells_.cell(k), dim, user_.base) + ")", "$." + std::string(kOrder), {k}, {}, -1, -1});
  }

  void check_sorted(const SortArrays& s, std::size_t p, int dim) {
    const auto& a = s.keys[p - 1];
    const auto& b = s.keys[p];
    const auto pa = std::lexicographical_compare(b.begin(), b.begin() + dim, a.begin(), a.begin() + dim);
    const std::string at = std::to_string(p + static_cast<std::size_t>(user_.base));
    const std::string before = std::to_string(p - 1 + static_cast<std::size_t>(user_.base));
    if (pa) {
      add({ProblemKind::WrongCell, kKeys + ("[" + at) + "] = " + cell_name(b, dim, user_.base) + " after " + kKeys + "[" + before + "] = " +
           cell_name(a, dim, user_.base) + ": not sorted (ix first)", sort_path(kKeys, p), {}, {}, -1, -1});
    } else if (std::equal(a.begin(), a.begin() + dim, b.begin()) && s.order[p] < s.order[p - 1] && in_range(s.order[p])) {
      if (exact_) {
        add({ProblemKind::WrongOrder, kOrder + ("[" + at) + "] = " + el(s.order[p]) + " after " + kOrder + "[" + before + "] = " +
             el(s.order[p - 1]) + " in cell " + cell_name(b, dim, user_.base) + ": the book's ties go by element id",
             sort_path(kOrder, p), {s.order[p]}, {}, -1, -1});
      } else {
        ++out_.other_order_lists;
      }
    }
  }

  const Elements& e_;
  const Grid& g_;
  const UserArrays& user_;
  bool exact_;
  ElementCells cells_;
  std::int64_t n_;
  std::vector<std::int32_t> owner_;  // list of the family being walked that holds each element, -1 none
  std::vector<std::int32_t> next_;   // a sparse family's next entries, kUnset elsewhere
  std::vector<std::int32_t> entry_;  // where in next_pairs each was given
  std::vector<ElementId> touched_;   // elements whose owner_ to reset
  struct Index {
    std::vector<ElementId> ids;                       // element ids by key
    std::vector<std::array<std::int32_t, 3>> keys;    // their keys, sorted
  };
  std::vector<ElementId> all_;
  Index index_[8];                   // by the axes a scope fixes (bit a: axis a)
  std::vector<bool> cut_;            // per list of the family: its walk stopped at a problem
  ArraysVerdict out_;
};

}  // namespace

ArraysVerdict verify_arrays(const Elements& elements, const Grid& grid, const UserArrays& user, bool exact) {
  return Checker(elements, grid, user, exact).run();
}

}  // namespace nbscope::verify

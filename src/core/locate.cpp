#include "core/locate.hpp"

#include <cstdlib>
#include <tuple>

#include "core/cells.hpp"

namespace nbscope {

namespace {

using Cell = std::array<std::int32_t, 3>;

// The offset from cell index a to b along one axis: folded into (-n/2, n/2] on a periodic axis of n cells.
std::int32_t cell_offset(std::int32_t a, std::int32_t b, std::int64_t n) {
  std::int64_t d = std::int64_t{b} - a;
  if (n > 0 && 2 * d > n) d -= n;
  if (n > 0 && 2 * d <= -n) d += n;
  return static_cast<std::int32_t>(d);
}

// True when cell `b` is in the half contact mask of cell `a` (not `a` itself), wrapped on the
// periodic axes (`wrap`: their cell counts).
bool in_mask_of(const Cell& a, const Cell& b, int dim, const std::array<std::int64_t, 3>& wrap) {
  const std::int32_t dx = cell_offset(a[0], b[0], wrap[0]), dy = cell_offset(a[1], b[1], wrap[1]);
  const std::int32_t dz = dim == 3 ? cell_offset(a[2], b[2], wrap[2]) : 0;
  if (std::abs(dx) > 1 || std::abs(dy) > 1 || std::abs(dz) > 1) return false;
  if (dx == 0 && dy == 0 && dz == 0) return false;
  return in_half_mask(dx, dy, dz);
}

bool same_cell(const TraceEvent& e, const Cell& c, int dim) {
  return e.cell[0] == c[0] && e.cell[1] == c[1] && (dim != 3 || e.cell[2] == c[2]);
}

// The first push of element k onto a list keyed to a cell other than `own` (an axis the list is not
// keyed on, -1, is not compared).
std::optional<std::size_t> first_wrong_push(std::span<const TraceEvent> events, std::int32_t k, const Cell& own, int dim) {
  for (std::size_t n = 0; n < events.size(); ++n) {
    const TraceEvent& e = events[n];
    if (e.op != TraceOp::Push || e.element != k) continue;
    for (int a = 0; a < dim; ++a) {
      const auto axis = static_cast<std::size_t>(a);
      if (e.cell[axis] >= 0 && e.cell[axis] != own[axis]) return n;
    }
  }
  return std::nullopt;
}

}  // namespace

PairLocation locate_pair(std::span<const TraceEvent> events, std::int32_t i, std::int32_t j, const PairCells& cells,
                         int dim) {
  PairLocation out;
  // 1. A test of the pair itself, in either order.
  std::optional<std::size_t> first_about_i, first_about_j;
  for (std::size_t n = 0; n < events.size(); ++n) {
    const TraceEvent& e = events[n];
    if (e.op == TraceOp::TestPair && ((e.element == i && e.other == j) || (e.element == j && e.other == i))) {
      out.finding = PairFinding::Tested;
      out.event = n;
      out.contact = e.contact;
      out.scanner = e.element;
      out.other = e.other;
      out.cell = e.other == j ? cells.j : cells.i;
      return out;
    }
    if (e.op == TraceOp::Push || e.op == TraceOp::Set) {
      if (e.element == i && !first_about_i) first_about_i = n;
      if (e.element == j && !first_about_j) first_about_j = n;
    }
  }

  // 2. An element on the list of a cell that is not its own: every later miss follows from that push.
  for (const auto& [k, other, own] : {std::tuple{i, j, cells.i}, std::tuple{j, i, cells.j}}) {
    if (const std::optional<std::size_t> wrong = first_wrong_push(events, k, own, dim)) {
      out.finding = PairFinding::WrongList;
      out.event = wrong;
      out.scanner = k;
      out.other = other;
      const TraceEvent& e = events[*wrong];
      out.cell = {e.cell[0], e.cell[1], dim == 3 ? e.cell[2] : -1};
      return out;
    }
  }
  if (i == j) return out;  // NotInTrace: no push of the element at all, or none onto a wrong list

  // 3. Which element's mask reaches the other's cell (in the same cell either one tests the other).
  const bool same = cells.i[0] == cells.j[0] && cells.i[1] == cells.j[1] && (dim != 3 || cells.i[2] == cells.j[2]);
  if (same || in_mask_of(cells.i, cells.j, dim, cells.wrap)) {
    out.scanner = i;
    out.other = j;
    out.cell = cells.j;
  } else if (in_mask_of(cells.j, cells.i, dim, cells.wrap)) {
    out.scanner = j;
    out.other = i;
    out.cell = cells.i;
  } else {
    out.finding = first_about_i || first_about_j ? PairFinding::NotNeighbours : PairFinding::NotInTrace;
    out.event = first_about_i ? first_about_i : first_about_j;
    out.scanner = i;
    out.other = j;
    out.cell = cells.j;
    return out;
  }

  // 4. A visit of that cell under the scanner's mask (in the same cell: under either one's).
  std::optional<std::size_t> last_visit;
  for (std::size_t n = 0; n < events.size(); ++n) {
    const TraceEvent& e = events[n];
    if (e.op != TraceOp::VisitCell) continue;
    const bool by_scanner = e.element == out.scanner || (same && e.element == out.other);
    if (!by_scanner) continue;
    if (same_cell(e, out.cell, dim)) {
      out.finding = PairFinding::CellVisited;
      out.event = n;
      if (e.element != out.scanner) std::swap(out.scanner, out.other);
      return out;
    }
    if (e.element == out.scanner) last_visit = n;
  }

  // 5. Never visited: show where the scanner's mask was walked, or where it was put in its list.
  const std::optional<std::size_t> pushed = out.scanner == i ? first_about_i : first_about_j;
  if (!last_visit && !pushed) {
    out.finding = PairFinding::NotInTrace;
    return out;
  }
  out.finding = PairFinding::CellNotVisited;
  out.event = last_visit ? last_visit : pushed;
  return out;
}

PairLocation locate_stray(std::span<const TraceEvent> events, std::int32_t stray, std::int32_t finder, const Cell& stray_cell,
                          int dim) {
  PairLocation out;
  out.scanner = finder;
  out.other = stray;
  // The first test of finder against stray, the visit whose walk made it, and the element before it.
  std::optional<std::size_t> visit, previous, test;
  for (std::size_t n = 0; n < events.size() && !test; ++n) {
    const TraceEvent& e = events[n];
    if (e.op == TraceOp::VisitCell && e.element == finder) {
      visit = n;
      previous.reset();
    } else if (e.op == TraceOp::TestPair && e.element == finder && visit) {
      if (e.other == stray) test = n;
      else previous = n;
    }
  }
  if (!test) return out;  // NotInTrace
  const TraceEvent& walked = events[*visit];
  out.cell = {walked.cell[0], walked.cell[1], dim == 3 ? walked.cell[2] : -1};
  out.finding = PairFinding::Tested;
  out.event = test;
  out.contact = events[*test].contact;
  if (same_cell(walked, stray_cell, dim)) return out;  // the list is stray's own: no stray
  // The last push onto this cell's list before the test of p (whose next led to stray), or of stray
  // itself when it heads the list.
  const std::int32_t p = previous ? events[*previous].other : -1;
  const std::int32_t pushed = p >= 0 ? p : stray;
  for (std::size_t n = *test; n-- > 0;) {
    const TraceEvent& e = events[n];
    if (e.op != TraceOp::Push || e.element != pushed || !same_cell(e, out.cell, dim)) continue;
    if (p >= 0 && e.write_count > 0 && e.writes[0].new_value == stray) {
      out.finding = PairFinding::StaleLink;
      out.event = n;
      out.scanner = p;
    } else if (p < 0) {
      out.finding = PairFinding::WrongList;
      out.event = n;
      out.scanner = stray;
      out.other = finder;
    }
    break;  // a later write (a set) linked it otherwise: the test is what the trace can show
  }
  return out;
}

}  // namespace nbscope

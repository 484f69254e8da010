// nbscope check: a violation's operation, in words (diagnosis.hpp).
#include "check/diagnosis.hpp"

#include <array>
#include <string_view>

namespace nbscope {

Diagnosis diagnose(const Violation& v, std::span<const TraceEvent> events, const Grid& grid, const Elements& e,
                   const std::string& algorithm, std::span<const char* const> pseudocode,
                   const std::function<std::string(std::int64_t)>& id, bool book_numbering) {
  Diagnosis d;
  d.operations = events.size();
  const auto index = [&](std::int32_t c) { return std::to_string(book_numbering && c >= 0 ? c + 1 : c); };
  const auto cell_text = [&](const std::array<std::int32_t, 3>& c) {
    std::string out = "(" + index(c[0]) + "," + index(c[1]);
    if (c[2] >= 0) out += "," + index(c[2]);
    return out + ")";
  };
  if (v.pair.i < 0 || v.pair.j < 0 || v.pair.i >= e.size() || v.pair.j >= e.size()) {
    d.text = "the pair is not among this frame's elements";
    return d;
  }
  PairCells cells;
  for (int a = 0; a < e.dim; ++a) {
    cells.i[static_cast<std::size_t>(a)] = grid.cell(e.axis(a)[v.pair.i], a);
    cells.j[static_cast<std::size_t>(a)] = grid.cell(e.axis(a)[v.pair.j], a);
    if (grid.periodic[a]) cells.wrap[static_cast<std::size_t>(a)] = grid.n[a];
  }
  const bool stray = v.invariant == Invariant::Cells && v.pair.i != v.pair.j;  // (stray, finder): a walked list
  PairLocation at = stray ? locate_stray(events, v.pair.i, v.pair.j, cells.i, e.dim) : locate_pair(events, v.pair.i, v.pair.j, cells, e.dim);
  // A cell the detector wrote wrongly while its lists have k right: the push that keyed k on that axis
  // is where it had the right cell (cell_i is the written one, cell_j the grid's).
  const bool written_wrong = v.invariant == Invariant::Cells && v.pair.i == v.pair.j && at.finding == PairFinding::NotInTrace;
  int axis = -1;
  if (written_wrong) axis = v.cell_i.ix != v.cell_j.ix ? 0 : v.cell_i.iy != v.cell_j.iy ? 1 : 2;
  for (std::size_t k = 0; written_wrong && axis >= 0 && k < events.size(); ++k) {
    if (events[k].op == TraceOp::Push && events[k].element == v.pair.i && events[k].cell[axis] >= 0) {
      at.event = k;
      break;
    }
  }
  d.at = at;
  d.event = at.event;
  if (at.event) {
    const TraceEvent& ev = events[*at.event];
    d.kind = trace_op_name(ev.op);
    if (ev.line < pseudocode.size()) {
      d.line = ev.line;
      d.pseudocode = pseudocode[ev.line];
    }
  }
  const std::string what = v.what;
  const std::string op = at.event ? "operation " + std::to_string(*at.event + 1) + " of " + std::to_string(events.size()) + ": " : "";
  const bool missing = v.invariant == Invariant::TInA || (v.invariant == Invariant::AEqualsR && what.find("missing") != std::string::npos);
  std::string& t = d.text;
  switch (at.finding) {
    case PairFinding::Tested:
      t = op + "k=" + id(at.scanner) + " tested against " + id(at.other) + ": " + (at.contact ? "contact" : "no contact") + ". ";
      if (stray && at.cell == cells.i) t += "That list is " + id(at.other) + "'s own cell's: this trace walks it rightly.";
      else if (stray) t += id(at.other) + " lies in " + cell_text(cells.i) + ", not in " + cell_text(at.cell) + ", whose list k's mask walked here: the list holds an element of another cell.";
      else if (missing && at.contact) t += "The detector found this contact here; it was lost after detection (an output fault), not by the lists.";
      else if (missing) t += "The detector's test answered apart where the reference (or Box2D) says contact: the contact test is wrong.";
      else if (what.find("twice") != std::string::npos) t += "This is the first of the pair's tests; the detector tested and reported it again later (a list that holds it twice, or stale).";
      else if (v.invariant == Invariant::AInF) t += "The detector found this contact here; Box2D's contact list does not have it.";
      else if (v.invariant == Invariant::AabbInCells) t += "The detector's own cells " + cell_text(cells.i) + " and " + cell_text(cells.j) + " are neighbours; the cells the check saw are not.";
      else t += "The detector reported the pair from this test; the reference does not have it.";
      break;
    case PairFinding::CellVisited:
      t = op + "the mask of k=" + id(at.scanner) + " visits cell " + cell_text(at.cell) + ", which holds " + id(at.other) +
          ", but the walk of that cell's list never reaches it: the list no longer holds it (a push or a clear cut it).";
      break;
    case PairFinding::CellNotVisited:
      t = op + "cell " + cell_text(at.cell) + " of " + id(at.other) + " is in the contact mask of k=" + id(at.scanner) +
          " but is never visited: the contact mask leaves it out; this is the last cell k's mask visits, where that visit was due.";
      break;
    case PairFinding::WrongList:
      t = op + "k=" + id(at.scanner) + " is pushed onto the list of cell " + cell_text(at.cell) + ", but its cell under the grid is " +
          cell_text(at.scanner == v.pair.i ? cells.i : cells.j) + ": the detector integerised it wrongly, and every mask that visits its own cell misses it.";
      break;
    case PairFinding::StaleLink:
      t = op + id(at.scanner) + " is pushed onto the list of cell " + cell_text(at.cell) + " while its head still held " + id(at.other) +
          " of cell " + cell_text(cells.i) + ": that head was not cleared after its last use, so the list runs on into a stale chain, which k=" +
          id(v.pair.j) + "'s mask walks.";
      break;
    case PairFinding::NotNeighbours:
      t = op + id(v.pair.i) + " lies in cell " + cell_text(cells.i) + " and " + id(v.pair.j) + " in " + cell_text(cells.j) +
          ": not neighbours, so no contact mask relates them; this operation puts " + id(v.pair.i) + " in its list.";
      break;
    case PairFinding::NotInTrace:
      if (written_wrong && at.event) {
        const char* axis_name = axis == 0 ? "x" : axis == 1 ? "y" : "z";
        t = op + "this push keys " + id(v.pair.i) + " to its cell on " + axis_name + " as the grid does, but the cell it wrote to out->cells on " +
            axis_name + " is another (" + std::to_string(axis == 0 ? v.cell_i.ix : axis == 1 ? v.cell_i.iy : v.cell_i.iz) +
            "): its cells output is not the cell it used.";
      } else {
        // "the frame's": the violation's own frame, named where the text is shown (a frame or a dump's timestep).
        t = "the frame's " + algorithm + " trace records nothing about " + id(v.pair.i) + " and " + id(v.pair.j) + ".";
      }
      break;
  }
  return d;
}

std::string element_label(std::int64_t atom, std::int64_t row) {
  return atom == row ? std::to_string(atom) : std::to_string(atom) + " (row " + std::to_string(row) + ")";
}

Diagnosis diagnose_frame(const Violation& v, const FrameTrace& trace, const std::function<std::string(std::int64_t)>& id,
                         bool book_numbering) {
  const std::vector<TraceEvent>& events = trace.log.events();
  Diagnosis d = diagnose(v, events, trace.grid, trace.elements, trace.algorithm, trace.pseudocode, id, book_numbering);
  ContractNames names;
  names.element = id;
  names.book_numbering = book_numbering;
  d.contract = first_broken_contract(trace, names);
  if (!d.contract) return d;
  const BrokenContract& c = *d.contract;
  d.event.reset();
  d.kind.clear();
  d.line = -1;
  d.pseudocode.clear();
  std::string text;
  if (c.event < events.size()) {
    const TraceEvent& ev = events[c.event];
    d.event = c.event;
    d.kind = trace_op_name(ev.op);
    if (ev.line < trace.pseudocode.size()) {
      d.line = ev.line;
      d.pseudocode = trace.pseudocode[ev.line];
    }
    text = std::string(c.after ? "after " : "") + "operation " + std::to_string(c.event + 1) + " of " + std::to_string(events.size()) + ": ";
  }
  text += "contract " + std::string(contract_name(c.contract)) + " broken: " + c.text + ".";
  if (c.cost_count > 0) {
    text += " It cost " + std::to_string(c.cost_count) + (c.cost_count == 1 ? " contact: " : " contacts: ");
    for (std::size_t k = 0; k < c.cost.size(); ++k) text += (k > 0 ? ", (" : "(") + id(c.cost[k].i) + ", " + id(c.cost[k].j) + ")";
    if (c.cost_count > static_cast<std::int64_t>(c.cost.size())) text += ", ...";
    text += ".";
  }
  // A `contract` violation is the break itself: its pair-level search has nothing to add.
  d.text = v.invariant == Invariant::Contract ? text : text + " Detail: " + d.text;
  return d;
}

}  // namespace nbscope

// `nbscope verify`: someone else's contact detection checked — their pairs against the reference
// (--pairs), or their heads and next arrays against the book (--arrays). Exit 0 right, 1 wrong, 2 bad input.
//
// Index: flags | --pairs (summary, then every wrong pair with both cells and distance - radii) |
// --arrays (the first broken contract and its problem in the book's terms, more, the count) | run_verify.
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>

#include "core/pairs.hpp"
#include "app/commands.hpp"
#include "app/dump_input.hpp"
#include "app/threads_flag.hpp"
#include "check/check.hpp"
#include "app/view_options.hpp"
#include "app/verify_run.hpp"
#include "core/detector.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/csv.hpp"
#include "io/given_pairs.hpp"
#include "io/plural.hpp"
#ifdef NBSCOPE_VERIFY_VIEW
#include "app/verify_view.hpp"
#endif

namespace nbscope {

namespace {

// Problems printed with their text after the first; the rest are counted.
constexpr std::size_t kProblemsShown = 20;

void print_line(const std::string& s) {
  std::fwrite(s.data(), 1, s.size(), stdout);
  std::fputc('\n', stdout);
}

// ---- --pairs ----

struct PairsReport {
  const Elements& e;
  const Grid& grid;
  int base;
  const std::vector<std::int64_t>& ids;  // a dump's atom ids: elements are named by them
  const Units& units;                    // the run's (--units, a data file's, --log's): lengths carry their unit when named
  [[nodiscard]] std::string id(std::int64_t k) const { return std::to_string(ids.empty() ? k + base : element_id(&ids, k)); }
  [[nodiscard]] std::string cell(std::int64_t k) const {
    const auto i = static_cast<ElementId>(k);
    std::array<std::int32_t, 3> c{grid.cell(e.x[i], 0), grid.cell(e.y[i], 1), e.dim == 3 ? grid.cell(e.z[i], 2) : -1};
    return verify::cell_name(c, e.dim, base);
  }
  // "cells (4,6) and (4,5), distance - radii = -0.0123 (overlap)"
  [[nodiscard]] std::string facts(std::int64_t i, std::int64_t j) const {
    const auto a = static_cast<ElementId>(i), b = static_cast<ElementId>(j);
    const double gap = contact_gap(e, a, b);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6g", gap);
    const std::string length = units.name.empty() ? std::string(buf) : units.length_text(gap, "%.6g");
    return "cells " + cell(i) + " and " + cell(j) + ", distance - radii = " + length + (gap <= 0 ? " (in contact)" : " (apart)");
  }
};

// The contacts of a dump local file for the frame `frame` (the same timestep), as given pairs of rows.
std::vector<verify::GivenPair> given_from_contacts(const DumpFrame& frame, const std::string& path, const ContactColumns& columns) {
  const std::vector<DumpContacts> all = read_dump_contacts({path}, columns);
  for (const DumpContacts& c : all) {
    if (c.timestep != frame.timestep) continue;
    const PairList rows = contacts_as_rows(frame, c);
    std::vector<verify::GivenPair> given(rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) given[k] = {rows[k].i, rows[k].j, k < c.lines.size() ? c.lines[k] : 0};
    return given;
  }
  throw Error(path + ": no contacts of timestep " + std::to_string(frame.timestep) + " (the frame of " + frame.where + ")");
}

int verify_pairs(const std::string& input, const std::string& pairs_path, const GridFlags& flags, int base,
                 std::int64_t brute_limit, DumpFlags dump, Touching touching, int threads) {
  const Units units = settle_units_and_log(dump, {input});
  const InputFrame frame = read_input_frame(input, dump);
  const Elements& e = frame.elements;
  std::vector<verify::GivenPair> given;
  if (is_dump_file(pairs_path)) {
    if (!frame.dump) throw Error("--pairs: " + pairs_path + " is a dump local file: its atom ids need --input FILE.dump");
    if (base != 0) throw Error("--base: a dump local file names atoms by their ids");
    given = given_from_contacts(*frame.dump, pairs_path, dump.columns);
  } else {
    if (dump.columns.numbers || dump.columns.names)
      throw Error("--contact-ids: needs --contacts, a dump local file as --pairs (" + pairs_path + " is not one: its pairs are i,j)");
    GivenPairsHeader header;
    given = read_given_pairs_csv(pairs_path, base, &header);
    if (frame.dump) {  // a dump's pairs name atoms by id, as `pairs --input FILE.dump` writes them
      if (base != 0) throw Error("--base: the pairs of a dump name atoms by their ids");
      given_pairs_ids_to_rows(*frame.dump, pairs_path, given);
    } else if (header.atom_ids) {  // read as rows they would be checked as the wrong pairs
      throw Error(pairs_path + ":" + std::to_string(header.line) + ": the header `id1,id2` says atom ids, but " + input +
                  " has none (its elements are rows, `i,j`): give the dump they came from as --input");
    }
  }
  DetectOptions options;
  options.touching = touching;
  options.threads = threads;  // nbs, the reference of a periodic frame above the limit
  options.grid = grid_options_for(flags, e.dim);
  // Above the limit sort; a periodic frame needs a detector that measures by the minimum image.
  const std::string reference = e.size() <= brute_limit ? "brute" : e.box.any() ? "nbs" : "sort";
  PairList r;
  auto detector = make_detector(reference);
  Grid grid;
  try {
    detector->detect(e, options, r);
    grid = make_grid(e, options.grid);
  } catch (const Error& err) {
    throw Error(input + ": " + err.what());
  }
  sort_pairs(r);
  verify::PairsVerdict v = verify::compare_pairs(e.size(), given, r);
  const PairsReport p{e, grid, base, frame.ids, units};
  // A dump's printed digits bound what it can decide: disagreements within them are at the boundary.
  std::vector<BoundaryPair> boundary;
  const double precision = frame.dump ? frame.precision : 0;
  std::erase_if(v.missing, [&](const Pair& m) {
    const auto b = boundary_pair(e, m.i, m.j, precision, true);
    if (b) boundary.push_back(*b);
    return b.has_value();
  });
  std::erase_if(v.extra, [&](const verify::GivenPair& x) {
    const auto b = boundary_pair(e, std::min(x.i, x.j), std::max(x.i, x.j), precision, false);
    if (b) boundary.push_back(*b);
    return b.has_value();
  });

  std::string summary = "nbscope verify: " + pairs_path + ": " + plural(static_cast<long long>(given.size()), "pair") +
                        " given for " + plural(static_cast<long long>(e.size()), "element") + ", the reference (" + reference +
                        ") finds " + std::to_string(r.size()) + ": " + std::to_string(v.right) + " right, " +
                        std::to_string(v.missing.size()) + " missing, " + std::to_string(v.extra.size()) + " extra, " +
                        std::to_string(v.duplicates.size()) + " duplicated, " + std::to_string(v.self.size()) +
                        " with itself, " + std::to_string(v.out_of_range.size()) + " out of range";
  if (!boundary.empty()) summary += ", " + std::to_string(boundary.size()) + " at the boundary (not wrong: the data cannot decide them)";
  if (touching == Touching::strict) summary += " (touching strict: <)";
  if (!units.name.empty()) summary += " (" + units.description() + ")";
  print_line(summary + (v.ok() ? ": right" : ": WRONG"));
  double gap_max = 0;  // the given pairs apart: many of them is a neighbour list given as contacts
  for (const verify::GivenPair& x : v.extra) gap_max = std::max(gap_max, contact_gap(e, static_cast<ElementId>(x.i), static_cast<ElementId>(x.j)));
  if (const std::string hint = apart_pairs_hint(static_cast<std::int64_t>(v.extra.size()), static_cast<std::int64_t>(given.size()), gap_max);
      !hint.empty())
    print_line(hint);
  for (const BoundaryPair& b : boundary)
    print_line(std::string(b.in_r ? "boundary, not given " : "boundary, given ") + p.id(b.pair.i) + "," + p.id(b.pair.j) + ": " +
               boundary_text(b, units.name.empty() ? nullptr : &units));
  for (const Pair& m : v.missing) print_line("missing " + p.id(m.i) + "," + p.id(m.j) + ": " + p.facts(m.i, m.j));
  for (const verify::GivenPair& x : v.extra)
    print_line("extra " + p.id(x.i) + "," + p.id(x.j) + " (line " + std::to_string(x.line) + "): " + p.facts(x.i, x.j));
  for (const auto& [d, first] : v.duplicates)
    print_line("duplicated " + p.id(d.i) + "," + p.id(d.j) + " (line " + std::to_string(d.line) + ", first on line " +
               std::to_string(first) + ")");
  for (const verify::GivenPair& s : v.self)
    print_line("with itself " + p.id(s.i) + "," + p.id(s.j) + " (line " + std::to_string(s.line) + "): i == j is no pair");
  for (const verify::GivenPair& o : v.out_of_range) {
    std::string hint = e.size() == 0 ? "there are no elements"
                                     : "elements are " + p.id(0) + ".." + p.id(e.size() - 1);
    if (base == 0 && (o.i == e.size() || o.j == e.size())) hint += "; numbered from 1? use --base 1";
    print_line("out of range " + p.id(o.i) + "," + p.id(o.j) + " (line " + std::to_string(o.line) + "): " + hint);
  }
  std::fflush(stdout);
  if (!frame.note.empty()) std::fprintf(stderr, "nbscope: %s\n", frame.note.c_str());
  return v.ok() ? 0 : 1;
}

// ---- --arrays ----

int report_arrays(const VerifyArraysInputs& in, const VerifyArraysRun& run) {
  const verify::ArraysVerdict& v = run.verdict;
  const std::string what = "the " + run.user.algorithm + " arrays of " + plural(static_cast<long long>(run.elements.size()), "element");
  if (v.problem_count == 0) {
    std::string s = "nbscope verify: " + in.arrays_path + ": " + what + " are right: every list ends, every element is on one list, " +
                    "the list of its own cell";
    if (in.exact) s += ", every list in the book's order";
    if (v.other_order_lists > 0)
      s += " (" + plural(v.other_order_lists, run.user.sort ? "tie" : "list") +
           " in another order than the book's; --exact holds them to it)";
    print_line(s);
    std::fflush(stdout);
    return 0;
  }
  // The lead: the first problem that breaks a contract, named by it as headless names a frame's
  // diagnosis; the first problem when none does (an order, an entry the file leaves out).
  const std::size_t lead = verify::first_contract_problem(v).value_or(0);
  const verify::Problem& first = v.problems[lead];
  const std::string contract = first.contract ? std::string("contract ") + contract_name(*first.contract) + " broken: " : "";
  print_line("nbscope verify: " + in.arrays_path + ": " + contract + first.where + ": " + first.text);
  // The others in the order found, the lead left out.
  std::size_t listed = 0;
  for (std::size_t i = 0; i < v.problems.size() && listed < kProblemsShown; ++i) {
    if (i == lead) continue;
    print_line("  " + v.problems[i].where + ": " + v.problems[i].text);
    ++listed;
  }
  const auto shown = static_cast<std::int64_t>(listed + 1);
  if (v.problem_count > shown) print_line("  ... and " + std::to_string(v.problem_count - shown) + " more");
  // The count by kind, in the order of ProblemKind.
  std::int64_t by_kind[8] = {};
  for (const verify::Problem& p : v.problems) ++by_kind[static_cast<int>(p.kind)];
  std::string kinds;
  for (int k = 0; k < 8; ++k)
    if (by_kind[k] > 0)
      kinds += (kinds.empty() ? "" : ", ") + std::to_string(by_kind[k]) + " " + verify::problem_kind_name(static_cast<verify::ProblemKind>(k));
  print_line("nbscope verify: " + plural(v.problem_count, "problem") + " in " + what + " (" + kinds +
             (v.problem_count > static_cast<std::int64_t>(v.problems.size()) ? ", of the first " + std::to_string(v.problems.size()) : "") +
             "): WRONG");
  std::fflush(stdout);
  return 1;
}

}  // namespace

int run_verify(Args& args) {
  VerifyArraysInputs in = take_verify_inputs(args);
  const auto pairs = args.value("--pairs");
  const std::int64_t brute_limit = args.integer("--brute-limit").value_or(2000);
  const Touching touching = take_touching(args);
  const int threads = take_threads(args);
  DumpFlags dump = take_dump_flags(args);
  dump.timestep = args.integer("--timestep");
  ViewOptions view;
  parse_view_options(args, true, view);
  args.finish();
  if (in.elements_path.empty()) throw Error("verify: --input ELEMENTS.csv is required");
  if (pairs.has_value() == !in.arrays_path.empty())
    throw Error("verify: give --pairs PAIRS.csv (your contact pairs) or --arrays ARRAYS.json (your heads and next arrays)");
  if (view.screenshot) {
#ifndef NBSCOPE_VERIFY_VIEW
    throw Error("--screenshot: this nbscope was built without the window (NBSCOPE_GUI=OFF)");  // before any work
#endif
    check_output_path(*view.screenshot);  // before any work: an unwritable path fails first
    check_outputs_distinct({{"--input", in.elements_path}, {"--arrays", in.arrays_path}}, {{"--screenshot", *view.screenshot}});
  }
  if (pairs) {
    if (in.algorithm) throw Error("--algorithm: only with --arrays (--pairs are checked against brute force, or sort above --brute-limit)");
    if (in.exact) throw Error("--exact: only with --arrays");
    if (view.screenshot) throw Error("--screenshot: only with --arrays (it draws your lists)");
    return verify_pairs(in.elements_path, *pairs, in.grid_flags, in.base.value_or(0), brute_limit, dump, touching, threads);
  }
  if (dump.columns.numbers || dump.columns.names)
    throw Error("--contact-ids: needs --contacts, a dump local file as --pairs: --arrays reads no contacts");
  const VerifyArraysRun run = run_verify_arrays(in);
  const int status = report_arrays(in, run);
#ifdef NBSCOPE_VERIFY_VIEW
  if (view.screenshot) print_line(write_verify_screenshot(run, view));
#endif
  return status;
}

}  // namespace nbscope

// LAMMPS/LIGGGHTS dumps through the command line (docs/dem.md): replay --dump --contacts, pairs,
// dump and verify --input FILE.dump, --touching, the precision band, periodic boxes, and every bad
// input's one line and exit 2. The dumps are written here; the contacts they list are computed here by
// an O(N^2) loop of the test's own (strict, minimum image), never by nbscope.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "support/run_cli.hpp"

namespace nbscope::testcli {
namespace {

struct Atom {
  long long id;
  int type;
  double x, y, z, r;
};

// A frame of atoms: a jittered lattice so that many pairs overlap a little and many do not; `settled`:
// no jitter, radii within a millionth of touching their neighbours, as in a settled packing, where a
// dump's printed digits cannot tell every contact.
std::vector<Atom> lattice_atoms(int n, unsigned seed, bool three_d, double box, bool settled = false) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(settled ? 0.0 : -0.15, settled ? 0.0 : 0.15), tiny(-1e-6, 1e-6);
  std::vector<Atom> atoms;
  const int side = three_d ? static_cast<int>(std::ceil(std::cbrt(n))) : static_cast<int>(std::ceil(std::sqrt(n)));
  const double step = box / side;
  long long id = 1;
  for (int k = 0; static_cast<int>(atoms.size()) < n; ++k) {
    const int ix = k % side, iy = (k / side) % side, iz = three_d ? k / (side * side) : 0;
    id += 1 + static_cast<long long>(rng() % 3);  // ids with gaps
    const int type = 1 + static_cast<int>(rng() % 2);
    atoms.push_back({id, type, (ix + 0.5 + jitter(rng)) * step, (iy + 0.5 + jitter(rng)) * step,
                     three_d ? (iz + 0.5 + jitter(rng)) * step : 0.0,
                     settled ? step * 0.5 * (1 + tiny(rng)) : step * (type == 1 ? 0.48 : 0.55)});
  }
  std::shuffle(atoms.begin(), atoms.end(), rng);  // any order
  return atoms;
}

// The dump custom text of one frame, numbers printed with `format` ("%.17g" full, "%g" LIGGGHTS's default).
std::string dump_frame(long long timestep, const std::vector<Atom>& atoms, double box, const char* format, bool periodic = false,
                       bool three_d = true) {
  char b[256];
  std::string s = "ITEM: TIMESTEP\n" + std::to_string(timestep) + "\nITEM: NUMBER OF ATOMS\n" + std::to_string(atoms.size()) +
                  "\nITEM: BOX BOUNDS " + (periodic ? "pp pp ff" : "ff ff ff") + "\n";
  for (int a = 0; a < 3; ++a) {
    std::snprintf(b, sizeof b, "0 %.17g\n", box);
    s += b;
  }
  s += three_d ? "ITEM: ATOMS id type x y z radius\n" : "ITEM: ATOMS id type x y radius\n";
  const std::string f = std::string(format);
  for (const Atom& a : atoms) {
    const std::string row = three_d ? "%lld %d " + f + " " + f + " " + f + " " + f + "\n" : "%lld %d " + f + " " + f + " " + f + "\n";
    if (three_d) std::snprintf(b, sizeof b, row.c_str(), a.id, a.type, a.x, a.y, a.z, a.r);
    else std::snprintf(b, sizeof b, row.c_str(), a.id, a.type, a.x, a.y, a.r);
    s += b;
  }
  return s;
}

// The atoms as the file gives them back (printed with `format` and read again).
std::vector<Atom> as_printed(std::vector<Atom> atoms, const char* format) {
  char b[64];
  for (Atom& a : atoms)
    for (double* v : {&a.x, &a.y, &a.z, &a.r}) {
      std::snprintf(b, sizeof b, format, *v);
      *v = std::strtod(b, nullptr);
    }
  return atoms;
}

// Every contact rsq < radsum^2 (strict, as LIGGGHTS), minimum image on x and y when periodic.
std::vector<std::array<long long, 2>> exact_contacts(const std::vector<Atom>& atoms, double box, bool periodic) {
  std::vector<std::array<long long, 2>> out;
  for (std::size_t i = 0; i < atoms.size(); ++i)
    for (std::size_t j = i + 1; j < atoms.size(); ++j) {
      double dx = atoms[i].x - atoms[j].x, dy = atoms[i].y - atoms[j].y;
      const double dz = atoms[i].z - atoms[j].z;
      if (periodic) {
        if (dx > box / 2) dx -= box;
        if (dx < -box / 2) dx += box;
        if (dy > box / 2) dy -= box;
        if (dy < -box / 2) dy += box;
      }
      const double rr = atoms[i].r + atoms[j].r;
      if (dx * dx + dy * dy + dz * dz < rr * rr) out.push_back({atoms[i].id, atoms[j].id});
    }
  return out;
}

// The dump local text of one frame's contacts, as LIGGGHTS's pair/gran/local `pos id` writes them
// (x1 y1 z1 x2 y2 z2 id1 id2 periodic-flag; ids printed as floats).
std::string local_frame(long long timestep, const std::vector<std::array<long long, 2>>& contacts, double box) {
  std::string s = "ITEM: TIMESTEP\n" + std::to_string(timestep) + "\nITEM: NUMBER OF ENTRIES\n" + std::to_string(contacts.size()) +
                  "\nITEM: BOX BOUNDS ff ff ff\n";
  for (int a = 0; a < 3; ++a) s += "0 " + std::to_string(box) + "\n";
  s += "ITEM: ENTRIES c_pgl[1] c_pgl[2] c_pgl[3] c_pgl[4] c_pgl[5] c_pgl[6] c_pgl[7] c_pgl[8] c_pgl[9]\n";
  for (const auto& c : contacts) s += "0 0 0 0 0 0 " + std::to_string(c[0]) + ".0 " + std::to_string(c[1]) + ".0 0\n";
  return s;
}

// Two frames in one dump, their contacts in one dump local file: the files of one test.
struct DumpRun {
  std::string dir, dump, contacts;
  std::vector<std::vector<std::array<long long, 2>>> lists;
};

DumpRun write_run(const std::string& test, const char* format, bool periodic = false, bool three_d = true, bool settled = false) {
  DumpRun run;
  run.dir = scratch_dir(test);
  run.dump = run.dir + "/atoms.dump";
  run.contacts = run.dir + "/contacts.dump";
  const double box = 0.05;
  std::string dump, local;
  for (int f = 0; f < 2; ++f) {
    std::vector<Atom> atoms = lattice_atoms(f == 0 ? 300 : 290, 7 + static_cast<unsigned>(f), three_d, box, settled);  // 10 atoms lost
    dump += dump_frame(1000 * f, atoms, box, format, periodic, three_d);
    run.lists.push_back(exact_contacts(as_printed(atoms, "%.17g"), box, periodic));  // the code's own list: its full-precision state
    local += local_frame(1000 * f, run.lists.back(), box);
  }
  write_text(run.dump, dump);
  write_text(run.contacts, local);
  return run;
}

// Error lines are one line: "nbscope: error: <where>: <what>\n".
void expect_one_error_line(const Result& r, const std::string& fragment) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err.rfind("nbscope: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(fragment), std::string::npos) << "wanted '" << fragment << "' in: " << r.err;
}

// replay --headless of a run's dump and contacts, the recorded pairs checked beside nbs and brute.
Result replay(const DumpRun& run, const std::string& extra = "--touching strict", const std::string& contacts = "") {
  return testcli::run("replay --headless --quiet --dump " + run.dump + " --contacts " + (contacts.empty() ? run.contacts : contacts) +
                      " --algorithm recorded,nbs,brute " + extra);
}

TEST(DumpCli, ReplayedContactsEqualAnExactListUnderStrict) {
  const DumpRun files = write_run("dump_cli_strict", "%.17g");
  ASSERT_GT(files.lists[0].size(), 50u);  // the lattice has contacts
  const Result r = replay(files);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("A==R held in every frame"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2 frames"), std::string::npos) << r.out;
}

TEST(DumpCli, AContactRemovedFromTheListIsAViolationNamingBothAtomsAndTheFrame) {
  DumpRun files = write_run("dump_cli_removed", "%.17g");
  // The list of timestep 1000 without its 5th contact.
  const auto gone = files.lists[1][4];
  std::string local;
  for (int f = 0; f < 2; ++f) {
    auto list = files.lists[static_cast<std::size_t>(f)];
    if (f == 1) list.erase(list.begin() + 4);
    local += local_frame(1000 * f, list, 0.05);
  }
  const std::string cut = files.dir + "/cut.dump";
  write_text(cut, local);
  const Result r = replay(files, "--touching strict", cut);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const std::string atoms = "atoms " + std::to_string(gone[0]) + ", " + std::to_string(gone[1]);
  EXPECT_NE(r.out.find(atoms), std::string::npos) << "wanted '" << atoms << "' in: " << r.out;
  EXPECT_NE(r.out.find("first in timestep 1000"), std::string::npos) << r.out;
  // The missing pair's gap, as verify gives it: in contact, so negative.
  EXPECT_NE(r.out.find("missing from the recorded pairs; distance - radii = -"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("; periodic: none; touching: strict (<)"), std::string::npos) << r.out;
}

TEST(DumpCli, ADefaultFormatDumpPassesWithPairsWithinTheDataPrecision) {
  // %g prints 6 digits: some pairs within ~1e-7 m of touching are decided by digits the file lacks.
  const DumpRun files = write_run("dump_cli_g", "%g", false, true, true);
  const Result r = replay(files);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("at the boundary, within the data's precision"), std::string::npos) << r.out;
  // Without the band (a tolerance of 0) the same disagreements are violations: the band is what passes them.
  const Result strict = replay(files, "--touching strict --tolerance 0");
  EXPECT_EQ(strict.exit_code, 1) << strict.out << strict.err;
}

TEST(DumpCli, ExactTiesAreNamedUnderTheOtherConvention) {
  // Two atoms exactly touching (0.25 + 0.25 = 0.5 apart, all exact in binary): LIGGGHTS (strict) lists no contact.
  const std::string dir = scratch_dir("dump_cli_tie");
  std::vector<Atom> atoms = {{1, 1, 1.0, 1.0, 1.0, 0.25}, {2, 1, 1.5, 1.0, 1.0, 0.25}, {3, 1, 3.0, 3.0, 3.0, 0.25}};
  write_text(dir + "/a.dump", dump_frame(0, atoms, 4.0, "%.17g"));
  write_text(dir + "/c.dump", local_frame(0, {}, 4.0));
  const std::string base = "replay --headless --quiet --dump " + dir + "/a.dump --contacts " + dir + "/c.dump --algorithm recorded";
  const Result inclusive = run(base);
  EXPECT_EQ(inclusive.exit_code, 0) << inclusive.out << inclusive.err;
  EXPECT_NE(inclusive.out.find("1 exact tie"), std::string::npos) << inclusive.out;
  const Result strict = run(base + " --touching strict");
  EXPECT_EQ(strict.exit_code, 0) << strict.out << strict.err;
  EXPECT_EQ(strict.out.find("exact tie"), std::string::npos) << strict.out;
  // pairs: the same frame under each convention.
  const Result pi = run("pairs --input " + dir + "/a.dump");
  EXPECT_NE(pi.out.find("\n1,2\n"), std::string::npos) << pi.out;
  const Result ps = run("pairs --input " + dir + "/a.dump --touching strict");
  EXPECT_EQ(ps.out, "id1,id2\n") << ps.out;
}

TEST(DumpCli, PairsOfADumpFrameAreNamedByAtomIds) {
  const DumpRun files = write_run("dump_cli_pairs", "%.17g");
  const Result r = testcli::run("pairs --input " + files.dump + " --timestep 1000 --touching strict");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::array<long long, 2>> want = files.lists[1];
  for (auto& p : want)
    if (p[0] > p[1]) std::swap(p[0], p[1]);
  std::sort(want.begin(), want.end());
  std::string text = "id1,id2\n";  // atom ids, and the header says so
  for (const auto& p : want) text += std::to_string(p[0]) + "," + std::to_string(p[1]) + "\n";
  EXPECT_EQ(r.out, text);
  // Several frames and no --timestep: refused, naming them.
  expect_one_error_line(testcli::run("pairs --input " + files.dump), "choose one with --timestep");
}

// --timestep seeks (issue 36): only its frame is parsed; the other frames' rows are counted, not read,
// so rows there that are no atoms do not stop it, and the errors still count every frame.
TEST(DumpCli, TimestepSeeksItsFrameWithoutParsingTheOthers) {
  const std::string dir = scratch_dir("dump_cli_seek");
  const double box = 0.05;
  const std::vector<Atom> atoms = lattice_atoms(200, 11, true, box);
  const auto junk = [&](long long timestep, std::size_t rows) {
    const std::string none = "NUMBER OF ATOMS\n0\n";
    std::string s = dump_frame(timestep, {}, box, "%.17g");
    s.replace(s.find(none), none.size(), "NUMBER OF ATOMS\n" + std::to_string(atoms.size()) + "\n");
    for (std::size_t k = 0; k < rows; ++k) s += "not an atom row\n";
    return s;
  };
  const std::string seek = dir + "/seek.dump";
  write_text(seek, junk(0, atoms.size()) + dump_frame(1000, atoms, box, "%.17g") + junk(2000, atoms.size()));
  std::vector<std::array<long long, 2>> want = exact_contacts(as_printed(atoms, "%.17g"), box, false);
  for (auto& p : want)
    if (p[0] > p[1]) std::swap(p[0], p[1]);
  std::sort(want.begin(), want.end());
  std::string text = "id1,id2\n";
  for (const auto& p : want) text += std::to_string(p[0]) + "," + std::to_string(p[1]) + "\n";
  const Result r = run("pairs --input " + seek + " --timestep 1000 --touching strict");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, text);
  expect_one_error_line(run("pairs --input " + seek), "3 frames (timesteps 0..2000): choose one with --timestep S");
  expect_one_error_line(run("dump --input " + seek + " --timestep 1500 --algorithm nbs"), "no frame of timestep 1500 (its timesteps: 0..2000, 3 frames)");
  // A skipped frame cut short is still refused as one.
  write_text(seek, junk(0, atoms.size() - 1) + dump_frame(1000, atoms, box, "%.17g"));
  expect_one_error_line(run("pairs --input " + seek + " --timestep 1000"), "timestep 0 has 199 rows, NUMBER OF ATOMS says 200");
}

TEST(DumpCli, VerifyTakesADumpAndItsDumpLocalContacts) {
  const DumpRun files = write_run("dump_cli_verify", "%.17g");
  const Result r = testcli::run("verify --input " + files.dump + " --timestep 0 --pairs " + files.contacts + " --touching strict");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find(": right"), std::string::npos) << r.out;
}

// A dump's PAIRS.csv names atoms by id, as `pairs --input FILE.dump` writes them (it was read as rows: WRONG).
TEST(DumpCli, VerifyReadsTheIdsOfADumpsPairsFile) {
  const DumpRun files = write_run("dump_cli_verify_ids", "%.17g");
  std::string text = "i,j\n";
  for (const auto& p : files.lists[1]) text += std::to_string(p[0]) + "," + std::to_string(p[1]) + "\n";
  write_text(files.dir + "/own.csv", text);
  const std::string verify = "verify --input " + files.dump + " --timestep 1000 --touching strict --pairs ";
  const Result own = run(verify + files.dir + "/own.csv");
  EXPECT_EQ(own.exit_code, 0) << own.out << own.err;
  EXPECT_NE(own.out.find(std::to_string(files.lists[1].size()) + " right, 0 missing"), std::string::npos) << own.out;
  // nbscope's own `pairs` output of the frame, as docs/dem.md chains them.
  const Result pairs = run("pairs --input " + files.dump + " --timestep 1000 --touching strict --output " + files.dir + "/p.csv");
  ASSERT_EQ(pairs.exit_code, 0) << pairs.err;
  const Result round = run(verify + files.dir + "/p.csv");
  EXPECT_EQ(round.exit_code, 0) << round.out << round.err;
  EXPECT_NE(round.out.find(": right"), std::string::npos) << round.out;
  // An id the frame lacks is bad input, named with its line; --base has no meaning for ids.
  write_text(files.dir + "/absent.csv", "i,j\n" + std::to_string(files.lists[1][0][0]) + ",999999\n");
  expect_one_error_line(run(verify + files.dir + "/absent.csv"), "absent.csv:2: pair (");
  expect_one_error_line(run(verify + files.dir + "/absent.csv"), "atom 999999 is not in the frame of timestep 1000");
  expect_one_error_line(run(verify + files.dir + "/own.csv --base 1"), "--base: the pairs of a dump name atoms by their ids");
}

// `id1,id2` (what pairs writes from a dump) says atom ids: against elements without ids (an
// ELEMENTS.csv) it is refused, naming the header's line, not read as rows.
TEST(DumpCli, AnIdsPairsFileAgainstElementsWithoutIdsIsRefused) {
  const std::string dir = scratch_dir("dump_cli_ids_header");
  write_text(dir + "/e.csv", "x,y,r\n0,0,0.5\n0.9,0,0.5\n5,5,0.5\n");
  write_text(dir + "/ids.csv", "# from pairs --input atoms.dump\nid1,id2\n1,2\n");
  expect_one_error_line(run("verify --input " + dir + "/e.csv --pairs " + dir + "/ids.csv"),
                        "ids.csv:2: the header `id1,id2` says atom ids, but " + dir + "/e.csv has none");
  write_text(dir + "/rows.csv", "i,j\n0,1\n");  // ELEMENTS.csv's rows as before
  const Result rows = run("verify --input " + dir + "/e.csv --pairs " + dir + "/rows.csv");
  EXPECT_EQ(rows.exit_code, 0) << rows.out << rows.err;
}

TEST(DumpCli, PeriodicContactsAcrossTheBoundaryAreFound) {
  const DumpRun files = write_run("dump_cli_periodic", "%.17g", true);
  // Some contact crosses the boundary (the lattice touches its own image): the test's list has one
  // that only the minimum image gives.
  const Result r = replay(files);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("A==R held in every frame"), std::string::npos) << r.out;
}

TEST(DumpCli, TwoDimensionalDumpsReplayInTheirOwnRight) {
  const DumpRun files = write_run("dump_cli_2d", "%.17g", false, false);
  const Result r = replay(files);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("A==R held in every frame"), std::string::npos) << r.out;
}

// ---- bad input: one line, exit 2 ----

TEST(DumpCli, EveryBadDumpIsOneLineAndExitTwo) {
  const std::string dir = scratch_dir("dump_cli_bad");
  const std::string head = "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 1\n";
  const auto refused = [&](const std::string& name, const std::string& text, const std::string& fragment) {
    write_text(dir + "/" + name, text);
    expect_one_error_line(run("pairs --input " + dir + "/" + name), fragment);
  };
  refused("no_radius.dump", head + "ITEM: ATOMS id type x y z\n1 1 0.1 0.1 0.1\n2 1 0.2 0.2 0.2\n", "no radius or diameter column");
  refused("no_id.dump", head + "ITEM: ATOMS type x y z radius\n1 0.1 0.1 0.1 0.1\n1 0.2 0.2 0.2 0.1\n", "no `id` column");
  refused("short.dump", head + "ITEM: ATOMS id x y z radius\n1 0.1 0.1 0.1 0.1\n", "has 1 rows, NUMBER OF ATOMS says 2");
  refused("repeated.dump", head + "ITEM: ATOMS id x y z radius\n7 0.1 0.1 0.1 0.1\n7 0.2 0.2 0.2 0.1\n", "atom id 7 appears twice");
  refused("triclinic.dump",
          "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS xy xz yz ff ff ff\n0 1 0\n0 1 0\n0 1 0\n"
          "ITEM: ATOMS id x y z radius\n1 0.1 0.1 0.1 0.1\n",
          "triclinic");
  refused("order.dump",
          "ITEM: TIMESTEP\n5\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 1\nITEM: ATOMS id x y z radius\n1 0.1 0.1 0.1 0.1\n"
          "ITEM: TIMESTEP\n3\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 1\nITEM: ATOMS id x y z radius\n1 0.1 0.1 0.1 0.1\n",
          "timestep 3 after timestep 5");
  // A glob the shell expanded (unquoted): its second file is a word of its own.
  expect_one_error_line(run("replay --headless --dump " + dir + "/short.dump " + dir + "/order.dump"), "quote it");
  // A glob matching nothing.
  expect_one_error_line(run("replay --headless --dump '" + dir + "/nothing*.dump'"), "no file matches");
}

TEST(DumpCli, EveryBadContactListIsOneLineAndExitTwo) {
  const std::string dir = scratch_dir("dump_cli_bad_local");
  std::vector<Atom> atoms = {{1, 1, 1.0, 1.0, 1.0, 0.3}, {2, 1, 1.5, 1.0, 1.0, 0.3}};
  write_text(dir + "/a.dump", dump_frame(0, atoms, 4.0, "%.17g"));
  const std::string head = "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ENTRIES\n1\nITEM: BOX BOUNDS ff ff ff\n0 4\n0 4\n0 4\nITEM: ENTRIES c_c[1] c_c[2]\n";
  write_text(dir + "/half.dump", head + "1 2.5\n");
  write_text(dir + "/absent.dump", head + "1 99\n");
  const std::string replay = "replay --headless --dump " + dir + "/a.dump --contact-ids 1,2 --contacts ";
  expect_one_error_line(run(replay + dir + "/half.dump"), "'2.5' is not an integer");
  expect_one_error_line(run(replay + dir + "/absent.dump"), "atom 99 is not in the frame of timestep 0");
}

// ---- --periodic and --box of elements from a CSV file (pairs, dump, verify, gui) ----

// Seven 2D elements in a 12 x 12 box; the pairs worked out by hand, by the minimum image:
// 0 (0.5, 6) and 1 (11.5, 6), r 1 each: 1.0 apart across x (< 2); 2 (6, 0.4) and 3 (6, 11.8): 0.6
// apart across y; 5 (11.9, 11.9) and 6 (0.1, 0.1), r 0.5: 0.28 apart across the corner (< 1); 4
// (6, 6) touches none (the nearest centres are 5.5 away). Without the box no pair touches.
const char* kSquareCsv = "x,y,r\n0.5,6,1\n11.5,6,1\n6,0.4,1\n6,11.8,1\n6,6,1\n11.9,11.9,0.5\n0.1,0.1,0.5\n";
const char* kSquarePairs = "i,j\n0,1\n2,3\n5,6\n";

TEST(PeriodicCli, ASquareBoxGivesThePairsAcrossItsEdges) {
  const std::string dir = scratch_dir("periodic_cli_square");
  write_text(dir + "/e.csv", kSquareCsv);
  const std::string flags = " --periodic x,y --box 0:12,0:12";
  for (const char* algorithm : {"nbs", "brute"}) {
    const Result r = run("pairs --input " + dir + "/e.csv --algorithm " + algorithm + flags);
    EXPECT_EQ(r.exit_code, 0) << algorithm << ": " << r.err;
    EXPECT_EQ(r.out, kSquarePairs) << algorithm;
  }
  // Without --periodic the same elements have no pair: the three are found across the edges only.
  EXPECT_EQ(run("pairs --input " + dir + "/e.csv").out, "i,j\n");
  const Result d = run("dump --input " + dir + "/e.csv --algorithm nbs" + flags);
  EXPECT_EQ(d.exit_code, 0) << d.err;
  write_text(dir + "/p.csv", kSquarePairs);
  const Result v = run("verify --input " + dir + "/e.csv --pairs " + dir + "/p.csv" + flags);
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
  EXPECT_NE(v.out.find("3 right, 0 missing, 0 extra"), std::string::npos) << v.out;
#ifdef NBSCOPE_TEST_GUI  // a build without the window refuses a screenshot
  const Result g = run("gui --input " + dir + "/e.csv --frames 1 --size 320x240 --screenshot " + dir + "/g.png" + flags,
                       "env -u DISPLAY -u WAYLAND_DISPLAY");
  EXPECT_EQ(g.exit_code, 0) << g.err;
#endif
}

TEST(PeriodicCli, ACubicBoxGivesThePairsAcrossItsFaces) {
  // A 9 x 9 x 9 box: 0 (0.3, 4, 4) and 1 (8.6, 4, 4), r 1: 0.7 apart across x; 2 (4, 4, 0.2) and
  // 3 (4, 4, 8.5): 0.7 apart across z; 0 and 2 are 5.2 apart.
  const std::string dir = scratch_dir("periodic_cli_cubic");
  write_text(dir + "/e.csv", "x,y,z,r\n0.3,4,4,1\n8.6,4,4,1\n4,4,0.2,1\n4,4,8.5,1\n");
  for (const char* algorithm : {"nbs", "brute"}) {
    const Result r = run("pairs --input " + dir + "/e.csv --algorithm " + std::string(algorithm) + " --periodic x,y,z --box 0:9,0:9,0:9");
    EXPECT_EQ(r.exit_code, 0) << algorithm << ": " << r.err;
    EXPECT_EQ(r.out, "i,j\n0,1\n2,3\n") << algorithm;
  }
  // z not periodic: only the pair across x.
  EXPECT_EQ(run("pairs --input " + dir + "/e.csv --periodic x,y --box 0:9,0:9,0:9").out, "i,j\n0,1\n");
}

TEST(PeriodicCli, EveryBadBoxIsOneLineAndExitTwo) {
  const std::string dir = scratch_dir("periodic_cli_bad");
  write_text(dir + "/e.csv", kSquareCsv);
  write_text(dir + "/e3.csv", "x,y,z,r\n1,1,1,0.5\n");
  const std::string pairs = "pairs --input " + dir + "/e.csv --periodic x,y --box ";
  for (const char* box : {"12:0,0:12", "0:0,0:12", "nan:12,0:12", "0:nan,0:12", "0:inf,0:12", "0:12", "0:12,,0:12", "0:12,0:12,0:12,0:12",
                          "0-12,0:12", "0:12,0:12,"})
    expect_one_error_line(run(pairs + "'" + box + "'"), "--box: '" + std::string(box) + "' is not XLO:XHI,YLO:YHI[,ZLO:ZHI]");
  expect_one_error_line(run("pairs --input " + dir + "/e3.csv --periodic x,y --box 0:9,0:9"), "--box: the elements are 3D: give ZLO:ZHI too");
  expect_one_error_line(run("pairs --input " + dir + "/e.csv --box 0:12,0:12"), "--box: needs --periodic");
  expect_one_error_line(run("pairs --input " + dir + "/e.csv --periodic x,y"), "--periodic: needs --box");
}

// ---- contacts the dump does not match, and --contact-ids with nothing to read ----

TEST(DumpCli, AContactFrameWithNoAtomsFrameIsSkippedWithOneNote) {
  const DumpRun files = write_run("dump_cli_extra_contacts", "%.17g");
  // The contacts of timesteps 0 and 1000, and one more frame (timestep 2000) the dump does not have.
  write_text(files.contacts, read_text(files.contacts) + local_frame(2000, files.lists[1], 0.05));
  const Result r = replay(files);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.err.rfind("nbscope: note: " + files.contacts + ":", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(": timestep 2000 has contacts but no atoms frame; skipped\n"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.out.find("2 frames"), std::string::npos) << r.out;
  // --frames 1 cuts the dump after timestep 0: the contact frames past it go with it, without a note.
  const Result cut = replay(files, "--touching strict --frames 1");
  EXPECT_EQ(cut.exit_code, 0) << cut.out << cut.err;
  EXPECT_EQ(cut.err, "");
  EXPECT_NE(cut.out.find("1 frame"), std::string::npos) << cut.out;
  // Contact frames between the dump's (contacts dumped more often than atoms): one note for all, the
  // count and the first timesteps.
  write_text(files.contacts, local_frame(0, files.lists[0], 0.05) + local_frame(250, {}, 0.05) + local_frame(500, {}, 0.05) +
                                 local_frame(750, {}, 0.05) + local_frame(900, {}, 0.05) + local_frame(1000, files.lists[1], 0.05));
  const Result many = replay(files);
  EXPECT_EQ(many.exit_code, 0) << many.out << many.err;
  EXPECT_EQ(std::count(many.err.begin(), many.err.end(), '\n'), 1) << many.err;
  EXPECT_NE(many.err.find("nbscope: note: " + files.contacts + ":"), std::string::npos) << many.err;
  EXPECT_NE(many.err.find(": 4 timesteps have contacts but no atoms frame (250, 500, 750, ...); skipped"), std::string::npos) << many.err;
  // No contact frame of any atoms frame's timestep: nothing would be checked, so it is refused.
  write_text(files.contacts, local_frame(250, {}, 0.05) + local_frame(750, {}, 0.05));
  expect_one_error_line(replay(files), files.contacts + ":");
  expect_one_error_line(replay(files), "no contact frame has the timestep of an atoms frame (contacts from timestep 250, atoms from 0)");
}

TEST(DumpCli, ContactIdsWithNoContactListToReadAreRefused) {
  const DumpRun files = write_run("dump_cli_ids_alone", "%.17g");
  write_text(files.dir + "/p.csv", "0,1\n");
  expect_one_error_line(run("replay --headless --dump " + files.dump + " --contact-ids 7,8"), "--contact-ids: needs --contacts");
  expect_one_error_line(run("replay --headless " + files.dir + "/r.nbsrec --contact-ids 7,8"), "--contact-ids: needs --contacts");
  expect_one_error_line(run("pairs --input " + files.dump + " --timestep 0 --contact-ids 7,8"), "--contact-ids: needs --contacts");
  expect_one_error_line(run("dump --input " + files.dump + " --timestep 0 --algorithm nbs --contact-ids 7,8"), "--contact-ids: needs --contacts");
  expect_one_error_line(run("verify --input " + files.dump + " --timestep 0 --pairs " + files.dir + "/p.csv --contact-ids 7,8"),
                        "--contact-ids: needs --contacts");
  // With a dump local file to read, the same flag is taken.
  const Result ok = run("verify --input " + files.dump + " --timestep 0 --pairs " + files.contacts + " --touching strict --contact-ids 7,8");
  EXPECT_EQ(ok.exit_code, 0) << ok.out << ok.err;
}

TEST(DumpCli, AlgorithmAllOnThreeDimensionalFramesRunsEveryDetectorThatCan) {
  const DumpRun files = write_run("dump_cli_all_3d", "%.17g");
  const Result r = run("replay --headless --quiet --dump " + files.dump + " --contacts " + files.contacts + " --touching strict --algorithm all");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  // box2d is the one 2D-only detector: left out, said once.
  EXPECT_EQ(r.err, "nbscope: note: --algorithm all: box2d left out (2D only; the frames are 3D)\n");
  for (const char* name : {"nbs", "brute", "tree", "sort", "screen", "recorded"})
    EXPECT_NE(r.out.find(name), std::string::npos) << name << " in: " << r.out;
  // 2D frames: box2d runs beside the others, no note.
  const DumpRun flat = write_run("dump_cli_all_2d", "%.17g", false, false);
  const Result r2 = run("replay --headless --quiet --dump " + flat.dump + " --contacts " + flat.contacts + " --touching strict --algorithm all");
  EXPECT_EQ(r2.exit_code, 0) << r2.out << r2.err;
  EXPECT_EQ(r2.err, "");
  EXPECT_NE(r2.out.find("box2d"), std::string::npos) << r2.out;
}

}  // namespace
}  // namespace nbscope::testcli

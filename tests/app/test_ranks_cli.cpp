// A run's per-rank dumps through the command line (docs/dem.md#mpi): a violation whose two atoms were
// in two ranks' files names both ranks in the replay's line; --color-by rank colours by the files'
// ranks when the dump has no proc column, and says in one line when it has neither. The files are
// written here: two ranks of a 10 x 10 box split at x = 5, and the contacts each rank lists.
#include <gtest/gtest.h>

#include <string>

#include "support/run_cli.hpp"

namespace nbscope::testcli {
namespace {

const char* kBox = "ITEM: BOX BOUNDS ff ff ff\n0 10\n0 10\n-0.5 0.5\n";

std::string atoms(const std::string& rows, int count) {
  return "ITEM: TIMESTEP\n100\nITEM: NUMBER OF ATOMS\n" + std::to_string(count) + "\n" + kBox + "ITEM: ATOMS id type x y radius\n" + rows;
}
std::string contacts(const std::string& rows, int count) {
  return "ITEM: TIMESTEP\n100\nITEM: NUMBER OF ENTRIES\n" + std::to_string(count) + "\n" + kBox + "ITEM: ENTRIES c_c[1] c_c[2]\n" + rows;
}

// Rank 0 (x < 5): atoms 1, 5 in contact and 3 at the cut; rank 1: atom 4 touching 3 across the cut, and 2.
// Contacts: 1-5 listed by rank 0; 3-4 by neither (a ghost cut-off too short loses exactly it).
std::string two_ranks(const std::string& test) {
  const std::string dir = scratch_dir(test);
  write_text(dir + "/atoms.0.100.dump", atoms("1 1 1.0000 1.0000 0.5000\n3 1 4.6000 5.0000 0.5000\n5 1 1.8000 1.0000 0.5000\n", 3));
  write_text(dir + "/atoms.1.100.dump", atoms("2 1 9.0000 9.0000 0.5000\n4 1 5.4000 5.0000 0.5000\n", 2));
  write_text(dir + "/contacts.0.100.dump", contacts("1 5\n", 1));
  write_text(dir + "/contacts.1.100.dump", "");
  return dir;
}

TEST(RanksCli, AViolationAcrossTwoRanksNamesBoth) {
  const std::string dir = two_ranks("ranks_violation");
  const Result r = run("replay --headless --dump '" + dir + "/atoms.*.dump' --contacts '" + dir + "/contacts.*.dump' --touching strict");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("A==R (atoms 3 of rank 0, 4 of rank 1) in contact (in R) but missing"), std::string::npos) << r.out;
  // Two atoms of one rank: no ranks named.
  write_text(dir + "/atoms.1.100.dump", atoms("2 1 9.0000 9.0000 0.5000\n", 1));
  write_text(dir + "/atoms.0.100.dump", atoms("1 1 1.0000 1.0000 0.5000\n3 1 4.6000 5.0000 0.5000\n4 1 5.4000 5.0000 0.5000\n5 1 1.8000 1.0000 0.5000\n", 4));
  write_text(dir + "/contacts.0.100.dump", contacts("1 5\n", 1));
  const Result same = run("replay --headless --dump '" + dir + "/atoms.*.dump' --contacts '" + dir + "/contacts.*.dump' --touching strict");
  EXPECT_EQ(same.exit_code, 1) << same.out << same.err;
  EXPECT_NE(same.out.find("A==R (atoms 3, 4) in contact (in R) but missing"), std::string::npos) << same.out;
}

#ifdef NBSCOPE_TEST_GUI  // a build without the window refuses a screenshot
TEST(RanksCli, ColourByRankTakesTheFilesRanksAndWithoutThemSaysSoInOneLine) {
  const std::string dir = two_ranks("ranks_colour");
  const Result r = run("replay --headless --dump '" + dir + "/atoms.*.dump' --color-by rank --screenshot '" + dir + "/ranks.png'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(read_text(dir + "/ranks.png").empty());
  // One file set and no proc column: neither.
  const Result none = run("replay --headless --dump '" + dir + "/atoms.0.100.dump' --color-by rank --screenshot '" + dir + "/none.png'");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_EQ(none.err, "nbscope: error: --color-by rank: the dump has no column 'proc' (it has: id type x y radius)\n");
}
#endif

}  // namespace
}  // namespace nbscope::testcli

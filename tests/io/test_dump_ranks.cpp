// A run's per-rank dumps (io/dump_ranks.hpp): which part of the names numbers the ranks, each
// timestep's pieces as one frame in id order with each row's rank, a contact two ranks list read
// once, and a rank's bare `dump local` rows read with rank 0's header and named by their own lines.
#include <gtest/gtest.h>

#include "io/dump_ranks.hpp"
#include "support/dump_text.hpp"

namespace nbscope {
namespace {

using namespace testdump;

TEST(DumpRanks, TheNamesRankRunIsTheOneEveryGroupNumbersFromZero) {
  using Paths = std::vector<std::string>;
  const auto split = split_by_rank({"a.0.500.dump", "a.1.500.dump", "a.0.1000.dump", "a.1.1000.dump"});
  ASSERT_EQ(split.size(), 2u);
  EXPECT_EQ(split[0], (Paths{"a.0.500.dump", "a.0.1000.dump"}));
  EXPECT_EQ(split[1], (Paths{"a.1.500.dump", "a.1.1000.dump"}));
  EXPECT_EQ(split_by_rank({"atoms.0.dump", "atoms.1.dump", "atoms.2.dump"}).size(), 3u);  // atoms.%.dump, one file a rank
  // Timesteps alone number no ranks; nor do two runs' names, or a rank missing from one group.
  EXPECT_EQ(split_by_rank({"a.500.dump", "a.1000.dump"}).size(), 1u);
  EXPECT_EQ(split_by_rank({"a.0.500.dump", "a.1.500.dump", "a.0.1000.dump"}).size(), 1u);
  EXPECT_EQ(split_by_rank({"run1/a.0.dump", "run2/b.1.dump"}).size(), 1u);
  EXPECT_EQ(rank_run_of({"a.0.500.dump", "a.1.500.dump"}), 0);
  EXPECT_EQ(with_digit_run("post/c.0.1500.dump", 0, 3), "post/c.3.1500.dump");  // digit runs count from 0, from the path's start
  EXPECT_EQ(digit_run("post/c.2.1500.dump", 1), 1500);
}

DumpFrame piece(std::vector<std::int64_t> ids, double x0) {
  DumpFrame f;
  f.timestep = 500;
  f.where = "rank:1";
  f.elements.dim = 2;
  for (std::size_t k = 0; k < ids.size(); ++k) f.elements.push_back(x0 + static_cast<double>(k), 0, 0, 0.5);
  f.ids = std::move(ids);
  f.types.assign(f.ids.size(), 1);
  return f;
}

TEST(DumpRanks, PiecesBecomeOneFrameInIdOrderWithTheirRanks) {
  const DumpFrame f = merge_rank_frames({piece({2, 7}, 0), piece({1, 5, 9}, 10)});
  EXPECT_EQ(f.ids, (std::vector<std::int64_t>{1, 2, 5, 7, 9}));
  EXPECT_EQ(f.ranks, (std::vector<std::int32_t>{1, 0, 1, 0, 1}));
  EXPECT_DOUBLE_EQ(f.elements.x[0], 10);  // atom 1: rank 1's first row
  EXPECT_DOUBLE_EQ(f.elements.x[3], 1);   // atom 7: rank 0's second row
  // The kept columns (--color-by, --export-vtk) follow their rows.
  DumpFrame a = piece({2, 7}, 0), b = piece({1, 5, 9}, 10);
  const auto columns = [](std::vector<double> vx) {
    auto c = std::make_shared<AtomColumns>();
    c->header = {"id", "type", "x", "y", "z", "radius", "vx"};
    c->names = {"vx"};
    c->values = {std::move(vx)};
    return c;
  };
  a.columns = columns({0.2, 0.7});
  b.columns = columns({0.1, 0.5, 0.9});
  const DumpFrame with = merge_rank_frames({a, b});
  ASSERT_TRUE(with.columns);
  EXPECT_EQ(with.columns->values[0], (std::vector<double>{0.1, 0.2, 0.5, 0.7, 0.9}));
  const std::string e = error_of([] { merge_rank_frames({piece({2, 7}, 0), piece({7}, 10)}); });
  EXPECT_NE(e.find("atom 7 is also in rank 0's frame"), std::string::npos) << e;
}

TEST(DumpRanks, TheMergedFrameKeepsEveryRanksColumnsAndFindsHowTheBoxWasSplit) {
  // Rank 0 holds x < 5, rank 1 x >= 5 of a 10-wide box: LAMMPS's `processors 2 1 1`.
  std::vector<DumpFrame> pieces{piece({2, 7}, 1), piece({1, 5, 9}, 6)};
  for (std::size_t r = 0; r < 2; ++r) {
    auto columns = std::make_shared<AtomColumns>();
    columns->header = {"id", "type", "x", "y", "radius", "proc"};
    columns->names = {"type", "proc"};
    columns->values = {std::vector<double>(pieces[r].ids.size(), 1), std::vector<double>(pieces[r].ids.size(), static_cast<double>(r))};
    pieces[r].columns = columns;
    pieces[r].box.hi[0] = pieces[r].box.hi[1] = 10;
  }
  const DumpFrame f = merge_rank_frames(std::move(pieces));
  ASSERT_NE(f.columns, nullptr);
  EXPECT_EQ(*f.columns->find("proc"), (std::vector<double>{1, 0, 1, 0, 1}));  // by id: 1 2 5 7 9
  ASSERT_NE(f.subdomains, nullptr);
  EXPECT_EQ(f.subdomains->grid, (std::array<int, 3>{2, 1, 1}));
  EXPECT_DOUBLE_EQ(f.subdomains->bounds_of(1).min[0], 5);
  EXPECT_DOUBLE_EQ(f.subdomains->bounds_of(0).max[1], 10);
}

TEST(DumpRanks, AContactTwoRanksListIsOneButARepeatWithinARankStays) {
  DumpContacts zero, one;
  zero.ids = {{1, 2}, {2, 7}, {2, 7}};  // a repeat within rank 0: the check names it
  one.ids = {{7, 2}, {5, 9}};           // (7, 2): rank 0's (2, 7) seen from rank 1 (newton off)
  const DumpContacts c = merge_rank_contacts({zero, one});
  EXPECT_EQ(c.ids, (std::vector<std::array<std::int64_t, 2>>{{1, 2}, {2, 7}, {2, 7}, {5, 9}}));
}

TEST(DumpRanks, BareRowsAreReadWithRankZerosHeaderAndNamedByTheirOwnLines) {
  const std::string dir = temp_dir("ranks-bare");
  const std::string zero = dir + "/c.0.500.dump", one = dir + "/c.1.500.dump";
  write_file(zero, "ITEM: TIMESTEP\n500\nITEM: NUMBER OF ENTRIES\n1\nITEM: BOX BOUNDS pp ff ff\n0 1\n0 1\n0 1\n"
                   "ITEM: ENTRIES c_c[1] c_c[2] \n1 2 \n");
  write_file(one, "5 9 \n7 8 \n");
  EXPECT_FALSE(is_bare_rows(zero));
  EXPECT_TRUE(is_bare_rows(one));
  const DumpFrameAt at{500, std::nullopt, 1, 0, 0, 1, zero + ":1"};
  const DumpContacts c = read_bare_contacts(one, zero, at, ContactColumns{});
  EXPECT_EQ(c.timestep, 500);
  EXPECT_EQ(c.ids, (std::vector<std::array<std::int64_t, 2>>{{5, 9}, {7, 8}}));
  EXPECT_EQ(c.lines, (std::vector<std::int64_t>{1, 2}));
  write_file(one, "5 9 \n7 x \n");
  const std::string e = error_of([&] { read_bare_contacts(one, zero, at, ContactColumns{}); });
  EXPECT_NE(e.find("c.1.500.dump:2:"), std::string::npos) << e;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace nbscope

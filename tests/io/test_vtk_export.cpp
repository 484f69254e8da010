// A dump's other columns kept by name (DumpOptions::keep_columns) and each atom's overlap.
#include <gtest/gtest.h>

#include <string>

#include "core/pairs.hpp"
#include "io/lammps_dump.hpp"
#include "support/dump_text.hpp"

namespace nbscope {
namespace {

using namespace testdump;

DumpOptions keeping() {
  DumpOptions o;
  o.keep_columns = true;
  return o;
}

// Rows out of id order and past 1..N, so both the by-id slots and the sort move the kept columns.
const std::string kRows = "30 1 0.3 0.1 0.2 0.01 -1.5 7 Cu\n5 2 0.5 0.6 0.7 0.02 2.25 3 Cu\n17 1 0.9 0.8 0.4 0.03 0.125 1 Ni\n";

TEST(DumpColumns, KeptByNameInTheRowsIdOrder) {
  const DumpFrame f = parse_dump_frames(frame(100, 3, "id type x y z radius vx proc element", kRows), "d.dump", keeping())[0];
  ASSERT_NE(f.columns, nullptr);
  EXPECT_EQ(f.columns->header, (std::vector<std::string>{"id", "type", "x", "y", "z", "radius", "vx", "proc", "element"}));
  // type first; the text column `element` is dropped; id, positions and radius are the elements'.
  EXPECT_EQ(f.columns->names, (std::vector<std::string>{"type", "vx", "proc"}));
  EXPECT_EQ(*f.columns->find("vx"), (std::vector<double>{2.25, 0.125, -1.5}));
  EXPECT_EQ(*f.columns->find("proc"), (std::vector<double>{3, 1, 7}));
  EXPECT_EQ(*f.columns->find("type"), (std::vector<double>{2, 1, 1}));
  EXPECT_EQ(f.columns->find("element"), nullptr);
  EXPECT_TRUE(f.columns->has("element"));
  const DumpFrame dense = parse_dump_frames(frame(0, 3, "id x y z radius vx", "3 0.3 0 0 0.01 3\n1 0.1 0 0 0.01 1\n2 0.2 0 0 0.01 2\n"),
                                            "d.dump", keeping())[0];
  EXPECT_EQ(*dense.columns->find("vx"), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(dense.columns->find("type"), nullptr);
}

TEST(DumpColumns, NotKeptUnlessAsked) {
  const DumpFrame f = parse_dump_frames(frame(100, 3, "id type x y z radius vx proc element", kRows), "d.dump", {})[0];
  EXPECT_EQ(f.columns, nullptr);
  EXPECT_EQ(f.ids, (std::vector<std::int64_t>{5, 17, 30}));
}

TEST(DumpColumns, TravelToTheRecordedFrame) {
  DumpFrame f = parse_dump_frames(frame(100, 3, "id type x y z radius vx proc element", kRows), "d.dump", keeping())[0];
  const RecordedFrame r = recorded_from_dump(std::move(f), nullptr, std::nullopt);
  ASSERT_NE(r.columns, nullptr);
  EXPECT_EQ(*r.columns->find("vx"), (std::vector<double>{2.25, 0.125, -1.5}));
}

TEST(ElementOverlaps, LargestOverEachElementsPairsByTheMinimumImage) {
  Elements e;
  e.push_back(0.0, 0, 0, 1);
  e.push_back(1.5, 0, 0, 1);  // overlaps 0 by 0.5
  e.push_back(3.25, 0, 0, 1); // overlaps 1 by 0.25
  e.push_back(9.5, 0, 0, 1);  // across x's period of 10: overlaps 0 by 1.5
  e.push_back(5.0, 5, 0, 1);  // no pair
  const PairList pairs = {{0, 1}, {1, 2}, {0, 3}};
  EXPECT_EQ(element_overlaps(e, pairs), (std::vector<double>{0.5, 0.5, 0.25, 0, 0}));
  e.box.periodic[0] = true;
  e.box.hi[0] = 10;
  e.box.hi[1] = 10;
  EXPECT_EQ(element_overlaps(e, pairs), (std::vector<double>{1.5, 0.5, 0.25, 1.5, 0}));
}

}  // namespace
}  // namespace nbscope

// A dump's other columns kept by name (DumpOptions::keep_columns), each atom's overlap, and
// --export-vtk's files (io/vtk_export.hpp): the points, arrays and tagged lines, written whole.
// (tests/dem/check_vtk_export.py reads a real LAMMPS run's export back with VTK itself.)
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/pairs.hpp"
#include "io/lammps_dump.hpp"
#include "io/vtk_export.hpp"
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

TEST(VtkExport, PointsArraysAndLinesTaggedByWhoHoldsThem) {
  const DumpFrame f = parse_dump_frames(frame(100, 3, "id type x y z radius vx proc element", kRows), "d.dump", keeping())[0];
  const PairList r = {{0, 1}, {1, 2}};  // rows: atoms 5-17 and 17-30
  const PairList a = {{0, 2}, {1, 2}};
  VtkFrame v{100, &f.elements, &f.ids, f.columns.get(), &r, &a, true};
  const std::string text = vtk_polydata(v);
  EXPECT_NE(text.find("<Piece NumberOfPoints=\"3\" NumberOfVerts=\"3\" NumberOfLines=\"3\""), std::string::npos) << text;
  EXPECT_NE(text.find("Name=\"id\" format=\"ascii\">\n          5 17 30\n"), std::string::npos) << text;
  EXPECT_NE(text.find("Name=\"vx\" format=\"ascii\">\n          2.25 0.125 -1.5\n"), std::string::npos) << text;
  EXPECT_NE(text.find("type=\"Int32\" Name=\"proc\" format=\"ascii\">\n          3 1 7\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("Name=\"element\""), std::string::npos);
  // Verts (kind 0), then the lines in pair order: (0,1) missing, (0,2) extra, (1,2) in both.
  EXPECT_NE(text.find("Name=\"kind\" format=\"ascii\">\n          0 0 0 2 3 1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("Name=\"connectivity\" format=\"ascii\">\n          0 1 0 2 1 2\n"), std::string::npos) << text;
  EXPECT_NE(text.find("Name=\"offsets\" format=\"ascii\">\n          2 4 6\n"), std::string::npos) << text;
  v.checked = false;  // a frame not checked: A's pairs are its contacts
  EXPECT_NE(vtk_polydata(v).find("Name=\"kind\" format=\"ascii\">\n          0 0 0 1 1\n"), std::string::npos);
}

TEST(VtkExport, FramesAndTheCollectionInTheDirectory) {
  const std::string dir = temp_dir("vtk") + "/out";  // made by the series
  const DumpFrame f = parse_dump_frames(frame(100, 3, "id type x y z radius vx proc element", kRows), "d.dump", keeping())[0];
  const PairList none;
  VtkSeries series(dir);
  for (std::int64_t step : {500, 100}) series.add(VtkFrame{step, &f.elements, &f.ids, f.columns.get(), &none, &none, true});
  EXPECT_TRUE(std::filesystem::exists(dir + "/frame_500.vtp"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/series.pvd"));  // written by finish()
  series.finish();
  std::ifstream in(dir + "/series.pvd");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("<DataSet timestep=\"100\" group=\"\" part=\"0\" file=\"frame_100.vtp\"/>\n"
                            "    <DataSet timestep=\"500\" group=\"\" part=\"0\" file=\"frame_500.vtp\"/>"),
            std::string::npos)
      << text.str();
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();  // no temporary left
  EXPECT_EQ(error_of([&] { VtkSeries bad(dir + "/frame_100.vtp"); }), "--export-vtk: " + dir + "/frame_100.vtp: exists and is not a directory");
}

}  // namespace
}  // namespace nbscope

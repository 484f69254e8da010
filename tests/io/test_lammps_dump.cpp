// The LAMMPS/LIGGGHTS dump readers (io/lammps_dump.hpp): atoms by id in any order, every header
// item, scaled/unwrapped/periodic positions, radii from columns or options, gzip, globs, the
// precision band, `dump local` contact lists, and every refusal named by file and line.
#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>

#include "core/error.hpp"
#include "io/lammps_dump.hpp"
#include "support/dump_text.hpp"

namespace nbscope {
namespace {

namespace fs = std::filesystem;

using namespace testdump;

std::string custom_error(const std::string& text, const DumpOptions& options = {}) {
  return error_of([&] { parse_dump_frames(text, "d.dump", options); });
}

TEST(LammpsDump, AtomsInAnyOrderWithGapsBecomeRowsInIdOrder) {
  const auto frames = parse_dump_frames(
      frame(100, 3, kColumns, "30 1 0.3 0.1 0.2 0.01\n5 2 0.5 0.6 0.7 0.02\n17 1 0.9 0.8 0.4 0.03\n"), "d.dump", {});
  ASSERT_EQ(frames.size(), 1u);
  const DumpFrame& f = frames[0];
  EXPECT_EQ(f.timestep, 100);
  EXPECT_EQ(f.where, "d.dump:1");
  EXPECT_EQ(f.ids, (std::vector<std::int64_t>{5, 17, 30}));
  EXPECT_EQ(f.types, (std::vector<std::int32_t>{2, 1, 1}));
  ASSERT_EQ(f.elements.dim, 3);
  EXPECT_DOUBLE_EQ(f.elements.x[0], 0.5);
  EXPECT_DOUBLE_EQ(f.elements.z[1], 0.4);
  EXPECT_DOUBLE_EQ(f.elements.r[2], 0.01);
  EXPECT_FALSE(f.time.has_value());
  EXPECT_TRUE(f.elements.box.periodic[0] && f.elements.box.periodic[2]);
}

TEST(LammpsDump, IdsOneToNPlacedAsReadAndAnIdPastNMidway) {
  const auto dense = parse_dump_frames(frame(0, 4, kColumns, "3 1 0.3 0 0 0.01\n1 2 0.1 0 0 0.01\n4 1 0.4 0 0 0.01\n2 1 0.2 0 0 0.01\n"),
                                       "d.dump", {})[0];
  EXPECT_EQ(dense.ids, (std::vector<std::int64_t>{1, 2, 3, 4}));
  EXPECT_EQ(dense.types, (std::vector<std::int32_t>{2, 1, 1, 1}));
  for (int k = 0; k < 4; ++k) EXPECT_DOUBLE_EQ(dense.elements.x[k], 0.1 * (k + 1));
  const auto mixed = parse_dump_frames(frame(0, 4, kColumns, "3 1 0.3 0 0 0.01\n1 2 0.1 0 0 0.01\n9 1 0.9 0 0 0.01\n2 1 0.2 0 0 0.01\n"),
                                       "d.dump", {})[0];
  EXPECT_EQ(mixed.ids, (std::vector<std::int64_t>{1, 2, 3, 9}));
  EXPECT_DOUBLE_EQ(mixed.elements.x[3], 0.9);
  EXPECT_DOUBLE_EQ(mixed.elements.x[1], 0.2);
  EXPECT_EQ(mixed.types, (std::vector<std::int32_t>{2, 1, 1, 1}));
  EXPECT_EQ(custom_error(frame(0, 4, kColumns, "3 1 0.3 0 0 0.01\n1 2 0.1 0 0 0.01\n9 1 0.9 0 0 0.01\n3 1 0.2 0 0 0.01\n")),
            "d.dump:13: atom id 3 appears twice in the frame of timestep 0 (lines 10 and 13)");
}

TEST(LammpsDump, SparseIdsTakeTheSortedPath) {
  const auto f = parse_dump_frames(frame(0, 3, kColumns, "9000000000 1 0.1 0.1 0.1 0.01\n2 1 0.2 0.2 0.2 0.01\n700 1 0.3 0.3 0.3 0.01\n"),
                                   "d.dump", {})[0];
  EXPECT_EQ(f.ids, (std::vector<std::int64_t>{2, 700, 9000000000}));
  EXPECT_DOUBLE_EQ(f.elements.x[2], 0.1);
  EXPECT_NE(custom_error(frame(0, 3, kColumns, "9000000000 1 0.1 0.1 0.1 0.01\n2 1 0.2 0.2 0.2 0.01\n2 1 0.3 0.3 0.3 0.01\n")).find("atom id 2 appears twice"),
            std::string::npos);
}

TEST(LammpsDump, RepeatedIdNamesTheIdAndBothLines) {
  EXPECT_EQ(custom_error(frame(7, 3, kColumns, "1 1 0.1 0.1 0.1 0.01\n2 1 0.2 0.2 0.2 0.01\n1 1 0.3 0.3 0.3 0.01\n")),
            "d.dump:12: atom id 1 appears twice in the frame of timestep 7 (lines 10 and 12)");
}

TEST(LammpsDump, TimeItemBeforeOrAfterTimestep) {
  const std::string rows = "1 1 0.1 0.1 0.1 0.01\n";
  const auto before = parse_dump_frames("ITEM: TIME\n0.25\n" + frame(10, 1, kColumns, rows), "d.dump", {});
  EXPECT_DOUBLE_EQ(*before[0].time, 0.25);
  std::string after = frame(10, 1, kColumns, rows);
  after.insert(after.find("ITEM: NUMBER"), "ITEM: TIME\n0.5\n");
  EXPECT_DOUBLE_EQ(*parse_dump_frames(after, "d.dump", {})[0].time, 0.5);
}

TEST(LammpsDump, ScaledPositionsAreFractionsOfTheBox) {
  const auto f = parse_dump_frames(frame(0, 1, "id xs ys zs radius", "1 0.25 0.5 0.75 0.1\n", "ff ff ff", "2 6\n-1 1\n0 10\n"), "d.dump", {})[0];
  EXPECT_DOUBLE_EQ(f.elements.x[0], 3.0);
  EXPECT_DOUBLE_EQ(f.elements.y[0], 0.0);
  EXPECT_DOUBLE_EQ(f.elements.z[0], 7.5);
  EXPECT_FALSE(f.elements.box.any());
}

TEST(LammpsDump, PeriodicAxesWrapUnwrappedCentresByWholePeriods) {
  const auto f = parse_dump_frames(frame(0, 3, "id xu yu zu radius", "1 10.25 -3.5 1 0.1\n2 1 0.5 0.5 0.1\n3 0.5 0.5 0.5 0.1\n",
                                         "pp ff pp", "0 1\n-5 5\n0 1\n"),
                                   "d.dump", {})[0];
  EXPECT_DOUBLE_EQ(f.elements.x[0], 0.25);
  EXPECT_DOUBLE_EQ(f.elements.y[0], -3.5);  // ff: not wrapped
  EXPECT_DOUBLE_EQ(f.elements.z[0], 0.0);   // z == hi is the image of lo
  EXPECT_DOUBLE_EQ(f.elements.x[1], 0.0);
  EXPECT_TRUE(f.elements.box.periodic[0]);
  EXPECT_FALSE(f.elements.box.periodic[1]);
  DumpOptions none;
  none.periodic = std::array<bool, 3>{false, false, false};
  EXPECT_DOUBLE_EQ(parse_dump_frames(frame(0, 1, "id xu yu zu radius", "1 10.25 0 0 0.1\n"), "d.dump", none)[0].elements.x[0], 10.25);
}

TEST(LammpsDump, RadiusFromDiameterTypeOrOption) {
  EXPECT_DOUBLE_EQ(parse_dump_frames(frame(0, 1, "id x y z diameter", "1 0 0 0 0.5\n"), "d.dump", {})[0].elements.r[0], 0.25);
  DumpOptions by_type;
  by_type.type_radius = {{1, 0.0015}, {2, 0.00225}};
  const auto f = parse_dump_frames(frame(0, 2, "id type x y z", "1 2 0 0 0\n2 1 0 0 0\n"), "d.dump", by_type)[0];
  EXPECT_DOUBLE_EQ(f.elements.r[0], 0.00225);
  EXPECT_DOUBLE_EQ(f.elements.r[1], 0.0015);
  EXPECT_EQ(custom_error(frame(0, 1, "id type x y z", "1 3 0 0 0\n"), by_type),
            "d.dump:10: no radius for type 3 (--type-radius names no such type)");
  DumpOptions one;
  one.radius = 0.1;
  EXPECT_DOUBLE_EQ(parse_dump_frames(frame(0, 1, "id type x y z", "1 3 0 0 0\n"), "d.dump", one)[0].elements.r[0], 0.1);
  EXPECT_NE(custom_error(frame(0, 1, "id type x y z", "1 3 0 0 0\n")).find("d.dump:9: no radius"), std::string::npos);
}

TEST(LammpsDump, TwoDimensionsWithoutZOrWhenForced) {
  EXPECT_EQ(parse_dump_frames(frame(0, 1, "id x y radius", "1 0.5 0.5 0.1\n"), "d.dump", {})[0].elements.dim, 2);
  DumpOptions flat;
  flat.force_2d = true;
  const auto f = parse_dump_frames(frame(0, 1, kColumns, "1 1 0.5 0.5 0 0.1\n"), "d.dump", flat)[0];
  EXPECT_EQ(f.elements.dim, 2);
  EXPECT_EQ(f.elements.z.size(), 0);
  EXPECT_FALSE(f.elements.box.periodic[2]);
}

TEST(LammpsDump, EveryRefusalNamesFileAndLine) {
  const std::string row = "1 1 0.1 0.1 0.1 0.01\n";
  EXPECT_EQ(custom_error(frame(0, 1, "type x y z radius", "1 0.1 0.1 0.1 0.01\n")),
            "d.dump:9: ITEM: ATOMS has no `id` column (nbscope names elements by their atom ids)");
  EXPECT_NE(custom_error(frame(0, 1, "id type radius", "1 1 0.1\n")).find("d.dump:9: ITEM: ATOMS has no position columns"), std::string::npos);
  EXPECT_EQ(custom_error(frame(0, 1, kColumns, row, "xy xz yz pp pp pp", "0 1 0\n0 1 0\n0 1 0\n")),
            "d.dump:5: a triclinic box (BOX BOUNDS xy xz yz): nbscope reads orthogonal boxes only");
  EXPECT_EQ(custom_error(frame(0, 2, kColumns, row)), "d.dump:10: timestep 0 has 1 rows, NUMBER OF ATOMS says 2");
  EXPECT_EQ(custom_error(frame(0, 1, kColumns, "1 1 0.1 0.1 0.01\n")), "d.dump:10: 5 columns; ITEM: ATOMS names 6");
  EXPECT_EQ(custom_error(frame(0, 1, kColumns, "1 1 0.1 abc 0.1 0.01\n")), "d.dump:10: y: 'abc' is not a number");
  EXPECT_EQ(custom_error(frame(0, 1, kColumns, "1 1 0.1 nan 0.1 0.01\n")), "d.dump:10: y: 'nan' is not a finite number");
  EXPECT_EQ(custom_error(frame(0, 1, kColumns, "1 1 0.1 0.1 0.1 0\n")), "d.dump:10: radius: '0' is not > 0");
  EXPECT_EQ(custom_error(frame(0, 1, kColumns, "1.5 1 0.1 0.1 0.1 0.1\n")), "d.dump:10: id: '1.5' is not an integer");
  EXPECT_EQ(custom_error("ITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\nITEM: ATOMS id x y z radius\n"),
            "d.dump:7: ITEM: ATOMS before ITEM: TIMESTEP");
  EXPECT_EQ(custom_error(frame(0, 1, kColumns, row) + "2 1 0.1 0.1 0.1 0.1\n"),
            "d.dump:11: '2 1 0.1 0.1 0.1 0.1' where an ITEM line was expected (more rows than NUMBER OF ATOMS?)");
  EXPECT_EQ(custom_error(frame(5, 1, kColumns, row) + frame(3, 1, kColumns, row)),
            "d.dump:11: timestep 3 after timestep 5 (d.dump:1): timesteps must increase within a file");
  EXPECT_EQ(custom_error(std::string("ITEM: TIMESTEP\n0\0\n", 17)).substr(0, 31), "d.dump:2: a NUL byte (byte 17):");
  EXPECT_EQ(custom_error("ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n200000000\n"),
            "d.dump:4: NUMBER OF ATOMS 200000000 is outside 0 to 100000000, the most elements nbscope reads");
  EXPECT_EQ(custom_error("  \n"), "d.dump:1: empty file (expected a LAMMPS `dump custom` file)");
  EXPECT_EQ(custom_error(std::string(70000, 'x')).substr(0, 35), "d.dump:1: a line longer than 64 KB,");
}

// A pipe gives a dump in pieces, a file in 4 MB chunks: a fault further on (a NUL byte, a corrupt
// gzip stream) must not be met before the lines ahead of it, or the two would refuse the same bytes
// with different messages (the pipe fuzz target found the gzip case).
TEST(LammpsDump, AFaultFurtherOnComesAfterTheErrorsOfTheLinesBeforeIt) {
  const std::string bad_row = frame(0, 1, kColumns, "1 1 0.1 0.1 0.01\n");  // line 10: 5 columns
  const std::string with_nul = bad_row + std::string("ITEM: TIMESTEP\n\0\n", 17);
  EXPECT_EQ(custom_error(with_nul), "d.dump:10: 5 columns; ITEM: ATOMS names 6");
  const std::string dir = temp_dir("fault");
  write_file(dir + "/nul.dump", with_nul);
  EXPECT_EQ(error_of([&] { read_dump_frames({dir + "/nul.dump"}, {}); }), dir + "/nul.dump:10: 5 columns; ITEM: ATOMS names 6");
  // The same rows gzipped, the trailer's CRC broken: zlib sees it only after inflating every row.
  gzFile gz = gzopen((dir + "/crc.dump.gz").c_str(), "wb");
  gzwrite(gz, bad_row.data(), static_cast<unsigned>(bad_row.size()));
  gzclose(gz);
  std::string bytes;
  {
    std::ifstream in(dir + "/crc.dump.gz", std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  ASSERT_GT(bytes.size(), 8u);
  bytes[bytes.size() - 8] = static_cast<char>(bytes[bytes.size() - 8] ^ 0x55);
  write_file(dir + "/crc.dump.gz", bytes);
  EXPECT_EQ(error_of([&] { read_dump_frames({dir + "/crc.dump.gz"}, {}); }),
            dir + "/crc.dump.gz:10: 5 columns; ITEM: ATOMS names 6");
  // A good frame before the same fault: the fault itself is the message.
  const std::string good = frame(0, 1, kColumns, "1 1 0.1 0.1 0.1 0.01\n");
  write_file(dir + "/nul2.dump", good + std::string("ITEM: TIMESTEP\n\0\n", 17));
  const std::string nul_at = dir + "/nul2.dump:12: a NUL byte (byte 149):";
  EXPECT_EQ(error_of([&] { read_dump_frames({dir + "/nul2.dump"}, {}); }).substr(0, nul_at.size()), nul_at);
  fs::remove_all(dir);
}

TEST(LammpsDump, AtomsLostAndInsertedKeepTheirIdsAcrossFrames) {
  const std::string text = frame(0, 3, kColumns, "1 1 0.1 0.1 0.1 0.01\n2 1 0.2 0.2 0.2 0.01\n3 1 0.3 0.3 0.3 0.01\n") +
                           frame(10, 3, kColumns, "4 1 0.4 0.4 0.4 0.01\n3 1 0.35 0.3 0.3 0.01\n1 1 0.15 0.1 0.1 0.01\n");
  const Recording rec = recording_from_dumps(parse_dump_frames(text, "d.dump", {}), {}, 0.001, "d.dump");
  ASSERT_EQ(rec.frames.size(), 2u);
  EXPECT_EQ(rec.frames[1].ids, (std::vector<std::int64_t>{1, 3, 4}));
  EXPECT_DOUBLE_EQ(rec.frames[1].elements.x[1], 0.35);  // atom 3 is row 1 now, row 2 before
  EXPECT_EQ(rec.frames[1].number, 10);
  EXPECT_DOUBLE_EQ(rec.frames[1].time, 0.01);
  EXPECT_FALSE(rec.has_pairs);
}

TEST(LammpsDump, GzipFilesAndGlobsOrderedByTimestepNotName) {
  const std::string dir = temp_dir("gz");
  const std::string rows = "2 1 0.2 0.2 0.2 0.01\n1 1 0.1 0.1 0.1 0.01\n";
  gzFile gz = gzopen((dir + "/atoms.a.dump.gz").c_str(), "wb");
  const std::string late = frame(2000, 2, kColumns, rows);
  gzwrite(gz, late.data(), static_cast<unsigned>(late.size()));
  gzclose(gz);
  write_file(dir + "/atoms.b.dump", frame(500, 2, kColumns, rows));
  const std::vector<std::string> paths = expand_dump_spec("--dump", dir + "/atoms.*");
  ASSERT_EQ(paths.size(), 2u);
  const auto frames = read_dump_frames(paths, {});
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].timestep, 500);
  EXPECT_EQ(frames[1].timestep, 2000);
  EXPECT_EQ(frames[1].ids, (std::vector<std::int64_t>{1, 2}));
  EXPECT_EQ(frames[1].where, dir + "/atoms.a.dump.gz:1");
  DumpOptions first;
  first.max_frames = 1;
  EXPECT_EQ(read_dump_frames(paths, first).size(), 1u);
  write_file(dir + "/atoms.c.dump", frame(500, 2, kColumns, rows));
  EXPECT_EQ(error_of([&] { read_dump_frames(expand_dump_spec("--dump", dir + "/atoms.*"), {}); }),
            dir + "/atoms.c.dump:1: timestep 500 is also in " + dir + "/atoms.b.dump:1 (two dumps of one run?)");
  write_file(dir + "/bad.gz", std::string("\x1f\x8b\x08\x00garbage, not deflate data", 30));
  EXPECT_NE(error_of([&] { read_dump_frames({dir + "/bad.gz"}, {}); }).find(dir + "/bad.gz: cannot read the dump file: "), std::string::npos);
  EXPECT_EQ(error_of([&] { read_dump_frames({dir + "/absent.dump"}, {}); }), dir + "/absent.dump: no such file");
  EXPECT_EQ(error_of([&] { read_dump_frames({dir}, {}); }), dir + ": a directory, not a dump file");
  EXPECT_EQ(error_of([&] { expand_dump_spec("--dump", dir + "/none.*"); }), "--dump: '" + dir + "/none.*': no file matches");
  EXPECT_EQ(error_of([&] { expand_dump_spec("--dump", dir + "/none"); }), "--dump: '" + dir + "/none': no file matches");
  fs::remove_all(dir);
}

// A seek (issue 36: one frame of a big dump cost the whole file): the frame asked for is parsed, the
// others' rows only counted, so rows that are no atoms there do not stop it.
TEST(LammpsDump, SeekParsesOnlyTheFrameOfItsTimestep) {
  const std::string good = "2 1 0.2 0.2 0.2 0.01\n1 2 0.1 0.1 0.1 0.01\n";
  const std::string junk = "not an atom\n1 1 0.1 abc\n";
  const std::string text = frame(0, 2, kColumns, junk) + frame(1000, 2, kColumns, good) + frame(2000, 2, kColumns, junk);
  EXPECT_NE(custom_error(text), "");  // reading every frame parses the junk
  const DumpSeek middle = seek_dump_frame_in(text, "d.dump", 1000, {});
  ASSERT_TRUE(middle.frame.has_value());
  EXPECT_EQ(middle.frame->timestep, 1000);
  EXPECT_EQ(middle.frame->where, "d.dump:12");
  EXPECT_EQ(middle.frame->ids, (std::vector<std::int64_t>{1, 2}));
  EXPECT_EQ(middle.frame->types, (std::vector<std::int32_t>{2, 1}));
  EXPECT_EQ(middle.frames, 2);  // stopped after its frame
  // No such timestep: every frame counted, none parsed.
  const DumpSeek absent = seek_dump_frame_in(text, "d.dump", 1500, {});
  EXPECT_FALSE(absent.frame.has_value());
  EXPECT_EQ(absent.frames, 3);
  EXPECT_EQ(absent.first_timestep, 0);
  EXPECT_EQ(absent.last_timestep, 2000);
  // No timestep: the first frame, the others counted.
  const DumpSeek first = seek_dump_frame_in(frame(0, 2, kColumns, good) + frame(1000, 2, kColumns, junk), "d.dump", std::nullopt, {});
  ASSERT_TRUE(first.frame.has_value());
  EXPECT_EQ(first.frame->timestep, 0);
  EXPECT_EQ(first.frames, 2);
  // A bad first frame is refused only when it is the only one; else the count says choose one.
  const DumpSeek bad_first = seek_dump_frame_in(frame(0, 2, kColumns, junk) + frame(1000, 2, kColumns, good), "d.dump", std::nullopt, {});
  EXPECT_FALSE(bad_first.frame.has_value());
  EXPECT_EQ(bad_first.frames, 2);
  EXPECT_EQ(error_of([&] { seek_dump_frame_in(frame(0, 2, kColumns, junk), "d.dump", std::nullopt, {}); }),
            "d.dump:10: id: 'not' is not an integer");
  EXPECT_EQ(error_of([&] { seek_dump_frame_in(frame(0, 2, kColumns, "1 1 0.1 0.1 0.1 0.01\n1 1 0.1 0.1 0.1 0.01\n"), "d.dump", std::nullopt, {}); }),
            "d.dump:11: atom id 1 appears twice in the frame of timestep 0 (lines 10 and 11)");
  // The same through a gzip file.
  const std::string dir = temp_dir("seek");
  gzFile gz = gzopen((dir + "/atoms.dump.gz").c_str(), "wb");
  gzwrite(gz, text.data(), static_cast<unsigned>(text.size()));
  gzclose(gz);
  const DumpSeek zipped = seek_dump_frame(dir + "/atoms.dump.gz", 1000, {});
  ASSERT_TRUE(zipped.frame.has_value());
  EXPECT_EQ(zipped.frame->ids, (std::vector<std::int64_t>{1, 2}));
  fs::remove_all(dir);
}

// What a seek passes over is still a dump: a frame cut short, extra rows, timesteps out of order and
// a bad ITEM: ATOMS line are refused in a frame it skips as in one it reads.
TEST(LammpsDump, SeekRefusesWhatItSkipsWhenTheItemLinesAreWrong) {
  const std::string good = "1 1 0.1 0.1 0.1 0.01\n";
  const auto seek_error = [](const std::string& text, std::optional<std::int64_t> timestep) {
    return error_of([&] { seek_dump_frame_in(text, "d.dump", timestep, {}); });
  };
  EXPECT_EQ(seek_error(frame(0, 3, kColumns, "x\ny\n") + frame(1000, 1, kColumns, good), 1000),
            "d.dump:12: timestep 0 has 2 rows, NUMBER OF ATOMS says 3");
  EXPECT_EQ(seek_error(frame(0, 1, kColumns, good) + frame(1000, 3, kColumns, "x\n"), 2000),
            "d.dump:20: timestep 1000 has 1 rows, NUMBER OF ATOMS says 3");
  EXPECT_EQ(seek_error(frame(0, 1, kColumns, "x\ny\n") + frame(1000, 1, kColumns, good), 1000),
            "d.dump:11: 'y' where an ITEM line was expected (more rows than NUMBER OF ATOMS?)");
  EXPECT_EQ(seek_error(frame(5, 1, kColumns, good) + frame(3, 1, kColumns, good), 3),
            "d.dump:11: timestep 3 after timestep 5 (d.dump:1): timesteps must increase within a file");
  EXPECT_EQ(seek_error(frame(0, 1, "type x y z radius", "x\n") + frame(1000, 1, kColumns, good), 1000),
            "d.dump:9: ITEM: ATOMS has no `id` column (nbscope names elements by their atom ids)");
  EXPECT_EQ(seek_error(frame(0, 1, kColumns, good) + "ITEM: TIMESTEP\n1000\n", std::nullopt),
            "d.dump:12: the file ends before ITEM: ATOMS (a frame cut short)");
}

TEST(LammpsDump, PrecisionFollowsThePrintedDigits) {
  const std::string coarse = frame(0, 2, kColumns, "1 1 0.0512346 0.05 0.0487654 0.00150000\n2 1 0.05 0.05 0.05 0.0015\n");
  const std::string fine = frame(0, 2, kColumns, "1 1 0.051234567890123457 0.05 0.048765432109876543 0.0015\n2 1 0.05 0.05 0.05 0.0015\n");
  const double p_coarse = parse_dump_frames(coarse, "d.dump", {})[0].precision;
  const double p_fine = parse_dump_frames(fine, "d.dump", {})[0].precision;
  // %g: 6 significant digits of 0.05 are 1e-7 apart: half of it on each coordinate of two atoms.
  EXPECT_GT(p_coarse, 1e-7);
  EXPECT_LT(p_coarse, 1e-6);
  EXPECT_GT(p_fine, 0);
  EXPECT_LT(p_fine, 1e-17);
  DumpOptions fixed;
  fixed.tolerance = 1e-3;
  EXPECT_DOUBLE_EQ(parse_dump_frames(coarse, "d.dump", fixed)[0].precision, 1e-3);
}

std::string local_frame(long timestep, const std::string& names, const std::string& rows, int n) {
  return "ITEM: TIMESTEP\n" + std::to_string(timestep) + "\nITEM: NUMBER OF ENTRIES\n" + std::to_string(n) +
         "\nITEM: BOX BOUNDS pp pp ff\n0 1\n0 1\n0 1\nITEM: ENTRIES " + names + "\n" + rows;
}

std::string local_error(const std::string& text, const ContactColumns& columns = {}) {
  return error_of([&] { parse_dump_contacts(text, "c.dump", columns); });
}

const std::string kPgl = "c_pgl[1] c_pgl[2] c_pgl[3] c_pgl[4] c_pgl[5] c_pgl[6] c_pgl[7] c_pgl[8] c_pgl[9] c_pgl[10]";

TEST(LammpsDumpLocal, PairGranLocalPosIdOrderWithFloatIds) {
  const auto c = parse_dump_contacts(local_frame(500, kPgl, "0.1 0.2 0.3 0.1 0.2 0.31 2753 17.0 0 1e-5 \n0 0 0 0 0 0 4 5 0 1e-6\n", 2),
                                     "c.dump", {});
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].timestep, 500);
  EXPECT_EQ(c[0].ids, (std::vector<std::array<std::int64_t, 2>>{{2753, 17}, {4, 5}}));
  EXPECT_EQ(c[0].lines, (std::vector<std::int64_t>{10, 11}));
  EXPECT_EQ(local_error(local_frame(500, kPgl, "0 0 0 0 0 0 2753.5 17 0 0\n", 1)),
            "c.dump:10: column 7 (c_pgl[7]): '2753.5' is not an integer; read as LIGGGHTS's compute pair/gran/local `pos id` "
            "order (ids in columns 7 and 8), which these values do not fit: give --contact-ids");
  EXPECT_NE(local_error(local_frame(500, kPgl, "0 0 0 0 0 0 1.23457e+06 17 0 0\n", 1)).find("written with an exponent"), std::string::npos);
}

// The ENTRIES names must outlive the text's refills: a file's rows past its first 4 MB chunk (a pipe's
// past its first read) moved them, and a refused id named a column with other bytes (the pipe fuzz target).
TEST(LammpsDumpLocal, ARefusalPastTheFirstChunkNamesItsColumn) {
  const std::string dir = temp_dir("local_chunks");
  std::string rows;
  constexpr int kRows = 250'000;  // 20 bytes each: 5 MB, past the 4 MB chunk
  for (int k = 0; k < kRows; ++k) rows += "0 0 0 0 0 0 1 2 0 0\n";
  write_file(dir + "/c.dump", local_frame(0, kPgl, rows + "0 0 0 0 0 0 2753.5 17 0 0\n", kRows + 1));
  const std::string refused = dir + "/c.dump:250010: column 7 (c_pgl[7]): '2753.5' is not an integer; read as";
  EXPECT_EQ(error_of([&] { read_dump_contacts({dir + "/c.dump"}, {}); }).substr(0, refused.size()), refused);
  fs::remove_all(dir);
}

TEST(LammpsDumpLocal, IdColumnsByNameNumberOrGiven) {
  EXPECT_EQ(parse_dump_contacts(local_frame(0, "dist id1 id2", "0.1 3 4\n", 1), "c.dump", {})[0].ids[0], (std::array<std::int64_t, 2>{3, 4}));
  ContactColumns numbers;
  numbers.numbers = std::array<int, 2>{3, 1};
  EXPECT_EQ(parse_dump_contacts(local_frame(0, "a b c", "3 0.5 4\n", 1), "c.dump", numbers)[0].ids[0], (std::array<std::int64_t, 2>{4, 3}));
  ContactColumns names;
  names.names = std::array<std::string, 2>{"b", "c"};
  EXPECT_EQ(parse_dump_contacts(local_frame(0, "a b c", "0.5 3 4\n", 1), "c.dump", names)[0].ids[0], (std::array<std::int64_t, 2>{3, 4}));
  names.names = std::array<std::string, 2>{"b", "zz"};
  EXPECT_EQ(local_error(local_frame(0, "a b c", "0.5 3 4\n", 1), names), "c.dump:9: --contact-ids: no ENTRIES column named 'zz'");
  EXPECT_EQ(local_error(local_frame(0, "a b c", "0.5 3 4\n", 1)),
            "c.dump:9: which ENTRIES columns hold the contact's atom ids? Give --contact-ids (column numbers 7,8 or names)");
  EXPECT_EQ(local_error(local_frame(0, "id1 id2", "3 4\n", 2)), "c.dump:10: timestep 0 has 1 rows, NUMBER OF ENTRIES says 2");
  EXPECT_EQ(local_error(local_frame(0, "id1 id2", "3 4 5\n", 1)), "c.dump:10: 3 columns; ITEM: ENTRIES names 2");
  EXPECT_EQ(local_error(local_frame(0, "id1 id2", "3 4\n", 50000001)),
            "c.dump:4: NUMBER OF ENTRIES 50000001 is outside 0 to 50000000, the most contacts of one frame nbscope reads");
  EXPECT_EQ(local_frame(0, "id1 id2", "", 0).empty(), false);
  EXPECT_TRUE(parse_dump_contacts(local_frame(0, "id1 id2", "", 0), "c.dump", {})[0].ids.empty());
}

TEST(LammpsDumpLocal, ContactsBecomeRowsAndNameAbsentAtoms) {
  const auto frames = parse_dump_frames(frame(500, 3, kColumns, "99 1 0.1 0.1 0.1 0.1\n17 1 0.2 0.1 0.1 0.1\n40 1 0.9 0.9 0.9 0.1\n"),
                                        "d.dump", {});
  const auto good = parse_dump_contacts(local_frame(500, "id1 id2", "99 17\n", 1), "c.dump", {});
  const PairList rows = contacts_as_rows(frames[0], good[0]);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].i, 2);
  EXPECT_EQ(rows[0].j, 0);
  const auto bad = parse_dump_contacts(local_frame(500, "id1 id2", "17 98\n", 1), "c.dump", {});
  EXPECT_EQ(error_of([&] { contacts_as_rows(frames[0], bad[0]); }),
            "c.dump:10: contact (17, 98): atom 98 is not in the frame of timestep 500 (d.dump:1)");
  const Recording rec = recording_from_dumps(frames, good, std::nullopt, "d.dump");
  EXPECT_TRUE(rec.has_pairs);
  EXPECT_EQ(rec.frames[0].pairs, rows);
  EXPECT_DOUBLE_EQ(rec.frames[0].time, 500);
  const auto other = parse_dump_contacts(local_frame(400, "id1 id2", "99 17\n", 1), "c.dump", {});
  EXPECT_EQ(error_of([&] { recording_from_dumps(frames, other, std::nullopt, "d.dump"); }), "d.dump:1: timestep 500 has no contact frame");
}

}  // namespace
}  // namespace nbscope

// The LAMMPS data file reader (io/lammps_data.hpp): atom styles sphere and atomic, the header's
// timestep and units, sections it does not need skipped, every refusal named by file and line; and
// files written by a real LAMMPS (`write_data`) read back equal to a `dump custom` of the same step.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "io/lammps_data.hpp"
#include "io/lammps_dump.hpp"
#include "support/dump_text.hpp"
#include "support/lammps_run.hpp"

namespace nbscope {
namespace {

using testdump::error_of;

std::string data_error(const std::string& text, const DumpOptions& options = {}) {
  return error_of([&] { parse_lammps_data(text, "d.data", options); });
}

// A write_data file of atom style sphere: three atoms out of id order, sections before and after Atoms.
const char* const kSphere =
    "LAMMPS data file via write_data, version 2 Aug 2023, timestep = 5000, units = lj\n"
    "\n"
    "3 atoms\n"
    "2 atom types\n"
    "\n"
    "0 10 xlo xhi\n"
    "0 8 ylo yhi\n"
    "-1 4 zlo zhi\n"
    "\n"
    "Masses\n"
    "\n"
    "1 1\n"
    "2 1.5\n"
    "\n"
    "Atoms # sphere\n"
    "\n"
    "7 2 1.5 1 9.5 1 2 -1 0 0\n"
    "2 1 1 1 0.25 1.5 2.5 0 0 0\n"
    "4 1 0.75 1 3 4 1 0 0 0\n"
    "\n"
    "Velocities\n"
    "\n"
    "7 0 0 0 0 0 0\n"
    "2 0 0 0 0 0 0\n"
    "4 0 0 0 0 0 0\n";

TEST(LammpsData, SphereRowsBecomeAFrameInIdOrderWithTheHeadersTimestepAndUnits) {
  std::string units;
  const DumpFrame f = parse_lammps_data(kSphere, "d.data", {}, &units);
  EXPECT_EQ(units, "lj");
  EXPECT_EQ(f.timestep, 5000);
  EXPECT_EQ(f.where, "d.data:15");
  EXPECT_EQ(f.ids, (std::vector<std::int64_t>{2, 4, 7}));
  EXPECT_EQ(f.types, (std::vector<std::int32_t>{1, 1, 2}));
  ASSERT_EQ(f.elements.dim, 3);
  EXPECT_EQ(f.elements.r[0], 0.5);  // diameter 1
  EXPECT_EQ(f.elements.r[1], 0.375);
  EXPECT_EQ(f.elements.r[2], 0.75);
  EXPECT_EQ(f.elements.x[2], 9.5);
  EXPECT_EQ(f.elements.y[0], 1.5);
  EXPECT_EQ(f.elements.z[1], 1);
  // Atom 7's image flag ix = -1: x is periodic, over xlo..xhi; y and z are not.
  EXPECT_TRUE(f.elements.box.periodic[0]);
  EXPECT_EQ(f.elements.box.hi[0], 10);
  EXPECT_FALSE(f.elements.box.periodic[1]);
  EXPECT_FALSE(f.elements.box.periodic[2]);
}

TEST(LammpsData, AtomicTakesItsRadiiByTypeAndRowsWithoutImageFlags) {
  const std::string text =
      "a hand-written data file\n\n2 atoms\n0 1 xlo xhi\n0 1 ylo yhi\n0 1 zlo zhi\n\nAtoms # atomic\n\n1 1 0.1 0.2 0.3\n2 2 0.4 0.5 0.6  # a comment\n";
  EXPECT_NE(data_error(text).find("d.data:8: atom style atomic has no diameter: give --type-radius"), std::string::npos) << data_error(text);
  DumpOptions o;
  o.type_radius = {{1, 0.05}, {2, 0.07}};
  std::string units = "x";
  const DumpFrame f = parse_lammps_data(text, "d.data", o, &units);
  EXPECT_EQ(units, "");  // no `units =` in the title
  EXPECT_EQ(f.timestep, 0);
  EXPECT_EQ(f.ids, (std::vector<std::int64_t>{1, 2}));
  EXPECT_EQ(f.elements.r[0], 0.05);
  EXPECT_EQ(f.elements.r[1], 0.07);
  EXPECT_EQ(f.elements.z[1], 0.6);
  o.type_radius = {{1, 0.05}};
  EXPECT_EQ(data_error(text, o), "d.data:11: no radius for type 2 (--type-radius names no such type)");
  o.radius = 0.02;  // the rest
  EXPECT_EQ(parse_lammps_data(text, "d.data", o).elements.r[1], 0.02);
}

TEST(LammpsData, BadInputIsNamedByFileAndLine) {
  const std::string head = "LAMMPS data file via write_data, version 29 Sep 2021, timestep = 0\n\n2 atoms\n0 1 xlo xhi\n0 1 ylo yhi\n0 1 zlo zhi\n\n";
  const std::string atoms = "Atoms # sphere\n\n1 1 0.1 1 0.5 0.5 0.5\n2 1 0.1 1 0.6 0.5 0.5\n";
  EXPECT_EQ(data_error(head + atoms).empty(), true);
  EXPECT_EQ(data_error(head + "Velocities\n\n1 0 0 0 0 0 0\n"), "d.data:10: no Atoms section (the file ends without one)");
  EXPECT_NE(data_error(head + "Atoms\n\n1 1 0.1 1 0.5 0.5 0.5\n").find("d.data:8: Atoms without its `# style` comment"), std::string::npos);
  EXPECT_NE(data_error(head + "Atoms # molecular\n\n1 1 1 0.5 0.5 0.5\n").find("d.data:8: atom style 'molecular': nbscope reads the styles sphere"),
            std::string::npos);
  EXPECT_EQ(data_error(head + "Atoms # sphere\n\n1 1 0.1 1 0.5 0.5\n"),
            "d.data:10: 6 columns; atom style sphere has 7 (id type diameter density x y z) or 10 (and ix iy iz)");
  EXPECT_EQ(data_error(head + "Atoms # sphere\n\n1 1 0.1 1 nan 0.5 0.5\n"), "d.data:10: x: 'nan' is not a finite number");
  EXPECT_EQ(data_error(head + "Atoms # sphere\n\n1 1 0.1 1 0.5 zero 0.5\n"), "d.data:10: y: 'zero' is not a number");
  EXPECT_EQ(data_error(head + "Atoms # sphere\n\n1 1 0.1 1 0.5 0.5 0.5\n\nVelocities\n\n1 0 0 0 0 0 0\n"),
            "d.data:12: the Atoms section has 1 rows, the header says 2 atoms");
  EXPECT_EQ(data_error(head + atoms + "3 1 0.1 1 0.7 0.5 0.5\n"), "d.data:12: more rows in Atoms than the header's 2 atoms");
  EXPECT_NE(data_error(head + "Atoms # sphere\n\n1 1 0 1 0.5 0.5 0.5\n2 1 0.1 1 0.6 0.5 0.5\n").find("d.data:10: diameter: '0' is not > 0"),
            std::string::npos);
  EXPECT_NE(data_error(head + "Atoms # sphere\n\n1 1 0.1 1 0.5 0.5 0.5\n1 1 0.1 1 0.6 0.5 0.5\n").find("atom id 1 appears twice"), std::string::npos);
  EXPECT_EQ(data_error("title\n\n2 atoms\n0 1 xlo xhi\n0 1 ylo yhi\n0 1 zlo zhi\n0.1 0 0 xy xz yz\n\n" + atoms),
            "d.data:7: a triclinic box (xy xz yz): nbscope reads orthogonal boxes only");
  EXPECT_EQ(data_error("title\n\n0 1 xlo xhi\n\n" + atoms), "d.data:5: Atoms before the `N atoms` header line");
}

TEST(LammpsData, IsToldFromADumpAndACsvByItsFirstLines) {
  EXPECT_TRUE(looks_like_lammps_data(kSphere));
  EXPECT_TRUE(looks_like_lammps_data("my own title\n\n  12 atoms  # the count\n"));
  EXPECT_FALSE(looks_like_lammps_data("ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n3 atoms\n"));
  EXPECT_FALSE(looks_like_lammps_data("x,y,r\n0,0,1\n1,0,1\n"));
  EXPECT_EQ(lammps_data_units(kSphere), "lj");
  EXPECT_EQ(lammps_data_units("LAMMPS data file via write_data, version 29 Sep 2021, timestep = 0\n"), "");
}

// A 2D data file (z all 0, LAMMPS's -0.5..0.5 z box) is planar; the same atoms in a deep box are not.
TEST(LammpsData, ADimension2FileIsPlanar) {
  const std::string atoms = "\nAtoms # sphere\n\n1 1 1 1 0.5 0.5 0\n2 1 1 1 1.4 0.5 0\n";
  DumpFrame flat = parse_lammps_data("t\n\n2 atoms\n0 5 xlo xhi\n0 5 ylo yhi\n-0.5 0.5 zlo zhi\n" + atoms, "d.data", {});
  EXPECT_TRUE(is_planar(flat));
  make_planar(flat);
  EXPECT_EQ(flat.elements.dim, 2);
  EXPECT_EQ(flat.elements.z.size(), 0);
  EXPECT_FALSE(is_planar(parse_lammps_data("t\n\n2 atoms\n0 5 xlo xhi\n0 5 ylo yhi\n-5 5 zlo zhi\n" + atoms, "d.data", {})));
}

// A run's look: its first frame with atoms when z is periodic (LIGGGHTS's empty frame 0 passed over),
// none when it is not (its rows not parsed: a bad number there is not seen).
TEST(LammpsData, TheFirstZPeriodicFrameWithAtomsShowsA2dRun) {
  const auto dir = testlammps::fresh_dir("probe");
  const auto frame = [](int step, const char* flags, const std::string& rows, int n) {
    return "ITEM: TIMESTEP\n" + std::to_string(step) + "\nITEM: NUMBER OF ATOMS\n" + std::to_string(n) + "\nITEM: BOX BOUNDS " + flags +
           "\n0 10\n0 10\n-0.5 0.5\nITEM: ATOMS id type x y z radius\n" + rows;
  };
  const std::string rows = "1 1 1 1 0 0.5\n2 1 1.9 1 0 0.5\n";
  std::ofstream(dir / "flat.dump") << frame(0, "pp ff pp", "", 0) << frame(100, "pp ff pp", rows, 2);
  const std::optional<DumpFrame> f = first_z_periodic_frame((dir / "flat.dump").string(), {});
  ASSERT_TRUE(f.has_value());
  EXPECT_EQ(f->timestep, 100);
  EXPECT_TRUE(is_planar(*f));
  std::ofstream(dir / "deep.dump") << frame(0, "pp ff ff", "1 1 1 1 x 0.5\n", 1);
  EXPECT_FALSE(first_z_periodic_frame((dir / "deep.dump").string(), {}).has_value());
  std::filesystem::remove_all(dir);
}

// A dump's head: ITEM: UNITS (first frame only, as dump_modify units yes writes it) and ITEM: TIME.
TEST(LammpsData, ADumpsHeadGivesItsUnitsAndWhetherItHasTimes) {
  const auto dir = testlammps::fresh_dir("head");
  const std::string frame = "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n0\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\nITEM: ATOMS id x y z radius\n";
  std::ofstream(dir / "u.dump") << "ITEM: UNITS\nreal\nITEM: TIME\n0\n" << frame;
  std::ofstream(dir / "plain.dump") << frame;
  const DumpHead u = read_dump_head((dir / "u.dump").string()), plain = read_dump_head((dir / "plain.dump").string());
  EXPECT_EQ(u.units, "real");
  EXPECT_TRUE(u.has_time);
  EXPECT_EQ(plain.units, "");
  EXPECT_FALSE(plain.has_time);
  EXPECT_EQ(parse_dump_frames("ITEM: UNITS\nreal\n" + frame, "d.dump", {}).size(), 1u);  // the reader still passes it by
  std::filesystem::remove_all(dir);
}

// Every prefix of a data file, and every byte of it replaced by a hostile one, is a frame or one Error: never a crash.
TEST(LammpsData, CutAndCorruptedFilesAreAFrameOrAnError) {
  const std::string whole = kSphere;
  const auto parses_or_refuses = [](const std::string& text) {
    try {
      (void)parse_lammps_data(text, "d.data", {});
    } catch (const Error&) {
      // refused, in one line
    }
  };
  for (std::size_t n = 0; n <= whole.size(); ++n) parses_or_refuses(whole.substr(0, n));
  for (std::size_t k = 0; k < whole.size(); ++k)
    for (const char c : {'#', '9', '-', 'e', ' ', '\n', 'A', '\0'}) {
      std::string bad = whole;
      bad[k] = c;
      parses_or_refuses(bad);
    }
}

// ---- files written by LAMMPS itself ----

// `write_data` and a `dump custom` (%.17g, sorted by id) of the same step: the data file's frame has
// the dump's atoms, ids, types, radii and positions, exactly.
void expect_same_as_dump(const std::filesystem::path& dir, const DumpOptions& options, std::int64_t timestep) {
  std::string units;
  const DumpFrame data = read_lammps_data((dir / "state.data").string(), options, &units);
  const std::vector<DumpFrame> dumps = read_dump_frames({(dir / "state.dump").string()}, options);
  ASSERT_EQ(dumps.size(), 1u);
  const DumpFrame& dump = dumps.front();
  EXPECT_EQ(data.timestep, timestep);
  EXPECT_EQ(dump.timestep, timestep);
  ASSERT_GT(data.elements.size(), 100);
  EXPECT_EQ(data.elements.size(), dump.elements.size());
  EXPECT_EQ(data.ids, dump.ids);
  EXPECT_EQ(data.types, dump.types);
  ASSERT_EQ(data.elements.dim, dump.elements.dim);
  for (Eigen::Index k = 0; k < data.elements.size(); ++k) {
    ASSERT_EQ(data.elements.r[k], dump.elements.r[k]) << "atom " << data.ids[static_cast<std::size_t>(k)];
    ASSERT_EQ(data.elements.x[k], dump.elements.x[k]) << "atom " << data.ids[static_cast<std::size_t>(k)];
    ASSERT_EQ(data.elements.y[k], dump.elements.y[k]);
    ASSERT_EQ(data.elements.z[k], dump.elements.z[k]);
  }
}

const char* const kLammpsSphere = R"(units lj
atom_style sphere
boundary f f f
comm_modify vel yes
region box block 0 10 0 10 0 20 units box
create_box 2 box
lattice sc 0.512
region start block 0.5 9.5 0.5 9.5 0.5 6.0 units box
create_atoms 1 region start
variable d atom 0.8+0.4*random(0,1,4857)
set group all diameter v_d
set group all density 1.0
set type 1 type/fraction 2 0.4 1234
pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
timestep 0.001
fix g all gravity 1.0 vector 0.0 0.0 -1.0
fix floor all wall/gran hooke 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 NULL
fix i all nve/sphere
run 700
write_data state.data
write_dump all custom state.dump id type x y z radius modify format line "%d %d %.17g %.17g %.17g %.17g" sort id
)";

TEST(LammpsDataFromLammps, WriteDataOfAtomStyleSphereReadsAsItsDump) {
  NBSCOPE_NEED_LMP();
  const auto dir = testlammps::fresh_dir("sphere");
  ASSERT_TRUE(testlammps::run_lmp(dir, kLammpsSphere)) << "lmp failed: see " << dir;
  expect_same_as_dump(dir, {}, 700);
  EXPECT_FALSE(read_lammps_data((dir / "state.data").string(), {}).elements.box.any());  // boundary f f f: no image flags
  std::filesystem::remove_all(dir);
}

TEST(LammpsDataFromLammps, WriteDataOfAtomStyleAtomicReadsAsItsDumpWithTypeRadii) {
  NBSCOPE_NEED_LMP();
  const auto dir = testlammps::fresh_dir("atomic");
  ASSERT_TRUE(testlammps::run_lmp(dir, R"(units lj
atom_style atomic
lattice fcc 0.8442
region box block 0 5 0 5 0 5
create_box 3 box
create_atoms 1 box
set type 1 type/fraction 2 0.3 77
set type 1 type/fraction 3 0.2 78
mass * 1.0
velocity all create 1.0 87287 loop geom
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0 2.5
fix 1 all nve
run 50
displace_atoms all move 3.3 0 0 units box
write_data state.data
write_dump all custom state.dump id type x y z modify format line "%d %d %.17g %.17g %.17g" sort id
)")) << "lmp failed: see " << dir;
  DumpOptions o;
  o.type_radius = {{1, 0.5}, {2, 0.45}, {3, 0.4}};
  expect_same_as_dump(dir, o, 50);
  const DumpFrame f = read_lammps_data((dir / "state.data").string(), o);
  for (std::size_t k = 0; k < f.types.size(); ++k) ASSERT_EQ(f.elements.r[static_cast<Eigen::Index>(k)], o.type_radius.at(f.types[k]));
  // Every atom moved 3.3 along the periodic x, some across its boundary: their image flags make x periodic.
  EXPECT_TRUE(f.elements.box.periodic[0]);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace nbscope

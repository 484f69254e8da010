// The panels in a run's own units (SimView::units: --units, a data file's, a LAMMPS log's): a real
// LAMMPS `units lj` pour's frame shows its cell size in sigma and its time in tau in Stats and
// Controls, and a run without units keeps nbscope's metres and seconds.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "check/units.hpp"
#include "io/lammps_dump.hpp"
#include "support/lammps_run.hpp"
#include "support/ui3d_fixture.hpp"
#include "ui/panels.hpp"

namespace nbscope::ui {
namespace {

using testui::Frame3d;
using testui::panel_text;
using testui::Scope3d;

// A small LAMMPS lj pour (spheres of diameter 0.8..1.2 in sigma), dumped at step 700 with dt 0.001 tau.
const char* const kLjPour = R"(units lj
atom_style sphere
boundary f f f
comm_modify vel yes
region box block 0 8 0 8 0 16 units box
create_box 1 box
lattice sc 0.512
region start block 0.5 7.5 0.5 7.5 0.5 6.0 units box
create_atoms 1 region start
variable d atom 0.8+0.4*random(0,1,4857)
set group all diameter v_d
set group all density 1.0
pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
timestep 0.001
fix g all gravity 1.0 vector 0.0 0.0 -1.0
fix floor all wall/gran hooke 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 NULL
fix i all nve/sphere
run 700
write_dump all custom atoms.dump id type x y z radius modify format line "%d %d %.17g %.17g %.17g %.17g" sort id
)";

TEST(PanelsInUnits, ALjRunShowsLengthsInSigmaAndTimesInTau) {
  NBSCOPE_NEED_LMP();
  const auto dir = testlammps::fresh_dir("units");
  ASSERT_TRUE(testlammps::run_lmp(dir, kLjPour)) << "lmp failed: see " << dir;
  DumpFrame dump = read_dump_frames({(dir / "atoms.dump").string()}, {}).front();
  std::filesystem::remove_all(dir);
  ASSERT_EQ(dump.timestep, 700);
  Scope3d scope;
  UiHost host;
  host.add_panel(make_controls_panel());
  Frame3d f(std::move(dump.elements), "atoms.dump");
  f.result.time = dump_frame_time(dump.timestep, dump.time, 0.001);  // replay --log gives dt from the log's `timestep`
  f.sim.time_step = 0.5;                                               // frames 500 steps apart
  f.sim.units = *units_named("lj");
  const Grid& g = f.grid();
  char d[32];
  std::snprintf(d, sizeof d, "%.3g", g.cell_size);  // the largest diameter, about 1.2 sigma
  const std::string stats = panel_text(host, f, "Stats");
  EXPECT_NE(stats.find("d = " + std::string(d) + " sigma"), std::string::npos) << stats;
  EXPECT_EQ(stats.find(" m\n"), std::string::npos) << stats;
  const std::string controls = panel_text(host, f, "Controls");
  EXPECT_NE(controls.find("t = 0.700 tau"), std::string::npos) << controls;
  EXPECT_NE(controls.find("time step 0.5 tau"), std::string::npos) << controls;
  EXPECT_EQ(controls.find("ms"), std::string::npos) << controls;
  f.state.selected = 0;
  char r[32];
  std::snprintf(r, sizeof r, "%.4g", f.elements.r[0]);
  EXPECT_NE(panel_text(host, f, "Selection").find("r = " + std::string(r) + " sigma"), std::string::npos) << panel_text(host, f, "Selection");
  // No units (a scene, a .nbsrec): metres and seconds, as before (a radius bare, as the Selection panel always gave it).
  f.sim.units = Units{};
  EXPECT_NE(panel_text(host, f, "Stats").find("d = " + std::string(d) + " m"), std::string::npos);
  EXPECT_NE(panel_text(host, f, "Controls").find("t = 0.700 s"), std::string::npos);
  const std::string bare = panel_text(host, f, "Selection");
  EXPECT_NE(bare.find("r = " + std::string(r) + "\n"), std::string::npos) << bare;
}

// A pair at the boundary of the data's precision gives its gap in the run's units (a bare number without).
TEST(PanelsInUnits, ABoundaryPairsGapCarriesItsUnit) {
  const std::vector<std::int64_t> ids{7, 9};
  const BoundaryPair b{Pair{0, 1}, -3.1e-08, 8.7e-08, false, true};
  const Units lj = *units_named("lj");
  EXPECT_EQ(boundary_line(b, false, &ids, &lj),
            "atoms (7, 9): at the boundary, within the data's precision (gap -3.1e-08 sigma, resolution 8.7e-08 sigma) (R has it, A not)");
  EXPECT_EQ(boundary_line(b, false, &ids),
            "atoms (7, 9): at the boundary, within the data's precision (gap -3.1e-08, resolution 8.7e-08) (R has it, A not)");
}

}  // namespace
}  // namespace nbscope::ui

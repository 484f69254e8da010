// The stepper against `nbscope dump`: dump prints each algorithm's arrays as they stand when its
// lists are complete, i.e. a partial run of the detection; the stepper, positioned at the start of
// the phase that follows the building of those lists, must show exactly the same arrays. Also the
// command-line side of the stepper: `headless --step` refuses what it cannot use.
//
// Index: helpers (CSV out, dump in, phase positions) | per-algorithm comparisons | the test over
// generated sets | --step errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "core/detector.hpp"
#include "core/stepper.hpp"
#include "core/tree.hpp"
#include "support/generators.hpp"
#include "support/run_cli.hpp"

namespace nbscope {
namespace {

using json = nlohmann::json;
using testdata::Layout;

// Writes the elements with every digit, so the binary reads exactly these doubles.
std::string write_csv(const std::string& dir, const Elements& e) {
  std::string text;
  char line[160];
  for (std::int64_t k = 0; k < e.size(); ++k) {
    if (e.dim == 3) {
      std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g\n", e.x[k], e.y[k], e.z[k], e.r[k]);
    } else {
      std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g\n", e.x[k], e.y[k], e.r[k]);
    }
    text += line;
  }
  const std::string path = dir + "/elements.csv";
  testcli::write_text(path, text);
  return path;
}

json dump(const std::string& csv, const std::string& algorithm) {
  const auto r = testcli::run("dump --input '" + csv + "' --algorithm " + algorithm);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return json::parse(r.out);
}

// Every number of a nested JSON array, depth first (C[ix][iy] flattened row-major).
void flatten(const json& j, std::vector<std::int32_t>& out) {
  if (j.is_array()) {
    for (const json& x : j) flatten(x, out);
  } else {
    out.push_back(j.get<std::int32_t>());
  }
}
std::vector<std::int32_t> flat(const json& j) {
  std::vector<std::int32_t> out;
  flatten(j, out);
  return out;
}

// Index of the first Phase event with this label (and index, and layer iz when given), or the end.
std::size_t phase_at(const Stepper& s, const std::string& label, std::int32_t index = -2, std::int32_t iz = -2) {
  const auto& ev = s.events();
  for (std::size_t i = 0; i < ev.size(); ++i) {
    if (ev[i].op != TraceOp::Phase || label != ev[i].label) continue;
    if (index != -2 && ev[i].index != index) continue;
    if (iz != -2 && ev[i].cell[2] != iz) continue;
    return i;
  }
  return ev.size();
}
// Index of the first Phase event after event i, or the end.
std::size_t next_phase_after(const Stepper& s, std::size_t i) {
  const auto& ev = s.events();
  for (std::size_t j = i + 1; j < ev.size(); ++j)
    if (ev[j].op == TraceOp::Phase) return j;
  return ev.size();
}

const std::vector<std::int32_t>& array(const Stepper& s, const std::string& name) {
  const int id = s.array_id(name);
  EXPECT_GE(id, 0) << "no traced array " << name;
  static const std::vector<std::int32_t> none;
  return id >= 0 ? s.state()[id] : none;
}

// The non-empty heads among the first `count` entries of an array: {(index, head)}.
std::set<std::pair<std::int32_t, std::int32_t>> set_heads(const std::vector<std::int32_t>& a, std::size_t count) {
  std::set<std::pair<std::int32_t, std::int32_t>> out;
  for (std::size_t i = 0; i < count && i < a.size(); ++i)
    if (a[i] != -1) out.insert({static_cast<std::int32_t>(i), a[i]});
  return out;
}
std::set<std::pair<std::int32_t, std::int32_t>> set_pairs(const json& j) {
  std::set<std::pair<std::int32_t, std::int32_t>> out;
  for (const json& p : j) out.insert({p[0].get<std::int32_t>(), p[1].get<std::int32_t>()});
  return out;
}
void expect_next(const std::vector<std::int32_t>& next, const json& entries, const char* what) {
  for (const json& p : entries)
    EXPECT_EQ(next.at(p[0].get<std::size_t>()), p[1].get<std::int32_t>()) << what << "[" << p[0] << "]";
}

// ---- per algorithm ---------------------------------------------------------------------------

void compare_screen(Stepper& s, const json& d) {
  s.seek(phase_at(s, "contacts"));
  EXPECT_EQ(array(s, "C"), flat(d["heads"]));
  EXPECT_EQ(array(s, "E"), flat(d["next"]));
}

void compare_tree(Stepper& s, const Grid& g, const json& d) {
  s.seek(phase_at(s, "contacts"));
  std::map<std::int32_t, std::int32_t> leaves, dumped;
  for (const TreeLeaf& l : tree_leaves(g, array(s, "child"), array(s, "HEAD"))) leaves[l.node] = l.head;
  for (const json& l : d["leaves"]) dumped[l["node"].get<std::int32_t>()] = l["head"].get<std::int32_t>();
  EXPECT_EQ(leaves, dumped);
  EXPECT_EQ(array(s, "E"), flat(d["next"]));
}

void compare_sort(Stepper& s, int dim, const json& d) {
  s.seek(phase_at(s, "contacts"));
  EXPECT_EQ(array(s, "order"), flat(d["order"]));
  EXPECT_EQ(array(s, "ix"), flat(d["ix"]));
  EXPECT_EQ(array(s, "iy"), flat(d["iy"]));
  if (dim == 3) {
    EXPECT_EQ(array(s, "iz"), flat(d["iz"]));
  }
}

// A row's x-lists, complete at its "contacts of row" phase: the current row's heads are the first
// nx entries of B (2D) or A (3D).
void compare_rows(Stepper& s, const json& rows, const char* heads, std::size_t nx, std::int32_t iz) {
  for (const json& row : rows) {
    const auto iy = row["iy"].get<std::int32_t>();
    SCOPED_TRACE("row " + std::to_string(iy) + " layer " + std::to_string(iz));
    s.seek(phase_at(s, "contacts of row", iy, iz == -1 ? -2 : iz));
    EXPECT_EQ(set_heads(array(s, heads), nx), set_pairs(row["x_heads"]));
    expect_next(array(s, "X"), row["x_next"], "X");
  }
}

void compare_nbs(Stepper& s, int dim, const json& d) {
  const auto nx = d["nx"].get<std::size_t>(), ny = d["ny"].get<std::size_t>();
  if (dim == 2) {
    s.seek(next_phase_after(s, phase_at(s, "y-lists")));
    EXPECT_EQ(array(s, "y_heads"), flat(d["y_heads"]));
    EXPECT_EQ(array(s, "Y"), flat(d["y_next"]));
    compare_rows(s, d["rows"], "B", nx, -1);
    return;
  }
  s.seek(next_phase_after(s, phase_at(s, "z-lists")));
  EXPECT_EQ(array(s, "C"), flat(d["z_heads"]));
  EXPECT_EQ(array(s, "Z"), flat(d["z_next"]));
  for (const json& layer : d["layers"]) {
    const auto iz = layer["iz"].get<std::int32_t>();
    SCOPED_TRACE("layer " + std::to_string(iz));
    s.seek(next_phase_after(s, phase_at(s, "y-lists of layer", iz)));
    EXPECT_EQ(set_heads(array(s, "B"), ny), set_pairs(layer["y_heads"]));
    expect_next(array(s, "Y"), layer["y_next"], "Y");
    compare_rows(s, layer["rows"], "A", nx, iz);
  }
}

// ---- the comparison over generated sets -----------------------------------------------------

TEST(StepperVsDump, TheStateWhereListsAreCompleteEqualsNbscopeDump) {
  const std::string dir = testcli::scratch_dir("stepper_vs_dump");
  int compared = 0;
  for (const char* name : {"screen", "nbs", "tree", "sort"}) {
    const DetectorInfo* info = nullptr;
    for (const DetectorInfo& i : detector_infos())
      if (i.name == name) info = &i;
    ASSERT_NE(info, nullptr) << name << " is not registered";
    for (int dim : {2, 3}) {
      if ((dim == 2 && !info->dim2) || (dim == 3 && !info->dim3)) continue;
      std::uint64_t seed = 11;
      for (Layout layout : {Layout::Dense, Layout::Clustered, Layout::Touching}) {
        const Elements e = testdata::make_layout(layout, 80, dim, seed++);
        SCOPED_TRACE(std::string(name) + " " + std::to_string(dim) + "D " + testdata::layout_name(layout));
        const json d = dump(write_csv(dir, e), name);
        auto detector = info->make();
        PairList pairs;
        TraceLog log;
        detector->detect_traced(e, DetectOptions{}, pairs, log);
        Stepper s;
        s.load(std::move(log));
        s.seek(s.size());  // start from the far end: the comparisons seek backwards and forwards
        const std::string algo = name;
        if (algo == "screen") compare_screen(s, d);
        if (algo == "tree") compare_tree(s, *detector->last_grid(), d);
        if (algo == "sort") compare_sort(s, dim, d);
        if (algo == "nbs") compare_nbs(s, dim, d);
        ++compared;
      }
    }
  }
  EXPECT_GE(compared, 12);
}

// The comparison can fail: one step short of the end of screen's mapping, one push is missing.
TEST(StepperVsDump, OneEventShortOfTheCompleteListsDiffers) {
  const std::string dir = testcli::scratch_dir("stepper_vs_dump_short");
  const Elements e = testdata::make_layout(Layout::Dense, 40, 2, 3);
  const json d = dump(write_csv(dir, e), "screen");
  auto detector = make_detector("screen");
  PairList pairs;
  TraceLog log;
  detector->detect_traced(e, DetectOptions{}, pairs, log);
  Stepper s;
  s.load(std::move(log));
  s.seek(phase_at(s, "contacts") - 1);
  EXPECT_NE(array(s, "C"), flat(d["heads"]));
}

// ---- headless --step: what it refuses --------------------------------------------------------

TEST(StepperCli, StepNeedsAScreenshotAndANonNegativeCount) {
  const std::string scene = std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/book-fig-3-15.json";
  for (const std::string& args : {std::string("--step 5"), std::string("--step -1 --screenshot /tmp/x.png"),
                                 std::string("--step many --screenshot /tmp/x.png")}) {
    const auto r = testcli::run("headless --scene '" + scene + "' --frames 1 " + args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("nbscope: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("--step"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

#ifdef NBSCOPE_TEST_GUI  // the stepper's picture needs the renderer (the ASan preset builds without it)
// A step past the frame's last operation, an algorithm that records none, or several algorithms:
// one line naming what is wrong, exit 2, and no screenshot.
TEST(StepperCli, StepPastTheEndOrWithoutOperationsIsRefusedWithoutAPicture) {
  const std::string scene = std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/book-fig-3-15.json";
  const std::string png = testcli::scratch_dir("step_refused") + "/step.png";
  const auto run = [&](const std::string& args) {
    std::filesystem::remove(png);
    return testcli::run("headless --scene '" + scene + "' --frames 1 --quiet --screenshot '" + png + "' " + args);
  };
  const std::pair<std::string, std::string> refused[] = {
      {"--algorithm screen --step 78", "--step: 78 is past the last of the 77 operations of frame 1 (screen)"},
      {"--algorithm screen --step 1000000000000", "--step: 1000000000000 is past the last of the 77 operations"},
      {"--algorithm box2d --step 3", "--step: box2d records no operations to step through"},
      {"--algorithm screen,nbs --step 3", "--algorithm screen,nbs names several: give one"},
      {"--algorithm all --step 3", "--algorithm all names several: give one"},
  };
  for (const auto& [args, message] : refused) {
    const auto r = run(args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("nbscope: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(png)) << args;
  }
  // box2d's refusal names the algorithms that can be stepped.
  EXPECT_NE(run("--algorithm box2d --step 3").err.find("brute, tree, sort, screen, nbs"), std::string::npos);
  // The last operation itself, and brute force (its trace is the pair tests), are fine.
  for (const std::string args : {"--algorithm screen --step 77", "--algorithm brute --step 3"}) {
    const auto r = run(args);
    EXPECT_EQ(r.exit_code, 0) << args << ": " << r.err;
    EXPECT_TRUE(std::filesystem::exists(png)) << args;
  }
}

#endif  // NBSCOPE_TEST_GUI

}  // namespace
}  // namespace nbscope

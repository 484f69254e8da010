// The example plugins of examples/detectors/, loaded as --detector-lib loads them (io's loader) and
// run through the frame pipeline on bundled scenes: the reference is the built-in nbs book loops
// to the pair and holds every invariant; each bug is caught within 120 frames by the invariant it
// breaks, and its first violation is located at the operation that lost it.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <optional>
#include <string>

#include "check/pipeline.hpp"
#include "core/error.hpp"
#include "core/frame_trace.hpp"
#include "core/locate.hpp"
#include "core/nbs.hpp"
#include "io/plugin_library.hpp"
#include "io/scene_json.hpp"
#include "physics/live_world.hpp"
#include "physics/world.hpp"

namespace nbscope {
namespace {

// Loads examples/detectors/NAME.so once per process (a registry name is taken once); its name.
std::string plugin(const std::string& name) {
  static std::map<std::string, std::string> loaded;
  const auto it = loaded.find(name);
  if (it != loaded.end()) return it->second;
  return loaded[name] = load_detector_plugin(std::string(NBSCOPE_EXAMPLES_DIR) + "/" + name + ".so");
}

std::string scene_path(const std::string& scene) { return std::string(NBSCOPE_SOURCE_DIR) + "/assets/scenes/" + scene + ".json"; }

// One scene's frames as headless makes them: frame 0, then a Box2D step before each next frame.
class SceneRun {
 public:
  SceneRun(const std::string& scene, const std::string& algorithm)
      : scene_(read_scene_json(scene_path(scene))), world_(std::make_unique<PhysicsWorld>(scene_)), pipeline_(options(algorithm)) {
    detect_.grid = scene_.grid;
    pipeline_.set_detect_options(detect_);
  }
  // Detects and checks the next frame.
  const FrameResult& next() {
    if (frames_ > 0) world_.step();
    FrameInput in;
    in.source = &world_;
    in.first = frames_++ == 0;
    in.where = "frame " + std::to_string(world_.frame()) + ": ";
    return pipeline_.run(in);
  }
  [[nodiscard]] const Elements& elements() const { return world_.elements(); }
  [[nodiscard]] const DetectOptions& detect_options() const { return detect_; }
  // The traced run of the last frame.
  std::shared_ptr<const FrameTrace> trace() { return pipeline_.trace(world_); }

 private:
  static PipelineOptions options(const std::string& algorithm) {
    PipelineOptions o;
    o.algorithm = algorithm;
    return o;
  }
  Scene scene_;
  LiveWorld world_;
  DetectOptions detect_;
  Pipeline pipeline_;
  std::int64_t frames_ = 0;
};

// The first violation of `algorithm` on `scene` within `frames` frames, and where its trace locates it.
struct Caught {
  std::int64_t frame = -1;
  Violation first;
  PairLocation at;
  TraceEvent event;  // the located operation
  CellIndex stray_cell;  // pair.i's cell under the grid
};

std::optional<Caught> first_violation(const std::string& scene, const std::string& algorithm, int frames) {
  SceneRun run(scene, algorithm);
  for (int f = 0; f < frames; ++f) {
    const FrameResult& r = run.next();
    const FrameReport& report = r.selected().report;
    if (report.violations.empty()) continue;
    Caught c;
    c.frame = r.frame;
    c.first = report.violations.front();
    const std::shared_ptr<const FrameTrace> trace = run.trace();
    EXPECT_TRUE(trace->refusal.empty()) << trace->refusal;
    PairCells cells;  // under the grid, as the Stepper computes them
    for (int a = 0; a < 2; ++a) {
      cells.i[static_cast<std::size_t>(a)] = trace->grid.cell(trace->elements.axis(a)[c.first.pair.i], a);
      cells.j[static_cast<std::size_t>(a)] = trace->grid.cell(trace->elements.axis(a)[c.first.pair.j], a);
    }
    c.stray_cell = CellIndex{cells.i[0], cells.i[1]};
    const bool stray = c.first.invariant == Invariant::Cells && c.first.pair.i != c.first.pair.j;  // as the Stepper
    c.at = stray ? locate_stray(trace->log.events(), c.first.pair.i, c.first.pair.j, cells.i, 2)
                 : locate_pair(trace->log.events(), c.first.pair.i, c.first.pair.j, cells, 2);
    if (c.at.event) c.event = trace->log.events()[*c.at.event];
    return c;
  }
  return std::nullopt;
}

// ---- the reference ------------------------------------------------------------------------------

// Frames per bundled scene: 600, fewer for large.json and under the sanitizers (tests/CMakeLists.txt says why).
int frames_of(const std::string& scene) { return scene == "large" ? NBSCOPE_EXAMPLE_FRAMES_LARGE : NBSCOPE_EXAMPLE_FRAMES; }

class ReferencePlugin : public ::testing::TestWithParam<std::string> {};

// Every frame: no violation, and the plugin's pairs are the built-in book loops' in the same order.
TEST_P(ReferencePlugin, HoldsEveryInvariantAndGivesTheBookLoopsPairsInOrder) {
  const std::string name = plugin("nbs_reference");
  SceneRun run(GetParam(), name);
  const std::unique_ptr<Detector> reference = make_detector(name);
  NbsDetector book;
  PairList plugin_pairs, book_pairs;
  std::int64_t pairs = 0;
  for (int f = 0; f < frames_of(GetParam()); ++f) {
    const FrameResult& r = run.next();
    ASSERT_TRUE(r.selected().report.ok()) << "frame " << r.frame << ": " << r.selected().report.violation_count() << " violations, first "
                                          << invariant_name(r.selected().report.violations.front().invariant);
    reference->detect(run.elements(), run.detect_options(), plugin_pairs);
    book.detect_book(run.elements(), run.detect_options(), book_pairs);
    ASSERT_EQ(plugin_pairs, book_pairs) << "frame " << r.frame;
    pairs += static_cast<std::int64_t>(book_pairs.size());
  }
  EXPECT_GT(pairs, 0);
}

INSTANTIATE_TEST_SUITE_P(BundledScenes, ReferencePlugin,
                         ::testing::Values("book-fig-3-15", "default", "dense-box", "gas", "large", "lattice", "left-of-origin",
                                           "mixed-sizes", "pile"),
                         [](const auto& info) {
                           std::string s = info.param;
                           for (char& ch : s)
                             if (ch == '-') ch = '_';
                           return s;
                         });

// The reference's trace is the built-in's: the same operations, lines and cells, in the same order.
TEST(ReferencePlugin, TracesTheBuiltInsOperations) {
  const std::string name = plugin("nbs_reference");
  SceneRun run("book-fig-3-15", name);
  run.next();
  const std::shared_ptr<const FrameTrace> mine = run.trace();
  NbsDetector book;
  TraceLog theirs;
  PairList pairs;
  book.detect_traced(run.elements(), run.detect_options(), pairs, theirs);
  ASSERT_EQ(mine->log.events().size(), theirs.events().size());
  for (std::size_t n = 0; n < theirs.events().size(); ++n) {
    const TraceEvent &a = mine->log.events()[n], &b = theirs.events()[n];
    ASSERT_EQ(a.op, b.op) << n;
    EXPECT_EQ(a.line, b.line) << n;
    EXPECT_EQ(a.element, b.element) << n;
    EXPECT_EQ(a.other, b.other) << n;
    EXPECT_EQ(a.contact, b.contact) << n;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(a.cell[k], b.cell[k]) << n;
  }
  EXPECT_EQ(mine->pseudocode.size(), NbsDetector::pseudocode_2d().size());
}

// ---- the bugs -----------------------------------------------------------------------------------

struct BugCase {
  const char* plugin;
  const char* scene;
  Invariant invariant;
  PairFinding finding;
};

class BugPlugin : public ::testing::TestWithParam<BugCase> {};

TEST_P(BugPlugin, IsCaughtAndLocatedAtTheOperationThatLostThePair) {
  const BugCase& c = GetParam();
  const std::optional<Caught> caught = first_violation(c.scene, plugin(c.plugin), 120);
  ASSERT_TRUE(caught.has_value()) << c.plugin << " broke nothing in 120 frames of " << c.scene;
  EXPECT_EQ(caught->first.invariant, c.invariant) << invariant_name(caught->first.invariant) << ": " << caught->first.what;
  EXPECT_EQ(caught->at.finding, c.finding);
  ASSERT_TRUE(caught->at.event.has_value());
  switch (c.finding) {
    case PairFinding::Tested:  // the test that answered apart
      EXPECT_EQ(caught->event.op, TraceOp::TestPair);
      EXPECT_FALSE(caught->at.contact);
      break;
    case PairFinding::CellVisited:  // the walk of the other's cell, which never reached it
      EXPECT_EQ(caught->event.op, TraceOp::VisitCell);
      break;
    case PairFinding::CellNotVisited:  // the scanner's last mask visit: (ix+1, iy-1) was due after it
      EXPECT_EQ(caught->event.op, TraceOp::VisitCell);
      EXPECT_EQ(caught->event.element, caught->at.scanner);
      EXPECT_EQ(caught->at.cell[0], caught->event.cell[0] + 1);
      EXPECT_EQ(caught->at.cell[1], caught->event.cell[1]);
      break;
    case PairFinding::WrongList:  // the push onto the list of the detector's cell, not the grid's
      EXPECT_EQ(caught->event.op, TraceOp::Push);
      EXPECT_EQ(caught->event.element, caught->first.pair.i);
      EXPECT_EQ(caught->event.cell[0], caught->first.cell_i.ix);
      EXPECT_NE(caught->first.cell_i, caught->first.cell_j);
      break;
    case PairFinding::StaleLink:  // the push that linked the visited cell's list on to the stray
      EXPECT_EQ(caught->event.op, TraceOp::Push);
      EXPECT_EQ(caught->event.writes[0].new_value, caught->first.pair.i);
      EXPECT_EQ(caught->event.cell[0], caught->first.cell_i.ix);
      EXPECT_EQ(caught->event.cell[1], caught->first.cell_i.iy);
      // The stale B[1] chain: the stray lies in the list's column, a row lower; the finder two rows up.
      EXPECT_EQ(caught->stray_cell.ix, caught->first.cell_i.ix);
      EXPECT_EQ(caught->stray_cell.iy, caught->first.cell_i.iy - 1);
      EXPECT_EQ(caught->first.cell_j.iy, caught->stray_cell.iy + 2);
      break;
    default: ADD_FAILURE() << "no such case";
  }
}

INSTANTIATE_TEST_SUITE_P(
    Examples, BugPlugin,
    ::testing::Values(BugCase{"nbs_bug_mask", "pile", Invariant::AEqualsR, PairFinding::CellNotVisited},
                      BugCase{"nbs_bug_trunc", "left-of-origin", Invariant::Cells, PairFinding::WrongList},
                      BugCase{"nbs_bug_push", "pile", Invariant::AEqualsR, PairFinding::CellVisited},
                      BugCase{"nbs_bug_stale", "pile", Invariant::Cells, PairFinding::StaleLink},
                      BugCase{"nbs_bug_strict", "lattice", Invariant::AEqualsR, PairFinding::Tested}),
    [](const auto& info) { return std::string(info.param.plugin); });

// The stale heads lose no pair: every frame's pairs equal the reference's, while the walks are caught.
TEST(BugPlugin, StaleHeadsKeepThePairsAndOnlyTheWalksBreak) {
  SceneRun run("pile", plugin("nbs_bug_stale"));
  std::int64_t strays = 0;
  for (int f = 0; f < 30; ++f) {
    const FrameReport& report = run.next().selected().report;
    EXPECT_EQ(report.broken[static_cast<std::size_t>(Invariant::AEqualsR)], 0) << "frame " << f;
    strays += report.broken[static_cast<std::size_t>(Invariant::Cells)];
  }
  EXPECT_GT(strays, 0);
}

}  // namespace
}  // namespace nbscope

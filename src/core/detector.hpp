// nbscope core: the one interface every contact-detection algorithm implements, and the registry
// that names them for the command line.
#pragma once
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/cells.hpp"
#include "core/elements.hpp"
#include "core/grid.hpp"
#include "core/pairs.hpp"
#include "core/threads.hpp"
#include "core/trace.hpp"

namespace nbscope {

// Inputs of one detection besides the elements.
struct DetectOptions {
  GridOptions grid;                        // cell size / origin overrides (defaults: docs/architecture.md "Cells")
  std::size_t max_pairs = kDefaultMaxPairs;  // past this detection throws Error
  std::int64_t frame = 0;                    // the frame detected, for a plugin's messages (core/plugin_detector.hpp)
  Touching touching = Touching::inclusive;   // whether a pair at exactly zero gap is a contact (core/pairs.hpp)
  // Check the lists a plugin walks on this untraced detection (the checked frames of a run): a
  // plugin that traces and builds lists gets its trace table, each test checked against the cell
  // the walk visited (Detector::walk_check). Off: untraced means no trace call at all.
  bool check_walks = false;
  // Threads the detection may use (nbs: bands of rows, 3D layers, each detected by one thread;
  // the other detectors run on one). Every value gives the same arrays and the same pairs in the
  // same order as 1, the book's serial loops. The command line's default is machine_threads().
  int threads = 1;
  // Fewest elements a band may hold: a set smaller than threads * this runs on fewer threads (a
  // thread costs more than it saves on a few thousand elements). Tests set 1 to band tiny sets.
  std::int64_t min_band_elements = kMinBandElements;
};

// A test of element `stray` from the list of a cell it does not lie in: the list held an element
// of another cell (a head not cleared, a list built on a stale one), found by the walk of `finder`.
struct StrayTest {
  std::int32_t finder = -1;  // the element whose mask visit walked the list
  std::int32_t stray = -1;   // the element found on it
  CellIndex list_cell;       // the cell visited, whose list held `stray`
  CellIndex own_cell;        // the cell `stray` lies in (the detector's own integerisation when it reports one)
  CellIndex finder_cell;     // the cell `finder` lies in (likewise)
};

// What the walk check of one detection found (DetectOptions::check_walks).
struct WalkCheck {
  static constexpr std::size_t kKept = 64;  // stray tests kept in `first`; `count` counts them all
  std::vector<StrayTest> first;
  std::int64_t count = 0;
};

// A detector's own bug seen in what it told nbscope (a plugin: a pair (k, k), out of range or given
// twice, a trace call naming what does not exist, a cell not written): evidence for its frame, a
// `contract` violation located where it happened, never an error that ends the run.
struct Misbehaviour {
  std::string text;                 // "add_pair(447, 447): an element paired with itself"
  Pair subject{-1, -1};             // the elements it names (in range), or -1
  std::size_t operations = 0;       // trace operations recorded before it (its place in the trace)
  bool cut = false;                 // the call was stopped there: the trace holds nothing after it
  bool cycle = false;               // it was stopped because a list closed on itself
  std::int32_t cell_element = -1;   // a cell not written (or outside the grid): its element,
  int cell_axis = -1;               // and its axis
  std::string where;                // "LIBRARY (NAME): frame N: ", for a message of its own
};


// A contact-detection algorithm. Instances keep their arrays between calls (as a simulation
// would), so repeated detection does not reallocate.
class Detector {
 public:
  virtual ~Detector() = default;
  // Registry name, e.g. "nbs".
  [[nodiscard]] virtual std::string_view name() const = 0;
  // True when the detector handles elements of this dimension (2 or 3).
  [[nodiscard]] virtual bool supports_dim(int dim) const = 0;
  // Finds every contact of `elements` into `out_pairs` (cleared first): each pair once, i < j,
  // in the detector's own order. Throws Error on unsupported input or past options.max_pairs.
  virtual void detect(const Elements& elements, const DetectOptions& options, PairList& out_pairs) = 0;
  // As detect(), also recording every book operation into `out_trace` (reset first).
  virtual void detect_traced(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                             TraceLog& out_trace) = 0;
  // Bytes of the detector's own arrays used by the last detection (not the input or the pairs).
  [[nodiscard]] virtual std::size_t own_bytes() const = 0;
  // The grid of the last detection, or nullptr for detectors without one.
  [[nodiscard]] virtual const Grid* last_grid() const { return nullptr; }
  // The cells of the last 2D detection as the detector itself integerised them, or nullptr when it
  // uses the grid's own integerisation (every built-in does): a plugin that reports its cells, which
  // the checks compare with the grid's (docs/architecture.md "Invariants").
  [[nodiscard]] virtual const std::vector<CellIndex>* own_cells() const { return nullptr; }
  // What the walk check of the last detection found, or nullptr when it was not checked (built-ins:
  // their lists are nbscope's own; plugins: DetectOptions::check_walks, 2D, traces and lists).
  [[nodiscard]] virtual const WalkCheck* walk_check() const { return nullptr; }
  // The first misbehaviour of the last detection, or nullptr (built-ins: never).
  [[nodiscard]] virtual const Misbehaviour* misbehaviour() const { return nullptr; }
  // The detector's loops in the book's wording for elements of dimension `dim`, one line each;
  // TraceEvent::line of a traced run indexes this list. Empty for detectors without a trace.
  [[nodiscard]] virtual const std::vector<const char*>& pseudocode(int dim) const;
};

// Throws DetectorBug with the last detection's misbehaviour (none: returns), where no check can hold
// it as a violation (`pairs`, `scaling`).
void throw_if_misbehaved(const Detector& detector);

// Base of a detector written once as `template <int D, class Trace> void run(...)` for D = 2 and 3
// (Self befriends this class): the dimension and the trace (NullTrace when off) are picked here.
// Each detector's .cpp instantiates it explicitly where run() is defined; its header says extern.
template <class Self>
class DimensionalDetector : public Detector {
 public:
  void detect(const Elements& elements, const DetectOptions& options, PairList& out_pairs) final;
  void detect_traced(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                     TraceLog& out_trace) final;

 private:
  template <class Trace>
  void dispatch(const Elements& elements, const DetectOptions& options, PairList& out_pairs, Trace& trace) {
    Self& self = static_cast<Self&>(*this);
    if (elements.dim == 3) {
      self.template run<3>(elements, options, out_pairs, trace);
    } else {
      self.template run<2>(elements, options, out_pairs, trace);
    }
  }
};

template <class Self>
void DimensionalDetector<Self>::detect(const Elements& elements, const DetectOptions& options, PairList& out_pairs) {
  NullTrace none;
  dispatch(elements, options, out_pairs, none);
}

template <class Self>
void DimensionalDetector<Self>::detect_traced(const Elements& elements, const DetectOptions& options,
                                              PairList& out_pairs, TraceLog& out_trace) {
  out_trace.reset();
  dispatch(elements, options, out_pairs, out_trace);
}

// What the registry knows of one algorithm: its name, and what it can do, so that callers ask
// for a capability instead of comparing names. tests/core/test_detectors.cpp holds every entry to its
// word by running it traced.
struct DetectorInfo {
  std::string name;
  std::string summary;  // one line for `nbscope algorithms`
  bool dim2 = true;     // handles 2D elements (Detector::supports_dim(2))
  bool dim3 = false;    // handles 3D elements (Detector::supports_dim(3))
  // detect_traced() records the book's operations (TraceLog events, never none on a scene with
  // a contact), which the stepper walks and `--step` needs. False: it records nothing (box2d).
  bool traces = false;
  // It builds singly connected lists, heads + next arrays with elements pushed at the head
  // (TraceOp::Push events), which the lists overlay draws as arrow chains. False for sort (runs
  // of equal cell keys, no lists), brute and box2d (no arrays at all).
  bool has_lists = false;
  // It finds contacts across a periodic boundary (Elements::box) by the minimum image; false: it
  // refuses a periodic frame with an Error naming itself (nbs and brute are the two that wrap).
  bool periodic = false;
  // It detects on DetectOptions::threads threads (nbs's bands); false: one thread whatever it is
  // given, so a scaling plan measures it once, at 1.
  bool uses_threads = false;
  // The shared library a plugin was loaded from (--detector-lib, as given); empty for a built-in.
  std::string library = {};
  std::function<std::unique_ptr<Detector>()> make;
};

// The `--algorithm` names that are not a detector: every detector, and a recording's own pairs (the
// `recorded` lane, check/recorded_lane.hpp). No detector or plugin may take them.
inline constexpr std::string_view kAllAlgorithms = "all";
inline constexpr std::string_view kRecordedAlgorithm = "recorded";

// All registered algorithms, in registration order (core's own first).
const std::vector<DetectorInfo>& detector_infos();
// Adds an algorithm defined outside core (e.g. physics' "box2d"); a second add of a name is ignored.
void register_detector(DetectorInfo info);
// The registry entry called `name`; throws Error naming the known ones if there is none. The
// reference holds until the next register_detector().
const DetectorInfo& detector_info(std::string_view name);
// Creates the detector called `name`; throws Error naming the known ones if there is none.
std::unique_ptr<Detector> make_detector(std::string_view name);
// "brute, nbs, ..." for messages.
std::string detector_names();
// `name` as run summaries write it: a plugin's with its library's file name ("nbs-bug-mask
// (nbs_bug_mask.so)"), a built-in's or an unknown one's as it is.
std::string detector_label(std::string_view name);

}  // namespace nbscope

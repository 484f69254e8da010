// nbscope core: a detector plugin's C tables (include/nbscope/detector.h) as a Detector. No dlopen
// here (core opens no files): io/plugin_library.hpp finds the symbols and hands them over.
//
// Index: PluginError | cut_plugin_text | PluginCallGuard, PluginCallScope | PluginSymbols |
// check_plugin_info | PluginDescription | PluginDetector.
//
// Everything the plugin says is checked (docs/limits.md "Detector plugins"): pairs in range, never
// i == j, never twice; trace calls that name declared arrays, entries inside their shapes, lines of
// the plugin's pseudocode; cells it reports inside the grid. A breach is a PluginError naming the
// library, the plugin and the frame. The callbacks never throw through the plugin's C frames: the
// first breach is kept, the callback answers "stop", and it is thrown once nbscope_detect returns.
//
// Well-formed but wrong is not a breach: wrong pairs and cells are the checks' business, and so are
// the lists a plugin walks. On the checked frames of a run (DetectOptions::check_walks) a plugin
// that traces its lists gets the trace table, and every test is held against the cell the walk
// visited (WalkCheck): an element of another cell on a cell's list is a stale or wrong list.
#pragma once
#include <nbscope/detector.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/detector.hpp"
#include "core/error.hpp"
#include "core/guarded_ints.hpp"
#include "core/pair_scan.hpp"

namespace nbscope {

// A plugin broke the contract of include/nbscope/detector.h; what() is "LIBRARY (NAME): frame N: what".
class PluginError : public Error {
 public:
  using Error::Error;
};

// Most bytes of a plugin's own text that nbscope keeps (fail() messages, array names, trace labels,
// its summary and pseudocode lines): a 1 MB message is not a 1 MB error line (docs/plugins.md).
inline constexpr std::size_t kMaxPluginTextBytes = 300;

// `text` (may be null: "") as nbscope keeps it: whole when it has at most kMaxPluginTextBytes bytes,
// else its first bytes up to that (cut at a UTF-8 character) and "... (1,048,276 more bytes)".
std::string cut_plugin_text(const char* text);

// `text` (a plugin's label or kind; may be null), cut (cut_plugin_text), as a string that lives as long
// as the process: a trace event's label.
const char* intern_plugin_label(const char* text);

// The calls into a plugin library, each bracketed by a PluginCallGuard.
enum class PluginCallKind {
  load,       // dlopen, which runs the library's constructors
  describe,   // nbscope_detector_describe, and reading what it returned
  detect,     // nbscope_detect
  release,    // nbscope_release
  own_bytes,  // nbscope_own_bytes
};

// How far a traced call got: its operations so far and the last one's kind and pseudocode line, read
// by a crash report or a watchdog (from a signal handler: lock-free atomics) to say where it stopped.
struct PluginProgress {
  std::atomic<std::int64_t> operations{0};  // trace calls made so far in this call
  std::atomic<std::int32_t> op{-1};          // the last one's TraceOp, -1 none
  std::atomic<std::int32_t> line{-1};        // its pseudocode line (0-based), -1 none
};

// Brackets every call into a plugin (io installs crash handlers and a watchdog there:
// io/plugin_library.hpp); core itself needs none.
class PluginCallGuard {
 public:
  virtual ~PluginCallGuard() = default;
  // Before the detect call: where its progress is kept while it runs (null: none), so that a crash or a
  // hang can be located at the last operation it traced.
  virtual void follow(const PluginProgress* progress) { (void)progress; }
  // Called just before the call `kind` runs (on frame `frame` for detect).
  virtual void enter(PluginCallKind kind, std::int64_t frame) = 0;
  // Called as soon as it returns.
  virtual void leave() = 0;
};

// Enters `guard` (when not null) for its lifetime: leave() comes however the scope ends.
class PluginCallScope {
 public:
  PluginCallScope(PluginCallGuard* guard, PluginCallKind kind, std::int64_t frame = 0) : guard_(guard) {
    if (guard_ != nullptr) guard_->enter(kind, frame);
  }
  ~PluginCallScope() {
    if (guard_ != nullptr) guard_->leave();
  }
  PluginCallScope(const PluginCallScope&) = delete;
  PluginCallScope& operator=(const PluginCallScope&) = delete;

 private:
  PluginCallGuard* guard_;
};

// The symbols of one plugin library and where it came from.
struct PluginSymbols {
  std::string library;                       // its path, for messages
  nbscope_describe_fn describe = nullptr;    // required
  nbscope_detect_fn detect = nullptr;        // required
  nbscope_release_fn release = nullptr;      // optional
  nbscope_own_bytes_fn own_bytes = nullptr;  // optional
  std::shared_ptr<PluginCallGuard> guard;    // optional: brackets each call (detect, release, own_bytes)
};

// Most pseudocode lines a plugin may declare per dimension (TraceEvent::line is 8 bits).
inline constexpr std::int32_t kMaxPluginPseudocodeLines = 256;

// Throws Error (without the library's name: the loader adds it) when `info` is not a usable
// description: null, another API version, a name not [a-z0-9_-]+ (at most 64), no dimension,
// pseudocode counts out of [0, kMaxPluginPseudocodeLines] or with a null line.
void check_plugin_info(const nbscope_detector_info* info);

// What a plugin described, copied once (under the describe guard) into nbscope's own memory, each
// text cut (cut_plugin_text): nothing of the plugin's is read again after the load.
struct PluginDescription {
  // `info` must have passed check_plugin_info().
  explicit PluginDescription(const nbscope_detector_info& info);
  PluginDescription(const PluginDescription&) = delete;
  PluginDescription& operator=(const PluginDescription&) = delete;

  std::string name;
  std::string summary;
  std::uint32_t capabilities = 0;
  std::vector<std::string> lines[2];        // pseudocode, 2D and 3D
  std::vector<const char*> line_texts[2];   // c_str() of each of lines[]

  // True when the plugin declared NBSCOPE_CAP_2D (dim 2) or NBSCOPE_CAP_3D (dim 3).
  [[nodiscard]] bool handles(int dim) const {
    return (dim == 2 && (capabilities & NBSCOPE_CAP_2D) != 0) || (dim == 3 && (capabilities & NBSCOPE_CAP_3D) != 0);
  }
  // Its pseudocode lines for `dim`.
  [[nodiscard]] const std::vector<const char*>& lines_of(int dim) const { return line_texts[dim == 3 ? 1 : 0]; }
};

// The registry entry of a described plugin: capabilities as DetectorInfo's, `make` building a
// PluginDetector over `symbols`.
DetectorInfo plugin_detector_info(const PluginSymbols& symbols, std::shared_ptr<const PluginDescription> description);
// The same for an info that check_plugin_info() accepted (copied here: PluginDescription).
DetectorInfo plugin_detector_info(const PluginSymbols& symbols, const nbscope_detector_info& info);

// One instance of a plugin: its state pointer lives as long as the instance (nbscope_release frees it).
class PluginDetector final : public Detector {
 public:
  // `info` must have passed check_plugin_info(); it is copied (PluginDescription).
  PluginDetector(PluginSymbols symbols, const nbscope_detector_info& info);
  // One more instance of a plugin described before.
  PluginDetector(PluginSymbols symbols, std::shared_ptr<const PluginDescription> description);
  ~PluginDetector() override;
  PluginDetector(const PluginDetector&) = delete;
  PluginDetector& operator=(const PluginDetector&) = delete;

  // The plugin's registry name.
  [[nodiscard]] std::string_view name() const override { return name_; }
  // True when the plugin declared NBSCOPE_CAP_2D (dim 2) or NBSCOPE_CAP_3D (dim 3).
  [[nodiscard]] bool supports_dim(int dim) const override;
  // Calls nbscope_detect untraced (trace = NULL); throws PluginError on any breach of the contract.
  void detect(const Elements& elements, const DetectOptions& options, PairList& out_pairs) override;
  // Calls nbscope_detect with the trace table, every call mapped into `out_trace`.
  void detect_traced(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                     TraceLog& out_trace) override;
  // nbscope_own_bytes(state) when the plugin exports it, else 0: asked (guarded) once per detection, as
  // only nbscope_detect changes the state (the window shows it every frame).
  [[nodiscard]] std::size_t own_bytes() const override;
  // The grid the plugin was given (make_grid, as every built-in fits it).
  [[nodiscard]] const Grid* last_grid() const override { return &grid_; }
  // The cells the plugin wrote (NBSCOPE_CAP_CELLS, 2D), else nullptr.
  [[nodiscard]] const std::vector<CellIndex>* own_cells() const override;
  // What the walk check of the last detection found (traced, or DetectOptions::check_walks; 2D
  // plugins declaring NBSCOPE_CAP_TRACES and NBSCOPE_CAP_LISTS), else nullptr.
  [[nodiscard]] const WalkCheck* walk_check() const override;
  // The last detection's first misbehaviour (a bad pair, a broken trace rule, a cell), or nullptr.
  [[nodiscard]] const Misbehaviour* misbehaviour() const override { return misbehaviour_ ? &*misbehaviour_ : nullptr; }
  // Most trace operations one call may make before it is stopped as a runaway loop; 0 (the default):
  // max(2^23, n(n-1)/2 + 64n), more than any book loop makes. Tests set a small one.
  void set_operation_limit(std::int64_t limit) { operation_limit_ = limit; }
  // The plugin's pseudocode lines for `dim`.
  [[nodiscard]] const std::vector<const char*>& pseudocode(int dim) const override;
  // What the plugin described (shared by its instances).
  [[nodiscard]] const std::shared_ptr<const PluginDescription>& description() const { return description_; }
  // Keeps the progress of each call at `progress` (which must outlive this detector), e.g. in memory
  // shared with another process that reports a crash of this one (io/plugin_host.hpp).
  void set_progress(PluginProgress* progress) { progress_ = progress; }

 private:
  void run(const Elements& elements, const DetectOptions& options, PairList& out_pairs, TraceLog* trace);
  // "LIBRARY (NAME): frame N: ", the head of every breach's message: built only when one is thrown.
  [[nodiscard]] std::string where(std::int64_t frame) const;
  // Copies the plugin's cells (has_cells_), or notes the first one not written or outside the grid.
  void check_cells(const Elements& elements, std::size_t operations);
  // Notes the first of `pairs`' first `given_before_breach` that names an element out of [0, elements)
  // or pairs one with itself as the misbehaviour; leaves it unset when none of them does.
  void note_bad_pair(const PairList& pairs, std::size_t given_before_breach, std::int64_t elements, std::size_t operations);
  // True when this detection's walks are checked: traced or asked, 2D, a plugin that traces its lists.
  [[nodiscard]] bool wants_walk_check(const Elements& elements, const DetectOptions& options, bool traced) const;

  PluginSymbols symbols_;
  std::shared_ptr<const PluginDescription> description_;
  std::string name_;
  std::uint32_t capabilities_ = 0;
  void* state_ = nullptr;
  mutable std::size_t own_bytes_ = 0;     // nbscope_own_bytes' answer for the state as it is
  mutable bool own_bytes_known_ = false;  // false until asked after the last detection
  Grid grid_;
  GuardedInts raw_cells_;                // what the plugin wrote: n * dim, prefilled -1, a guard page after it
  std::vector<CellIndex> cells_;
  bool has_cells_ = false;               // the last detection was 2D with NBSCOPE_CAP_CELLS
  PairScanScratch pair_scan_;             // scan_pairs' memory (kept between frames)
  WalkCheck walks_;                      // the last detection's walk check
  std::optional<Misbehaviour> misbehaviour_;  // the last detection's first misbehaviour
  PluginProgress own_progress_;           // the running call's, for a crash report or a watchdog,
  PluginProgress* progress_ = &own_progress_;  // or where set_progress() keeps it
  std::int64_t operation_limit_ = 0;      // set_operation_limit()
  bool walks_checked_ = false;
};

}  // namespace nbscope

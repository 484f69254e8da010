// nbscope io: running a detector plugin in a process of its own (the default; --detector-isolation).
// A plugin that writes out of bounds, crashes or hangs then takes only its host down: nbscope reads
// the host's last words, makes them the frame's misbehaviour (located at the last traced
// operation), and starts a new host for the next frame. docs/plugins.md "Isolation" says what it costs.
//
// Index: PluginIsolation | plugin_host_path | serve_plugin_host (the host's side) |
// IsolatedPluginDetector (nbscope's side).
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/detector.hpp"
#include "core/grid.hpp"
#include "core/plugin_detector.hpp"
#include "io/plugin_wire.hpp"

namespace nbscope {

// Where a plugin's nbscope_detect runs: in a host process of its own, or in nbscope's.
enum class PluginIsolation { process, none };

// The host executable (nbscope-plugin-host): $NBSCOPE_PLUGIN_HOST when set, else beside the running
// binary, else where it is installed (LIBEXECDIR/nbscope), else the build tree's (a test binary's).
// Throws Error when none is there.
std::string plugin_host_path();

// The host's whole life (nbscope-plugin-host LIBRARY TIMEOUT, with its socket on fd 3 and the shared
// progress on fd 4): loads LIBRARY in-process, says it is ready, then answers each request until
// nbscope closes the socket. A crash or a hang in the plugin ends it with the guard's one line on
// stderr (exit 2). Returns the exit code.
int serve_plugin_host(int argc, char** argv);

struct HostProcess;  // a running host: its pid, socket, stderr and shared progress (plugin_host.cpp)

// A plugin detector whose every call runs in a host process; what it gives is what PluginDetector
// would give in-process, plus: a crash or a hang in nbscope_detect is that frame's misbehaviour.
class IsolatedPluginDetector final : public Detector {
 public:
  // `library` as it was loaded; `timeout` the seconds a call may take (0: no limit).
  IsolatedPluginDetector(std::string library, std::shared_ptr<const PluginDescription> description, double timeout);
  // Closes the host, which releases the plugin's state; a crash or a hang there ends nbscope (exit 2), as in-process.
  ~IsolatedPluginDetector() override;
  IsolatedPluginDetector(const IsolatedPluginDetector&) = delete;
  IsolatedPluginDetector& operator=(const IsolatedPluginDetector&) = delete;

  // The plugin's registry name.
  [[nodiscard]] std::string_view name() const override { return description_->name; }
  // True when the plugin declared the dimension.
  [[nodiscard]] bool supports_dim(int dim) const override;
  // PluginDetector::detect, in the host.
  void detect(const Elements& elements, const DetectOptions& options, PairList& out_pairs) override;
  // PluginDetector::detect_traced, in the host; its trace is copied into `out_trace`.
  void detect_traced(const Elements& elements, const DetectOptions& options, PairList& out_pairs,
                     TraceLog& out_trace) override;
  // nbscope_own_bytes in the host (asked once per detection), 0 without one or without a host.
  [[nodiscard]] std::size_t own_bytes() const override;
  // The grid the plugin was given.
  [[nodiscard]] const Grid* last_grid() const override { return &grid_; }
  // The cells the plugin wrote (NBSCOPE_CAP_CELLS, 2D), else nullptr.
  [[nodiscard]] const std::vector<CellIndex>* own_cells() const override { return has_cells_ ? &cells_ : nullptr; }
  // The last detection's walk check, else nullptr.
  [[nodiscard]] const WalkCheck* walk_check() const override { return walks_checked_ ? &walks_ : nullptr; }
  // The last detection's first misbehaviour, a crash or a hang of the host included.
  [[nodiscard]] const Misbehaviour* misbehaviour() const override { return misbehaviour_ ? &*misbehaviour_ : nullptr; }
  // The plugin's pseudocode lines for `dim`.
  [[nodiscard]] const std::vector<const char*>& pseudocode(int dim) const override;
  // PluginDetector::set_operation_limit, in the host.
  void set_operation_limit(std::int64_t limit) { operation_limit_ = limit; }

 private:
  void run(const Elements& elements, const DetectOptions& options, PairList& out_pairs, TraceLog* trace);
  // The host ended in the call: its last words as the frame's misbehaviour, the trace up to there recorded again.
  void host_ended(const Elements& elements, const DetectOptions& options, PairList& out_pairs, TraceLog* trace);
  // "LIBRARY (NAME): frame N: ".
  [[nodiscard]] std::string where(std::int64_t frame) const;

  std::string library_;
  std::shared_ptr<const PluginDescription> description_;
  double timeout_;
  mutable std::unique_ptr<HostProcess> host_;  // null until the first call, and after the host ended
  Grid grid_;
  bool has_cells_ = false;
  std::vector<CellIndex> cells_;
  bool walks_checked_ = false;
  WalkCheck walks_;
  std::optional<Misbehaviour> misbehaviour_;
  mutable std::optional<std::size_t> own_bytes_;  // asked since the last detection
  std::int64_t operation_limit_ = 0;
  bool record_again_ = true;  // after a death in a traced call, record its trace again (not in that recording)
  WireWriter request_;                 // the last request (its memory kept between frames)
  mutable std::vector<char> message_;  // the last reply's bytes (likewise)
  std::vector<TraceEvent> events_;     // the last reply's trace events (likewise)
};

}  // namespace nbscope

// nbscope ui: the Scaling panel — choose detectors, layouts and the range of N, run them in the
// background (the app owns the thread behind ScalingRunner), watch the progress, and read ns and
// bytes per element against N on log-log plots with the book's O(N) and O(N log N) slopes; export
// the rows as CSV.
#pragma once
#include <cstdint>
#include <memory>
#include <string>

#include "core/scaling.hpp"
#include "ui/panel.hpp"

namespace nbscope::ui {

// The panel's title (View menu, --panels "scaling", its key in the settings file).
inline constexpr const char* kScalingTitle = "Scaling";

// A scaling run as the panel sees it: a copy taken once a frame.
struct ScalingStatus {
  bool running = false;
  std::size_t done = 0, total = 0;  // points
  std::string point;                // the last point finished ("nbs loose N=1000")
  ScalingPlan plan;                 // what the rows below measure
  ScalingResult result;             // the rows so far, the skipped points' notes
  double seconds = 0;               // wall time of the run (so far)
  std::string source;               // "" for a run, else the CSV the rows were read from
  std::uint64_t generation = 0;     // changes with every start and every load
};

// Runs a plan away from the UI thread; implemented by the app (app/scaling_job.hpp).
class ScalingRunner {
 public:
  virtual ~ScalingRunner() = default;
  // Starts `plan` unless a run is going on (a finished one is replaced).
  virtual void start(const ScalingPlan& plan) = 0;
  // Asks the run to stop after the detection going on (returns at once).
  virtual void cancel() = 0;
  // The run's state now (never blocks on the run).
  [[nodiscard]] virtual ScalingStatus status() const = 0;
};

// The Export box's default: the user's data directory, never a source tree (the cwd of a run from a
// checkout is one). Shown as typed, so the panel looks the same on every machine.
inline constexpr const char* kScalingExportDefault = "$XDG_DATA_HOME/nbscope/scaling.csv";
// The file an Export path names: a leading "$XDG_DATA_HOME" is that variable, or ~/.local/share when
// it is unset or empty (the XDG default); a leading "~/" is $HOME; any other path as typed. "" when
// the variable it needs is unset.
std::string resolve_export_path(const std::string& typed);

// The Scaling panel on `runner` (docked at the bottom, closed by default).
std::unique_ptr<Panel> make_scaling_panel(std::shared_ptr<ScalingRunner> runner);

}  // namespace nbscope::ui

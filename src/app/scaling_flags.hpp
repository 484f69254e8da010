// nbscope app: the plan flags of `nbscope scaling` and `nbscope headless --scaling run`
// (--algorithm, --layout, --n, --points-per-decade), the terminal progress of a run and its table.
#pragma once
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "app/view_options.hpp"
#include "core/scaling.hpp"

namespace nbscope {

// The largest N the flags accept (1e7 elements: ~400 MB with the detectors' arrays).
inline constexpr std::int64_t kMaxScalingN = 10'000'000;

// "nbs,sort" or "all" (every 2D detector in registry order) into detector names; Error names
// `flag` for an empty, repeated or unknown name, or a detector without 2D.
std::vector<std::string> parse_scaling_algorithms(const std::string& flag, const std::string& text);
// "loose,dense" into layouts (those of scaling_layouts()); Error names `flag` otherwise.
std::vector<Layout> parse_scaling_layouts(const std::string& flag, const std::string& text);
// "MIN..MAX" or "N" (whole numbers, or 1e3-style powers) into n_min, n_max; Error names `flag`.
void parse_n_range(const std::string& flag, const std::string& text, std::int64_t& out_min, std::int64_t& out_max);
// A plan of the detectors `algorithms` (an --algorithm value: names or "all"), the thread counts of
// --threads `threads` (scaling_threads: 1 and N) and --layout, --n and --points-per-decade taken from
// `args`; Error on bad values. `given` tells whether any of the three was.
ScalingPlan take_scaling_plan_flags(Args& args, const std::string& algorithms, int threads, bool* given = nullptr);

// Runs `plan` on this thread, with a one-line progress bar on stderr when `bar` is set.
ScalingResult run_scaling_in_terminal(const ScalingPlan& plan, bool bar);
// The rows as an aligned text table (one line per row), then the notes.
std::string scaling_table(const ScalingResult& result);

// Error when `spec` (a --scaling value: a CSV path or "run") is empty or `view` has no screenshot.
void check_headless_scaling(const std::string& spec, const ViewOptions& view);
// The rows of `spec`: the CSV read and checked (Error "FILE:LINE: ..."), or `plan` run now.
ScalingShown scaling_to_show(const std::string& spec, const ScalingPlan& plan, bool bar);

}  // namespace nbscope

// `nbscope scaling`: every (detector, layout, N) of a plan timed in this process, a table on
// stdout and, with --output, the CSV the Scaling panel and `headless --scaling FILE.csv` plot.
#include <unistd.h>

#include <cstdio>

#include "app/commands.hpp"
#include "app/dump_input.hpp"
#include "app/scaling_flags.hpp"
#include "app/threads_flag.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/plural.hpp"
#include "io/scaling_csv.hpp"

namespace nbscope {

int run_scaling_command(Args& args) {
  const std::string algorithms = args.value("--algorithm").value_or("all");
  ScalingPlan plan = take_scaling_plan_flags(args, algorithms, take_threads(args));
  plan.touching = take_touching(args);
  const auto output = args.value("--output");
  const bool quiet = args.flag("--quiet");
  args.finish();
  check_scaling_plan(plan);
  if (output) check_output_path(*output);  // before minutes of measuring, not after

  const ScalingResult result = run_scaling_in_terminal(plan, !quiet && ::isatty(STDERR_FILENO) == 1);
  std::fputs(scaling_table(result).c_str(), stdout);
  if (output) {
    write_scaling_csv(*output, result.rows);
    if (!quiet)
      std::fprintf(stderr, "nbscope: %s: %s\n", output->c_str(), plural(static_cast<long long>(result.rows.size()), "row").c_str());
  }
  return 0;
}

}  // namespace nbscope

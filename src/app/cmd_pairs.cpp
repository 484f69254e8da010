// `nbscope pairs`: contact pairs of an ELEMENTS.csv, timed without the I/O.
#include <cerrno>
#include <chrono>
#include <cstring>
#include <cstdio>
#include <iostream>
#include <limits>

#include "app/commands.hpp"
#include "app/dump_input.hpp"
#include "app/grid_flags.hpp"
#include "app/threads_flag.hpp"
#include "core/detector.hpp"
#include "core/error.hpp"
#include "core/plugin_detector.hpp"
#include "io/atomic_file.hpp"
#include "io/csv.hpp"
#include "io/plural.hpp"

namespace nbscope {

int run_pairs(Args& args) {
  const auto input = args.value("--input");
  const std::string algorithm = args.value("--algorithm").value_or("nbs");
  const auto output = args.value("--output");
  const long long repeat = args.integer("--repeat").value_or(1);
  DetectOptions options;
  options.max_pairs = static_cast<std::size_t>(args.integer("--max-pairs").value_or(kDefaultMaxPairs));
  const GridFlags grid_flags = take_grid_flags(args);
  options.touching = take_touching(args);
  options.threads = take_threads(args);
  DumpFlags dump_flags = take_dump_flags(args);
  dump_flags.timestep = args.integer("--timestep");
  args.finish();
  if (dump_flags.columns.numbers || dump_flags.columns.names)
    throw Error("--contact-ids: needs --contacts (a dump local file's columns): pairs reads no contacts (replay --contacts FILES and verify --pairs FILE.dump do)");
  if (!input) throw Error("pairs: --input ELEMENTS.csv (or FILE.dump) is required");

  auto detector = make_detector(algorithm);  // before reading: a bad name fails fast
  if (output) check_output_path(*output);    // and a bad output path before any detection
  if (output) check_outputs_distinct({{"--input", *input}}, {{"--output", *output}});
  (void)settle_units_and_log(dump_flags, {*input});  // nothing printed here is a length, but a bad --log is refused
  const InputFrame frame = read_input_frame(*input, dump_flags);
  const Elements& elements = frame.elements;
  if (!detector->supports_dim(elements.dim))
    throw Error(*input + ": algorithm '" + algorithm + "' does not support " + std::to_string(elements.dim) + "D elements");
  options.grid = grid_options_for(grid_flags, elements.dim);

  PairList pairs, first;
  double best = 1e300, total = 0;
  for (long long rep = 0; rep < repeat; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    try {
      detector->detect(elements, options, pairs);
      throw_if_misbehaved(*detector);  // no check here to hold it as a violation
    } catch (const PluginError&) {
      throw;  // names its library and frame
    } catch (const DetectorBug&) {
      throw;  // likewise
    } catch (const Error& e) {
      throw Error(*input + ": " + e.what());  // where: the grid or the pairs of this file
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    best = std::min(best, s);
    total += s;
    sort_pairs(pairs);
    if (repeat == 1) break;
    if (rep == 0) {
      first = pairs;  // kept only to compare the repeats with
    } else if (pairs != first) {
      std::fprintf(stderr, "nbscope: repeat %lld of %s gave %s, the first gave %zu: detection is not repeatable\n",
                   rep + 1, algorithm.c_str(), plural(static_cast<long long>(pairs.size()), "pair").c_str(), first.size());
      return 1;
    }
  }
  if (output) {
    write_pairs_csv(*output, pairs, frame.ids);
  } else {
    write_pairs_csv(std::cout, pairs, frame.ids);
    std::cout.flush();
    if (!std::cout) throw Error(std::string("stdout: cannot write: ") + std::strerror(errno));  // `> /dev/full`
  }
  // The line about the run after its output: when writing fails, the error is the only line on stderr.
  std::fprintf(stderr, "nbscope: %s: %s (%dD), %s, detection %.3f ms", detector_label(algorithm).c_str(),
               plural(static_cast<long long>(elements.size()), "element").c_str(), elements.dim,
               plural(static_cast<long long>(pairs.size()), "pair").c_str(), best * 1e3);
  if (repeat > 1) std::fprintf(stderr, " (best of %lld, mean %.3f ms, all runs agree)", repeat, total / repeat * 1e3);
  std::fprintf(stderr, ", %zu bytes of own arrays", detector->own_bytes());
  if (options.touching == Touching::strict) std::fprintf(stderr, ", touching strict (<)");
  if (elements.box.any()) std::fprintf(stderr, ", periodic");
  std::fputc('\n', stderr);
  if (!frame.note.empty()) std::fprintf(stderr, "nbscope: %s\n", frame.note.c_str());
  return 0;
}

}  // namespace nbscope

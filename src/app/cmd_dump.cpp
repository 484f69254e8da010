// `nbscope dump`: one detector's integer arrays, as they stand when its lists are complete, as JSON
// on stdout (formats in io/dump_json.hpp and the README).
#include <cstdio>
#include <cerrno>
#include <cstring>
#include <iostream>
#include <limits>

#include "app/commands.hpp"
#include "app/dump_input.hpp"
#include "app/grid_flags.hpp"
#include "core/detector.hpp"
#include "core/error.hpp"
#include "core/plugin_detector.hpp"
#include "io/csv.hpp"
#include "io/dump_json.hpp"

namespace nbscope {

int run_dump(Args& args) {
  const auto input = args.value("--input");
  const auto algorithm = args.value("--algorithm");
  const GridFlags grid_flags = take_grid_flags(args);
  const std::string format = args.value("--format").value_or("json");
  const Touching touching = take_touching(args);
  DumpFlags dump_flags = take_dump_flags(args);
  dump_flags.timestep = args.integer("--timestep");
  args.finish();
  if (dump_flags.columns.numbers || dump_flags.columns.names)
    throw Error("--contact-ids: needs --contacts (a dump local file's columns): dump reads no contacts (replay --contacts FILES and verify --pairs FILE.dump do)");
  if (!input) throw Error("dump: --input ELEMENTS.csv is required");
  if (!algorithm) throw Error("dump: --algorithm NAME is required (one of: " + detector_names() + ")");
  if (format != "json") throw Error("dump: --format: '" + format + "' is not a known format (json)");

  auto detector = make_detector(*algorithm);  // before reading: a bad name fails fast
  (void)settle_units_and_log(dump_flags, {*input});  // the arrays hold no lengths, but a bad --log is refused
  const InputFrame frame = read_input_frame(*input, dump_flags);
  const Elements& elements = frame.elements;
  if (!detector->supports_dim(elements.dim))
    throw Error(*input + ": algorithm '" + *algorithm + "' does not support " + std::to_string(elements.dim) + "D elements");

  DetectOptions options;
  options.touching = touching;
  options.grid = grid_options_for(grid_flags, elements.dim);
  TraceLog trace;
  trace.set_keep_tests(false);  // the arrays are all a dump needs
  // Each event is taken as it happens and not kept: the log of 5 million elements took 2.2 GB.
  DumpCollector collector(*algorithm, elements.dim);
  trace.set_consumer([&](const TraceEvent& e) { collector.event(trace, e); });
  PairList pairs;
  try {
    detector->detect_traced(elements, options, pairs, trace);
    throw_if_misbehaved(*detector);  // a plugin's own bug: no check here to hold it
  } catch (const PluginError&) {
    throw;  // names its library and frame
  } catch (const DetectorBug&) {
    throw;  // likewise
  } catch (const Error& e) {
    throw Error(*input + ": " + e.what());  // where: the grid or the pairs of this file
  }

  DumpSource source;
  source.algorithm = *algorithm;
  source.elements = &elements;
  source.grid = detector->last_grid();
  source.trace = &trace;
  source.own_bytes = detector->own_bytes();
  source.pairs = pairs.size();
  source.ids = &frame.ids;
  // Streamed: a document of the whole dump took several times the arrays' memory.
  collector.write(source, std::cout);
  std::cout.flush();
  if (!std::cout) throw Error(std::string("stdout: cannot write: ") + std::strerror(errno));  // `> /dev/full`
  if (!frame.note.empty()) std::fprintf(stderr, "nbscope: %s\n", frame.note.c_str());
  return 0;
}

}  // namespace nbscope

// `nbscope dump`: one detector's integer arrays, as they stand when its lists are complete, as JSON
// on stdout (formats in io/dump_json.hpp and the README).
#include <cmath>
#include <cstdio>

#include "app/commands.hpp"
#include "core/detector.hpp"
#include "core/error.hpp"
#include "io/csv.hpp"
#include "io/dump_json.hpp"

namespace nbscope {

int run_dump(Args& args) {
  const auto input = args.value("--input");
  const auto algorithm = args.value("--algorithm");
  const auto cell_size = args.number("--cell-size");
  const auto origin = args.value("--origin");
  const auto cells = args.value("--cells");
  const std::string format = args.value("--format").value_or("json");
  args.finish();
  if (!input) throw Error("dump: --input ELEMENTS.csv is required");
  if (!algorithm) throw Error("dump: --algorithm NAME is required (one of: " + detector_names() + ")");
  if (format != "json") throw Error("dump: --format: '" + format + "' is not a known format (json)");
  double o[3] = {0, 0, 0}, c[3] = {1, 1, 1};
  const int origin_dim = origin ? parse_point("--origin", *origin, o) : 0;
  const int cells_dim = cells ? parse_point("--cells", *cells, c) : 0;
  for (int a = 0; a < cells_dim; ++a) {
    if (c[a] < 1 || c[a] != std::floor(c[a]) || c[a] > 1e15)
      throw Error("--cells: '" + *cells + "' is not NX,NY or NX,NY,NZ of whole numbers >= 1");
  }

  auto detector = make_detector(*algorithm);  // before reading: a bad name fails fast
  const Elements elements = read_elements_csv(*input);
  if (!detector->supports_dim(elements.dim))
    throw Error(*input + ": algorithm '" + *algorithm + "' does not support " + std::to_string(elements.dim) + "D elements");
  if (origin && origin_dim != elements.dim)
    throw Error("--origin: '" + *origin + "' has " + std::to_string(origin_dim) + " coordinates, the elements are " +
                std::to_string(elements.dim) + "D");
  if (cells && cells_dim != elements.dim)
    throw Error("--cells: '" + *cells + "' has " + std::to_string(cells_dim) + " counts, the elements are " +
                std::to_string(elements.dim) + "D");

  DetectOptions options;
  if (cell_size) options.grid.cell_size = *cell_size;
  if (origin) options.grid.origin = std::array<double, 3>{o[0], o[1], o[2]};
  if (cells) {
    options.grid.cells = std::array<std::int64_t, 3>{static_cast<std::int64_t>(c[0]), static_cast<std::int64_t>(c[1]),
                                                     static_cast<std::int64_t>(c[2])};
  }
  TraceLog trace;
  trace.set_keep_tests(false);  // the arrays are all a dump needs: memory O(writes), not O(tests)
  PairList pairs;
  detector->detect_traced(elements, options, pairs, trace);

  DumpSource source;
  source.algorithm = *algorithm;
  source.elements = &elements;
  source.grid = detector->last_grid();
  source.trace = &trace;
  source.own_bytes = detector->own_bytes();
  source.pairs = pairs.size();
  const std::string text = format_dump(dump_json(source));
  std::fwrite(text.data(), 1, text.size(), stdout);
  return 0;
}

}  // namespace nbscope

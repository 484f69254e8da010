// nbscope tests: nbscope's own arrays of a set of elements as `nbscope dump` writes them, for the
// tests that hold verify's reader and checks to the writer (one copy; three tests had their own).
#pragma once
#include <sstream>
#include <string>

#include "core/detector.hpp"
#include "io/dump_json.hpp"

namespace nbscope::testdump {

// The dump of `algorithm` on `e` as text, byte for byte the writer's (`grid` pins the grid, as a
// user's grid keys would).
inline std::string own_dump_text(const Elements& e, const std::string& algorithm, const GridOptions& grid = {}) {
  auto d = make_detector(algorithm);
  DetectOptions options;
  options.grid = grid;
  TraceLog trace;
  trace.set_keep_tests(false);
  PairList pairs;
  d->detect_traced(e, options, pairs, trace);
  DumpSource s;
  s.algorithm = algorithm;
  s.elements = &e;
  s.grid = d->last_grid();
  s.trace = &trace;
  s.own_bytes = d->own_bytes();
  s.pairs = pairs.size();
  std::ostringstream out;
  write_dump(s, out);
  return out.str();
}

}  // namespace nbscope::testdump

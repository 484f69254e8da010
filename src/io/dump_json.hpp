// nbscope io: `nbscope dump` — a detector's integer arrays as JSON, as they stand when its lists
// are complete (the detectors clear their heads before they return, so the arrays are read from a
// traced run: the state right before the phase that first uses complete lists).
//
// Every index is 0-based and -1 means an empty list or the end of a list. Keys (docs/formats.md "Arrays JSON"):
//   all:     algorithm, dim, elements, pairs, cell_size, origin, nx, ny (nz in 3D), own_bytes, bytes;
//            ids (element k is atom ids[k]) when the elements came from a LAMMPS/LIGGGHTS dump
//   then the algorithm's arrays, as core/array_schema.hpp lays them out (screen, tree, sort, nbs 2D/3D).
#pragma once
#include <cstddef>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "core/elements.hpp"
#include "core/grid.hpp"
#include "core/trace.hpp"

namespace nbscope {

// What one dump is made of: the detector's name and grid, its traced run and its memory.
struct DumpSource {
  std::string algorithm;
  const Elements* elements = nullptr;
  const Grid* grid = nullptr;  // nullptr for detectors without cells (brute)
  const TraceLog* trace = nullptr;
  std::size_t own_bytes = 0;
  std::size_t pairs = 0;
  const std::vector<std::int64_t>* ids = nullptr;  // a dump frame's row -> atom id ("ids"), or null
};

// The dump gathered from a traced run's events as they happen (TraceLog::set_consumer), so that no
// log of the run is kept: for 5 million elements the log took 2.2 GB and a document of the dump
// more, where what is shown is a copy of the arrays and each row's lists.
class DumpCollector {
 public:
  DumpCollector(std::string algorithm, int dim);
  ~DumpCollector();
  DumpCollector(const DumpCollector&) = delete;
  DumpCollector& operator=(const DumpCollector&) = delete;

  // One event of the run, in order; `log` is the run's trace, which declares the arrays.
  void event(const TraceLog& log, const TraceEvent& e);
  // Writes the dump of `source` (its trace: the one the events came from) to `out` in format_dump's
  // layout, keys in the order above. A failed write is left in `out`'s state for the caller.
  void write(const DumpSource& source, std::ostream& out) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The dump of a kept trace (`source.trace->events()`) to `out`, as a collector fed them would write it.
void write_dump(const DumpSource& source, std::ostream& out);

// The same as a JSON document (tests; small dumps).
nlohmann::ordered_json dump_json(const DumpSource& source);

// `json` as text: objects one key a line, arrays of numbers (and arrays of short number arrays,
// such as [ix, head] pairs) on one line, so the book's arrays read as the book prints them.
std::string format_dump(const nlohmann::ordered_json& json);

}  // namespace nbscope

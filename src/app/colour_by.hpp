// nbscope app: --color-by type|vx|overlap|rank|COLUMN of gui, headless, replay (and watch): what
// colours the atoms, read from the frame (a dump's kept columns, its elements, or the overlap nbscope
// computes), checked against the first frame (docs/export.md).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "app/option_spec.hpp"
#include "app/view_options.hpp"
#include "check/frame_result.hpp"
#include "core/elements.hpp"

namespace nbscope {

// --color-by's row, for every command that draws frames.
OptionSpec colour_by_option();
// --color-by's value, when given (any name: it is checked against the frames once they are read).
std::optional<std::string> take_colour_by(Args& args);

// Headless: Error("--color-by: needs --screenshot") for colours with nothing drawn.
void check_colour_by_drawn(const ViewOptions& view);

// One value per element to colour by, and how.
struct ColourValues {
  std::vector<double> values;  // by row
  bool categorical = false;    // type, rank: a colour per value; else a map over the frame's range
  std::string title;           // the legend's: "type", "vx", "overlap", "rank (proc)", "rank"
};

// The values `what` (--color-by's) gives the frame of `result` (its elements `elements`): a kept
// column by name (type, vx, proc, ...), x y z radius diameter id from the elements, `overlap` (each
// atom's largest over its pairs in R, else in the selected lane's A: core's element_overlaps), `rank`
// (the proc column, else `ranks`: the rank whose file held each row, per-rank dumps). Error "--color-by:
// the dump has no column 'foo' (it has: id type x y z radius)" when the frame has no such column (a
// scene's or .nbsrec's frames: none but the elements').
ColourValues colour_values_of(const std::string& what, const FrameResult& result, const Elements& elements,
                              const std::vector<std::int32_t>* ranks = nullptr);

}  // namespace nbscope

// --color-by (colour_by.hpp).
#include "app/colour_by.hpp"

#include "core/error.hpp"
#include "core/pairs.hpp"

namespace nbscope {

OptionSpec colour_by_option() {
  return {"--color-by", "type|vx|overlap|rank|COLUMN", "",
          "colours the atoms by a dump column (type, rank = proc, else the per-rank file: a colour each; vx or any numeric column: a map over the frame's "
          "range) or by overlap (each atom's largest r_i + r_j - |c_i - c_j|, computed by nbscope), with a legend (docs/export.md)"};
}

std::optional<std::string> take_colour_by(Args& args) {
  auto v = args.value("--color-by");
  if (v && v->empty()) throw Error("--color-by: missing column name (type, vx, overlap, rank or a column of the dump)");
  return v;
}

void check_colour_by_drawn(const ViewOptions& view) {
  if (view.colour_by && !view.screenshot) throw Error("--color-by: needs --screenshot (headless draws nothing without one)");
}

namespace {

[[noreturn]] void no_column(const std::string& what, const std::string& column, const FrameResult& result, const Elements& e) {
  std::string has;
  if (result.columns) {
    for (const std::string& h : result.columns->header) has += (has.empty() ? "" : " ") + h;
    throw Error("--color-by" + (what == column ? std::string() : " " + what) + ": the dump has no column '" + column + "' (it has: " + has + ")");
  }
  has = e.dim == 3 ? "x y z radius" : "x y radius";
  throw Error("--color-by" + (what == column ? std::string() : " " + what) + ": the frames have no column '" + column + "' (they have: " +
              has + ", and overlap; columns such as type and vx come from a LAMMPS or LIGGGHTS dump: replay --dump)");
}

}  // namespace

ColourValues colour_values_of(const std::string& what, const FrameResult& result, const Elements& e, const std::vector<std::int32_t>* ranks) {
  ColourValues out;
  out.title = what;
  const auto n = static_cast<std::size_t>(e.size());
  if (what == "overlap") {
    out.values = element_overlaps(e, result.reference.empty() ? result.selected().pairs : result.reference);
    return out;
  }
  const std::string column = what == "rank" ? "proc" : what;
  if (what == "rank") out.title = "rank (proc)";
  out.categorical = what == "type" || what == "rank" || column == "proc";
  if (result.columns) {
    if (const std::vector<double>* v = result.columns->find(column); v != nullptr && v->size() == n) {
      out.values = *v;
      return out;
    }
  }
  if (what == "rank" && ranks != nullptr && ranks->size() == n) {  // per-rank files: the file that held each row
    out.values.assign(ranks->begin(), ranks->end());
    out.title = "rank";
    return out;
  }
  const bool from_file = !result.columns || result.columns->has(column);  // a dump names its columns; other frames have the elements'
  const auto axis = column == "x" ? 0 : column == "y" ? 1 : column == "z" && e.dim == 3 ? 2 : -1;
  if (axis >= 0 && from_file) {
    const Eigen::ArrayXd& c = e.axis(axis);
    out.values.assign(c.data(), c.data() + c.size());
    return out;
  }
  if ((column == "radius" || column == "diameter") && (from_file || column == "radius")) {
    out.values.assign(e.r.data(), e.r.data() + e.r.size());
    if (column == "diameter")
      for (double& v : out.values) v *= 2;
    return out;
  }
  if (column == "id" && result.ids && result.ids->size() == n) {
    out.values.assign(result.ids->begin(), result.ids->end());
    return out;
  }
  no_column(what, column, result, e);
}

}  // namespace nbscope

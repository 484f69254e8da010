// One arrays check: both files read, the grid agreed between the flags, the file and the elements,
// the arrays built for it and walked (app/verify_run.hpp).
#include "app/verify_run.hpp"

#include <cmath>
#include <sstream>

#include "core/array_schema.hpp"
#include "core/error.hpp"
#include "io/arrays_json.hpp"
#include "io/csv.hpp"

namespace nbscope {

namespace {

std::string number_text(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// The grid: the flags' and the file's keys (which must agree where both are given), the rest
// derived from the elements as `nbscope dump` derives it.
GridOptions agreed_grid(const VerifyArraysInputs& in, const ArraysJson& file, int dim) {
  GridOptions flags = grid_options_for(in.grid_flags, dim);
  GridOptions out = file.grid;
  const std::string& f = in.arrays_path;
  if (flags.cell_size) {
    if (out.cell_size && *out.cell_size != *flags.cell_size)
      throw Error("--cell-size " + number_text(*flags.cell_size) + ", but " + f + ": $.cell_size is " + number_text(*out.cell_size));
    out.cell_size = flags.cell_size;
  }
  if (flags.origin) {
    for (int a = 0; a < dim && out.origin; ++a)
      if ((*out.origin)[a] != (*flags.origin)[a])
        throw Error("--origin " + in.grid_flags.origin_text + ", but " + f + ": $.origin[" + std::to_string(a) + "] is " +
                    number_text((*out.origin)[a]));
    out.origin = flags.origin;
  }
  if (flags.cells) {
    for (int a = 0; a < dim && out.cells; ++a)
      if ((*out.cells)[a] != (*flags.cells)[a])
        throw Error("--cells " + in.grid_flags.cells_text + ", but " + f + ": $.n" + std::string(1, "xyz"[a]) + " is " +
                    std::to_string((*out.cells)[a]));
    out.cells = flags.cells;
  }
  if (out.cells && dim == 2) (*out.cells)[2] = 1;
  return out;
}

// Refuses elements outside a pinned grid: the user's arrays were built on a grid that holds them all.
void check_inside(const Elements& e, const Grid& g, const std::string& where) {
  const char* axis = "xyz";
  for (int a = 0; a < e.dim; ++a) {
    const Eigen::ArrayXd& v = e.axis(a);
    for (std::int64_t k = 0; k < e.size(); ++k) {
      const double c = (v[k] - g.origin[a]) / g.cell_size;
      const double eps = verify::kBoundaryTolerance * std::max(1.0, std::fabs(c));
      if (c >= -eps && c < static_cast<double>(g.n[a]) + eps) continue;
      throw Error(where + ": the grid does not hold the elements: element " + std::to_string(k) + " has " + axis[a] + " = " +
                  number_text(v[k]) + ", outside the " + std::to_string(g.n[a]) + " cells of " + number_text(g.cell_size) +
                  " from " + number_text(g.origin[a]) + " (pin the grid the arrays were built on: --cell-size, --origin, --cells)");
    }
  }
}

}  // namespace

VerifyArraysInputs take_verify_inputs(Args& args) {
  VerifyArraysInputs in;
  in.elements_path = args.value("--input").value_or("");
  in.arrays_path = args.value("--arrays").value_or("");
  in.algorithm = args.value("--algorithm");
  if (const auto b = args.integer("--base")) in.base = static_cast<int>(*b);
  in.exact = args.flag("--exact");
  in.grid_flags = take_grid_flags(args);
  return in;
}

VerifyArraysRun run_verify_arrays(const VerifyArraysInputs& in) {
  VerifyArraysRun run;
  ArraysJson file = read_arrays_json(in.arrays_path);
  run.elements = read_elements_csv(in.elements_path);
  const Elements& e = run.elements;
  const std::string& f = in.arrays_path;

  std::string algorithm;
  if (in.algorithm && file.algorithm && *in.algorithm != *file.algorithm)
    throw Error("--algorithm " + *in.algorithm + ", but " + f + ": $.algorithm is \"" + *file.algorithm + "\"");
  if (in.algorithm) {
    algorithm = *in.algorithm;
  } else if (file.algorithm) {
    algorithm = *file.algorithm;
  } else {
    throw Error(f + ": $: no \"algorithm\" key, and no --algorithm (" + array_schema::algorithms_text("or") + ")");
  }
  if (array_schema::find_layout(algorithm, e.dim) == nullptr)
    throw Error((in.algorithm ? std::string("--algorithm") : f + ": $.algorithm") + ": '" + algorithm +
                "': verify checks the arrays of " + array_schema::algorithms_text());
  if (file.dim && *file.dim != e.dim)
    throw Error(f + ": $.dim: " + std::to_string(*file.dim) + "D arrays, but " + in.elements_path + " holds " +
                std::to_string(e.dim) + "D elements");
  if (file.elements && *file.elements != e.size())
    throw Error(f + ": $.elements: " + std::to_string(*file.elements) + ", but " + in.elements_path + " has " +
                std::to_string(e.size()) + " elements");
  if (in.base && file.base && *in.base != *file.base)
    throw Error("--base " + std::to_string(*in.base) + ", but " + f + ": $.base is " + std::to_string(*file.base));
  const int base = in.base.value_or(file.base.value_or(0));

  const GridOptions options = agreed_grid(in, file, e.dim);
  try {
    run.grid = make_grid(e, options);
  } catch (const Error& err) {
    throw Error(f + ": the grid does not fit the elements: " + err.what());
  }
  if (options.cells || options.origin) check_inside(e, run.grid, f);
  run.user = file.arrays(algorithm, run.grid, e.size(), base);
  file.doc.reset();  // the document's tree is not needed past here: free it before the walk
  run.verdict = verify::verify_arrays(e, run.grid, run.user, in.exact);
  return run;
}

}  // namespace nbscope

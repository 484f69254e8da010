// --touching, on every command that detects (app/dump_input.hpp).
#include "app/dump_input.hpp"
#include "core/error.hpp"

namespace nbscope {

Touching take_touching(Args& args) {
  const auto t = args.value("--touching");
  if (!t || *t == "inclusive") return Touching::inclusive;
  if (*t == "strict") return Touching::strict;
  throw Error("--touching: '" + *t + "' is not inclusive (|c_i - c_j| <= r_i + r_j, the default) or strict (<, as LAMMPS and LIGGGHTS)");
}

}  // namespace nbscope

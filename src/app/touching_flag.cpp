// --touching, on every command that detects (app/dump_input.hpp).
#include "app/dump_input.hpp"

namespace nbscope {

Touching take_touching(Args& args) {
  // A choice of its row (touching_option): the parser refused any other word.
  return args.value("--touching") == "strict" ? Touching::strict : Touching::inclusive;
}

}  // namespace nbscope

// nbscope core: the one error type that every layer reports bad input with.
#pragma once
#include <stdexcept>
#include <string>

namespace nbscope {

// An error in the user's input or request; the app prints "nbscope: error: <what>" and exits 2.
// `what()` already names the place ("file.csv:12: ...") when the thrower knows it.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace nbscope

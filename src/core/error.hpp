// nbscope core: the one error type that every layer reports bad input with.
#pragma once
#include <stdexcept>
#include <string>
#include <string_view>

namespace nbscope {

// An error in the user's input or request; the app prints "nbscope: error: <what>" and exits 2.
// `what()` already names the place ("file.csv:12: ...") when the thrower knows it.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A detector's own bug where no check can hold it as a violation (`pairs`, `scaling`: no frame
// checks): the app prints "nbscope: error: <what>" and exits 1, as a violation would.
class DetectorBug : public Error {
 public:
  using Error::Error;
};

// `text` made safe for one line of a terminal: control bytes and bytes that are not valid UTF-8
// (echoed from a bad input file) become \xNN; valid UTF-8, e.g. a file name with accents, stays.
std::string printable_line(std::string_view text);

}  // namespace nbscope

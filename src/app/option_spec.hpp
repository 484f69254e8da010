// nbscope app: one option's row in the command table (app/command_table.hpp): what the help pages
// print, and what the one parser (Args, app/cli.hpp) needs to take it: its kind, range, choices and
// whether it repeats. Adding an option is one row plus the code that reads it.
#pragma once
#include <limits>
#include <utility>
#include <vector>

namespace nbscope {

enum class OptionKind {
  flag,     // `--name` alone (Args::flag)
  text,     // `--name VALUE` (Args::value; Args::values when repeatable)
  integer,  // a whole number in [min, max] ("1e6" is one too; Args::integer)
  number,   // a finite number in [low, high] (Args::number)
  choice,   // one of `choices` (Args::value)
};

// How an option's value is taken; the parser refuses anything else before the command runs.
struct OptionValue {
  OptionKind kind = OptionKind::text;
  long long min = 0, max = 0;                                // integer
  double low = -std::numeric_limits<double>::infinity();     // number
  double high = std::numeric_limits<double>::infinity();
  std::vector<const char*> choices = {};                     // choice
  // number out of [low, high], a choice not among `choices`: the error after "--name: " ("{}" is
  // the value given, quoted); nullptr: "'{}' is not a number from LOW to HIGH" / "'{}' is not one of A, B, C".
  const char* refusal = nullptr;
  bool repeatable = false;                                   // text: every value, in order
};

inline OptionValue flag_value() {
  OptionValue v;
  v.kind = OptionKind::flag;
  return v;
}
inline OptionValue integer_value(long long min, long long max) {
  OptionValue v;
  v.kind = OptionKind::integer;
  v.min = min;
  v.max = max;
  return v;
}
inline OptionValue number_value(double low = -std::numeric_limits<double>::infinity(),
                                double high = std::numeric_limits<double>::infinity(), const char* refusal = nullptr) {
  OptionValue v;
  v.kind = OptionKind::number;
  v.low = low;
  v.high = high;
  v.refusal = refusal;
  return v;
}
inline OptionValue choice_value(std::vector<const char*> choices, const char* refusal = nullptr) {
  OptionValue v;
  v.kind = OptionKind::choice;
  v.choices = std::move(choices);
  v.refusal = refusal;
  return v;
}
inline OptionValue repeated_value() {
  OptionValue v;
  v.repeatable = true;
  return v;
}

// One option of a command: `--name ARGUMENT`, what it does, its default ("" for none), its value.
struct OptionSpec {
  const char* name;           // "--frames"
  const char* argument;       // "N"; "" for a flag (then `value` is flag_value())
  const char* default_value;  // "600"; "" when there is none to name
  const char* help;           // one line (wrapped when printed)
  OptionValue value = {};     // text unless the row says otherwise
  // Taken only to be refused by the command with a reason (gui --contact-ids): on no help page and
  // in no "it is one of ..." list.
  bool hidden = false;
};

// Options under one heading of a command's page ("options", "rendering options (...)").
struct OptionGroup {
  const char* title;
  std::vector<OptionSpec> options;
};

}  // namespace nbscope

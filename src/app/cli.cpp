#include "app/cli.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "app/command_table.hpp"
#include "core/error.hpp"
#include "io/excerpt.hpp"

namespace nbscope {

std::size_t Args::untaken(const std::string& name, std::size_t from) const {
  for (std::size_t i = from; i < args_.size(); ++i)
    if (!used_[i] && (args_[i] == name || args_[i].rfind(name + "=", 0) == 0)) return i;
  return std::string::npos;
}

// A flag given twice is refused by name rather than left over as an "unknown flag".
void Args::refuse_repeat(const std::string& name) const {
  if (untaken(name) != std::string::npos) throw Error(name + ": given more than once");
}

std::string Args::take(const std::string& name, std::size_t i) {
  used_[i] = true;
  if (args_[i] != name) return args_[i].substr(name.size() + 1);  // --name=VALUE
  if (i + 1 >= args_.size()) throw Error(name + ": missing value");
  used_[i + 1] = true;
  return args_[i + 1];
}

std::optional<std::string> Args::value(const std::string& name) {
  const std::size_t i = untaken(name);
  if (i == std::string::npos) return std::nullopt;
  std::string v = take(name, i);
  refuse_repeat(name);
  return v;
}

std::vector<std::string> Args::values(const std::string& name) {
  std::vector<std::string> out;
  for (std::size_t i = untaken(name); i != std::string::npos; i = untaken(name, i + 1)) out.push_back(take(name, i));
  return out;
}

bool Args::has(const std::string& name) const { return untaken(name) != std::string::npos; }

std::optional<std::string> Args::peek(const std::string& name) const {
  const std::size_t i = untaken(name);
  if (i == std::string::npos) return std::nullopt;
  if (args_[i] != name) return args_[i].substr(name.size() + 1);
  return i + 1 < args_.size() ? std::optional<std::string>(args_[i + 1]) : std::nullopt;
}

void Args::set(const std::string& name, const std::string& value) {
  const std::size_t i = untaken(name);
  if (i != std::string::npos && args_[i] != name) {
    args_[i] = name + "=" + value;
  } else if (i != std::string::npos && i + 1 < args_.size()) {
    args_[i + 1] = value;
  } else {
    args_.push_back(name + "=" + value);  // one word: never mistaken for a positional argument
    used_.push_back(false);
  }
}

bool Args::flag(const std::string& name) {
  for (std::size_t i = 0; i < args_.size(); ++i) {
    if (!used_[i] && args_[i] == name) {
      used_[i] = true;
      refuse_repeat(name);
      return true;
    }
  }
  return false;
}

std::optional<long long> Args::integer(const std::string& name, long long min, long long max) {
  const auto v = value(name);
  if (!v) return std::nullopt;
  const auto refuse = [&] {
    return Error(name + ": '" + excerpt(*v) + "' is not a whole number from " + std::to_string(min) + " to " + std::to_string(max));
  };
  long long out = 0;
  const char* end = v->data() + v->size();
  const auto [ptr, ec] = std::from_chars(v->data(), end, out);
  if (!v->empty() && ec == std::errc() && ptr == end) {
    if (out < min || out > max) throw refuse();
    return out;
  }
  // Written with an exponent or a fraction ("1e6", "2.5e3"): a whole number still, when it is one.
  double d = 0;
  const auto [dptr, dec] = std::from_chars(v->data(), end, d);
  if (v->empty() || dec != std::errc() || dptr != end || !std::isfinite(d) || std::fabs(d) > 9e18 || d != std::floor(d) ||
      d < static_cast<double>(min) || d > static_cast<double>(max))
    throw refuse();
  return static_cast<long long>(d);
}

std::optional<double> Args::number(const std::string& name) {
  const auto v = value(name);
  if (!v) return std::nullopt;
  double out = 0;
  const auto [ptr, ec] = std::from_chars(v->data(), v->data() + v->size(), out);
  if (v->empty() || ec != std::errc() || ptr != v->data() + v->size() || !std::isfinite(out))
    throw Error(name + ": '" + *v + "' is not a finite number");
  return out;
}

std::optional<std::string> Args::positional() {
  refuse_unknown_options();
  for (std::size_t i = 0; i < args_.size(); ++i) {
    if (!used_[i] && args_[i].rfind("--", 0) != 0) {
      used_[i] = true;
      return args_[i];
    }
  }
  return std::nullopt;
}

void Args::refuse_unknown_options() const {
  for (std::size_t i = 0; i < args_.size(); ++i) {
    if (used_[i] || args_[i].size() < 2 || args_[i][0] != '-') continue;
    const std::string name = args_[i].substr(0, args_[i].find('='));  // --name=VALUE: the name alone
    if (command_.empty()) throw Error(name + ": unknown option (see nbscope --help)");
    const std::string others = commands_taking(name);
    // Taken by this command only in another mode (replay --gl with a window): not here.
    if ((", " + others + ", ").find(", " + command_ + ", ") != std::string::npos)
      throw Error(command_ + ": " + name + " does not apply here (see nbscope --help)");
    throw Error(command_ + ": " + name + " is not an option of " + command_ +
                (others.empty() ? " (see nbscope --help)" : " (it is one of " + others + ")"));
  }
}

void Args::finish() const {
  refuse_unknown_options();
  for (std::size_t i = 0; i < args_.size(); ++i)
    if (!used_[i]) throw Error(args_[i] + ": unexpected argument (see nbscope --help)");
}

// The command table's options (app/command_table.hpp) as names per command, built once from it.
const std::vector<std::pair<const char*, std::vector<const char*>>>& command_options() {
  static const std::vector<std::pair<const char*, std::vector<const char*>>> options = [] {
    std::vector<std::pair<const char*, std::vector<const char*>>> out;
    for (const CommandSpec& command : command_table()) {
      out.emplace_back(command.name, std::vector<const char*>{});
      for (const OptionGroup& g : command.groups)
        for (const OptionSpec& o : g.options) out.back().second.push_back(o.name);
    }
    return out;
  }();
  return options;
}

std::string commands_taking(const std::string& option) {
  std::string out;
  for (const auto& [command, options] : command_options())
    for (const char* o : options)
      if (option == o) out += (out.empty() ? "" : ", ") + std::string(command);
  return out;
}

void parse_size(const std::string& flag, const std::string& text, int& out_width, int& out_height) {
  const std::size_t x = text.find('x');
  int w = 0, h = 0;
  bool ok = x != std::string::npos;
  if (ok) {
    auto [p1, e1] = std::from_chars(text.data(), text.data() + x, w);
    auto [p2, e2] = std::from_chars(text.data() + x + 1, text.data() + text.size(), h);
    ok = e1 == std::errc() && e2 == std::errc() && p1 == text.data() + x && p2 == text.data() + text.size();
  }
  if (!ok || w < 16 || h < 16 || w > 8192 || h > 8192)
    throw Error(flag + ": '" + text + "' is not a size WxH with sides from 16 to 8192");
  out_width = w;
  out_height = h;
}

int parse_point(const std::string& flag, const std::string& text, double out[3]) {
  int count = 0;
  std::size_t start = 0;
  while (count < 4) {
    const std::size_t comma = text.find(',', start);
    const std::size_t end = comma == std::string::npos ? text.size() : comma;
    double v = 0;
    auto [p, ec] = std::from_chars(text.data() + start, text.data() + end, v);
    if (ec != std::errc() || p != text.data() + end || !std::isfinite(v) || count == 3)
      throw Error(flag + ": '" + text + "' is not X,Y or X,Y,Z");
    out[count++] = v;
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (count < 2) throw Error(flag + ": '" + text + "' is not X,Y or X,Y,Z");
  return count;
}

std::vector<std::string> split_names(const std::string& flag, const std::string& text) {
  std::vector<std::string> names;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const std::string name = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (name.empty()) throw Error(flag + ": empty name in '" + text + "'");
    if (std::find(names.begin(), names.end(), name) != names.end()) throw Error(flag + ": '" + name + "' named twice");
    names.push_back(name);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return names;
}

}  // namespace nbscope

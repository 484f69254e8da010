#include "app/cli.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "app/command_table.hpp"
#include "core/error.hpp"
#include "io/excerpt.hpp"

namespace nbscope {

namespace {

std::string with_value(const char* refusal, const std::string& value) {
  std::string out = refusal;
  const std::size_t at = out.find("{}");
  if (at != std::string::npos) out.replace(at, 2, "'" + excerpt(value) + "'");
  return out;
}

std::string number_text(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", v);
  return buffer;
}

// The error for `text` as the value of `o`, or "" when it is one.
std::string refusal_of(const OptionSpec& o, const std::string& text) {
  const OptionValue& v = o.value;
  const char* end = text.data() + text.size();
  switch (v.kind) {
    case OptionKind::integer: {
      long long out = 0;
      const auto [ptr, ec] = std::from_chars(text.data(), end, out);
      if (!text.empty() && ec == std::errc() && ptr == end) {
        if (out >= v.min && out <= v.max) return "";
      } else {
        // Written with an exponent or a fraction ("1e6", "2.5e3"): a whole number still, when it is one.
        double d = 0;
        const auto [dptr, dec] = std::from_chars(text.data(), end, d);
        if (!text.empty() && dec == std::errc() && dptr == end && std::isfinite(d) && std::fabs(d) <= 9e18 && d == std::floor(d) &&
            d >= static_cast<double>(v.min) && d <= static_cast<double>(v.max))
          return "";
      }
      return "'" + excerpt(text) + "' is not a whole number from " + std::to_string(v.min) + " to " + std::to_string(v.max);
    }
    case OptionKind::number: {
      double out = 0;
      const auto [ptr, ec] = std::from_chars(text.data(), end, out);
      if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(out)) return "'" + text + "' is not a finite number";
      if (out >= v.low && out <= v.high) return "";
      return v.refusal ? with_value(v.refusal, text)
                       : "'" + excerpt(text) + "' is not a number from " + number_text(v.low) + " to " + number_text(v.high);
    }
    case OptionKind::choice: {
      std::string listed;
      for (const char* c : v.choices) {
        if (text == c) return "";
        listed += (listed.empty() ? "" : ", ") + std::string(c);
      }
      return v.refusal ? with_value(v.refusal, text) : "'" + excerpt(text) + "' is not one of " + listed;
    }
    case OptionKind::flag:
    case OptionKind::text:
      break;
  }
  return "";
}

const char* kind_name(OptionKind kind) {
  switch (kind) {
    case OptionKind::flag: return "a flag";
    case OptionKind::text: return "a text option";
    case OptionKind::integer: return "an integer option";
    case OptionKind::number: return "a number option";
    case OptionKind::choice: return "a choice option";
  }
  return "?";
}

}  // namespace

Args::Args(std::vector<std::string> args, const CommandSpec& command) : command_(command.name) {
  for (const OptionGroup& g : command.groups) options_.insert(options_.end(), g.options.begin(), g.options.end());
  parse(args);
}

Args::Args(std::vector<std::string> args, std::string command, std::vector<OptionSpec> options)
    : command_(std::move(command)), options_(std::move(options)) {
  parse(args);
}

// Every argument in order: an option of the row takes its value (the next argument, or what follows
// "="); the first bad value, missing value or repeat is refused, then the first unknown option.
void Args::parse(const std::vector<std::string>& args) {
  given_.assign(options_.size(), Given{});
  std::string unknown;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() < 2 || a[0] != '-') {
      positionals_.push_back(a);
      continue;
    }
    const std::size_t equals = a.find('=');
    const std::string name = a.substr(0, equals);  // --name=VALUE: the name alone
    std::size_t k = 0;
    while (k < options_.size() && name != options_[k].name) ++k;
    if (k == options_.size()) {
      if (unknown.empty()) unknown = name;
      continue;
    }
    const OptionSpec& o = options_[k];
    Given& g = given_[k];
    std::string value;
    if (o.value.kind == OptionKind::flag) {
      if (equals != std::string::npos) throw Error(name + ": takes no value");
    } else if (equals != std::string::npos) {
      value = a.substr(equals + 1);
    } else if (i + 1 < args.size()) {
      value = args[++i];
    } else {
      throw Error(name + ": missing value");
    }
    if (!g.values.empty() && !o.value.repeatable) throw Error(name + ": given more than once");
    if (const std::string refusal = refusal_of(o, value); !refusal.empty()) throw Error(name + ": " + refusal);
    if (g.values.empty()) g.first = i;
    g.values.push_back(std::move(value));
  }
  if (unknown.empty()) return;
  if (command_.empty()) throw Error(unknown + ": unknown option (see nbscope --help)");
  const std::string others = commands_taking(unknown);
  throw Error(command_ + ": " + unknown + " is not an option of " + command_ +
              (others.empty() ? " (see nbscope --help)" : " (it is one of " + others + ")"));
}

std::size_t Args::index(const std::string& name) const {
  for (std::size_t k = 0; k < options_.size(); ++k)
    if (name == options_[k].name) return k;
  throw std::logic_error(command_ + ": reads " + name + ", which its command-table row does not list (add the row)");
}

Args::Given& Args::read(const std::string& name, OptionKind kind) {
  const std::size_t k = index(name);
  const OptionKind row = options_[k].value.kind;
  if (row != kind && !(kind == OptionKind::text && row == OptionKind::choice))
    throw std::logic_error(command_ + ": reads " + name + " as " + kind_name(kind) + ", but its row makes it " + kind_name(row));
  given_[k].read = true;
  return given_[k];
}

bool Args::flag(const std::string& name) { return !read(name, OptionKind::flag).values.empty(); }

std::optional<std::string> Args::value(const std::string& name) {
  const Given& g = read(name, OptionKind::text);
  if (options_[index(name)].value.repeatable) throw std::logic_error(command_ + ": reads the repeatable " + name + " as one value");
  return g.values.empty() ? std::nullopt : std::optional<std::string>(g.values.front());
}

std::vector<std::string> Args::values(const std::string& name) {
  const Given& g = read(name, OptionKind::text);
  if (!options_[index(name)].value.repeatable) throw std::logic_error(command_ + ": reads " + name + ", not repeatable, as a list");
  return g.values;
}

std::optional<long long> Args::integer(const std::string& name) {
  const Given& g = read(name, OptionKind::integer);
  if (g.values.empty()) return std::nullopt;
  const std::string& v = g.values.front();
  long long out = 0;
  const auto [ptr, ec] = std::from_chars(v.data(), v.data() + v.size(), out);
  if (ec == std::errc() && ptr == v.data() + v.size()) return out;
  double d = 0;
  std::from_chars(v.data(), v.data() + v.size(), d);
  return static_cast<long long>(d);  // a whole number written with an exponent: checked when parsed
}

std::optional<double> Args::number(const std::string& name) {
  const Given& g = read(name, OptionKind::number);
  if (g.values.empty()) return std::nullopt;
  double out = 0;
  std::from_chars(g.values.front().data(), g.values.front().data() + g.values.front().size(), out);
  return out;
}

bool Args::has(const std::string& name) const { return !given_[index(name)].values.empty(); }

bool Args::offers(const std::string& name) const {
  for (const OptionSpec& o : options_)
    if (name == o.name) return true;
  return false;
}

void Args::set(const std::string& name, const std::string& value) {
  const std::size_t k = index(name);
  if (options_[k].value.kind != OptionKind::text || options_[k].value.repeatable)
    throw std::logic_error(command_ + ": sets " + name + ", which is not one text value");
  given_[k].values = {value};
}

std::optional<std::string> Args::positional() {
  refuse_unread();
  if (next_positional_ == positionals_.size()) return std::nullopt;
  return positionals_[next_positional_++];
}

// The option given first (in the arguments' order) that no read took.
void Args::refuse_unread() const {
  const Given* first = nullptr;
  const OptionSpec* spec = nullptr;
  for (std::size_t k = 0; k < options_.size(); ++k) {
    const Given& g = given_[k];
    if (g.values.empty() || g.read || (first != nullptr && first->first < g.first)) continue;
    first = &g;
    spec = &options_[k];
  }
  if (spec == nullptr) return;
  const std::string name = spec->name;
  // Taken by this command only in another mode (replay --gl with a window): not here.
  if (!spec->hidden) throw Error(command_ + ": " + name + " does not apply here (see nbscope --help)");
  const std::string others = commands_taking(name);
  throw Error(command_ + ": " + name + " is not an option of " + command_ +
              (others.empty() ? " (see nbscope --help)" : " (it is one of " + others + ")"));
}

void Args::finish() const {
  refuse_unread();
  if (next_positional_ < positionals_.size())
    throw Error(positionals_[next_positional_] + ": unexpected argument (see nbscope --help)");
}

std::string commands_taking(const std::string& option) {
  std::string out;
  for (const CommandSpec& command : command_table())
    for (const OptionGroup& g : command.groups)
      for (const OptionSpec& o : g.options)
        if (option == o.name && !o.hidden) out += (out.empty() ? "" : ", ") + std::string(command.name);
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

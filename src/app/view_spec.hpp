// nbscope app: the --overlays and --panels specs ("all,-lists", "+metrics", "grid,ids"), applied to
// a set of named switches; shared by the main view (gl_view.cpp) and the verify view.
#pragma once
#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "render/overlays.hpp"

namespace nbscope {

// `s` in lower case (ASCII).
inline std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// A spec is a comma list: "all", "none", "name" (from none: only the names listed), "+name", "-name".
// Calls set_all(on) and set(name, on) in order; Error naming `flag` for a name not in `names`.
template <class SetAll, class Set>
void apply_spec(const std::string& flag, const std::string& spec, const std::vector<std::string>& names,
                SetAll set_all, Set set) {
  if (spec.empty()) return;
  bool first = true;
  std::size_t start = 0;
  while (start <= spec.size()) {
    const std::size_t comma = std::min(spec.find(',', start), spec.size());
    std::string token = lower(spec.substr(start, comma - start));
    start = comma + 1;
    if (token.empty()) continue;
    if (token == "all" || token == "none") {
      set_all(token == "all");
    } else {
      bool on = true;
      if (token[0] == '+' || token[0] == '-') {
        on = token[0] == '+';
        token.erase(0, 1);
      } else if (first) {
        set_all(false);
      }
      if (std::find(names.begin(), names.end(), token) == names.end()) {
        std::string known;
        for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
        throw Error(flag + ": '" + token + "' is not one of all, none, " + known);
      }
      set(token, on);
    }
    first = false;
  }
}

// `--overlays SPEC` applied to `flags` (the names of render::overlay_infos()).
inline void apply_overlay_spec(const std::string& spec, render::OverlayFlags& flags) {
  std::vector<std::string> names;
  for (const auto& o : render::overlay_infos()) names.emplace_back(o.name);
  apply_spec(
      "--overlays", spec, names,
      [&](bool on) {
        for (const auto& o : render::overlay_infos()) flags.*o.flag = on;
      },
      [&](const std::string& name, bool on) {
        for (const auto& o : render::overlay_infos())
          if (name == o.name) render::set_overlay(flags, o.flag, on);
      });
}

}  // namespace nbscope

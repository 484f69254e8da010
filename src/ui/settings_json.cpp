#include "ui/settings_json.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "io/excerpt.hpp"
#include "io/json_limits.hpp"

namespace nbscope::ui {

namespace {

using Json = nlohmann::json;

// Far more than a settings file holds (a few dozen values), few enough to parse in microseconds.
constexpr std::size_t kMaxSettingsValues = 10'000;

// `key VALUE (why)`, the value cut short and on one line.
std::string phrase(const std::string& key, const Json& value, const char* why) {
  return key + " " + excerpt(value.dump(-1, ' ', false, Json::error_handler_t::replace)) + " (" + why + ")";
}

std::optional<double> finite_number(const Json& v) {
  if (!v.is_number()) return std::nullopt;
  const double d = v.get<double>();
  return std::isfinite(d) ? std::optional<double>(d) : std::nullopt;
}

// An object of true/false entries: the good ones into `out` (only `known` names, when given).
void read_switches(const Json& j, const char* key, std::span<const std::string_view> known, bool check_names,
                   std::map<std::string, bool>& out, std::vector<std::string>& ignored) {
  const auto it = j.find(key);
  if (it == j.end()) return;
  if (!it->is_object()) {
    ignored.push_back(phrase(key, *it, "not an object"));
    return;
  }
  for (const auto& [name, on] : it->items()) {
    const std::string where = std::string(key) + "." + excerpt(name);
    if (check_names && std::find(known.begin(), known.end(), name) == known.end()) {
      ignored.push_back(where + " (no such overlay)");
    } else if (!on.is_boolean()) {
      ignored.push_back(phrase(where, on, "not true or false"));
    } else {
      out[name] = on.get<bool>();
    }
  }
}

}  // namespace

SettingsValues parse_settings_json(std::string_view text, std::span<const std::string_view> overlay_names,
                                   std::vector<std::string>& ignored) {
  if (text.size() > kMaxSettingsBytes) throw Error("larger than " + std::to_string(kMaxSettingsBytes >> 20) + " MB");
  try {
    check_json_limits(text, "", "settings file", kMaxSettingsValues);
  } catch (const Error& e) {
    throw Error("line " + std::string(e.what()).substr(1));  // ":3: nesting ..." -> "line 3: nesting ..."
  }
  Json j;
  try {
    j = Json::parse(text);
  } catch (const Json::exception& e) {
    throw Error("not JSON: " + json_error_text(e.what()));
  }
  if (!j.is_object()) throw Error("not a JSON object");
  const auto version = j.find("version");
  if (version == j.end()) throw Error("no \"version\"");
  if (!(version->is_number_integer() && version->get<std::int64_t>() == kSettingsVersion))
    throw Error(phrase("version", *version, ("this nbscope reads version " + std::to_string(kSettingsVersion)).c_str()));

  SettingsValues out;
  read_switches(j, "overlays", overlay_names, true, out.overlays, ignored);
  read_switches(j, "panels", {}, false, out.panels, ignored);
  const auto text_of = [&](const char* key, std::optional<std::string>& into) {
    const auto it = j.find(key);
    if (it == j.end()) return;
    if (it->is_string() && !it->get_ref<const std::string&>().empty()) into = it->get<std::string>();
    else ignored.push_back(phrase(key, *it, "not a file name"));
  };
  text_of("last_scene", out.last_scene);
  if (const auto it = j.find("algorithm"); it != j.end()) {
    if (it->is_string() && !it->get_ref<const std::string&>().empty()) out.algorithm = it->get<std::string>();
    else ignored.push_back(phrase("algorithm", *it, "not a name"));
  }
  if (const auto it = j.find("detector_libs"); it != j.end()) {
    const bool good = it->is_array() && std::all_of(it->begin(), it->end(), [](const Json& p) {
      return p.is_string() && !p.get_ref<const std::string&>().empty();
    });
    if (good) out.detector_libs = it->get<std::vector<std::string>>();
    else ignored.push_back(phrase("detector_libs", *it, "not a list of file names"));
  }
  if (const auto it = j.find("camera"); it != j.end()) {
    bool good = it->is_array() && it->size() == 3;
    std::array<double, 3> c{};
    for (std::size_t k = 0; good && k < 3; ++k) {
      const auto v = finite_number((*it)[k]);
      good = v.has_value();
      if (good) c[k] = *v;
    }
    if (good && c[2] > 0) out.camera = c;
    else ignored.push_back(phrase("camera", *it, "not [x, y, pixels per metre > 0]"));
  }
  if (const auto it = j.find("speed"); it != j.end()) {
    const auto v = finite_number(*it);
    if (v && *v > 0.0 && *v <= 100.0) out.speed = *v;
    else ignored.push_back(phrase("speed", *it, "not a number in (0, 100]"));
  }
  if (const auto it = j.find("history_mb"); it != j.end()) {
    const bool whole = it->is_number_unsigned() || it->is_number_integer();
    const std::int64_t mb = whole && !(it->is_number_unsigned() && it->get<std::uint64_t>() > 1'000'000) ? it->get<std::int64_t>() : -1;
    if (whole && mb >= 0 && mb <= 1'000'000) out.history_mb = mb;
    else ignored.push_back(phrase("history_mb", *it, "not a whole number of MB in 0..1,000,000"));
  }
  if (const auto it = j.find("side_view_yz"); it != j.end()) {
    if (it->is_boolean()) out.side_view_yz = it->get<bool>();
    else ignored.push_back(phrase("side_view_yz", *it, "not true or false"));
  }
  if (const auto it = j.find("window_size"); it != j.end()) {
    bool good = it->is_array() && it->size() == 2;
    std::array<int, 2> size{};
    for (std::size_t k = 0; good && k < 2; ++k) {
      const auto& v = (*it)[k];
      good = (v.is_number_unsigned() || v.is_number_integer()) && v.get<std::int64_t>() >= kMinWindowSide && v.get<std::int64_t>() <= 100000;
      if (good) size[k] = static_cast<int>(v.get<std::int64_t>());
    }
    if (good) out.window_size = size;
    else ignored.push_back(phrase("window_size", *it, "not [width, height] in pixels, each 320..100,000"));
  }
  return out;
}

std::string settings_json_text(const SettingsValues& values) {
  Json j;
  j["version"] = kSettingsVersion;
  j["overlays"] = values.overlays;
  j["panels"] = values.panels;
  if (values.last_scene) j["last_scene"] = *values.last_scene;
  if (values.algorithm) j["algorithm"] = *values.algorithm;
  if (!values.detector_libs.empty()) j["detector_libs"] = values.detector_libs;
  if (values.camera) j["camera"] = *values.camera;
  j["speed"] = values.speed;
  j["history_mb"] = values.history_mb;
  j["side_view_yz"] = values.side_view_yz;
  if (values.window_size) j["window_size"] = *values.window_size;
  return j.dump(2);
}

}  // namespace nbscope::ui

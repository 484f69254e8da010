#include "ui/settings.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace nbscope::ui {

namespace {
constexpr int kVersion = 1;
}

std::string settings_path() {
  const char* xdg = std::getenv("XDG_CONFIG_HOME");
  if (xdg != nullptr && *xdg == '/') return std::string(xdg) + "/nbscope/settings.json";
  const char* home = std::getenv("HOME");
  if (home != nullptr && *home != '\0') return std::string(home) + "/.config/nbscope/settings.json";
  return "";
}

Settings load_settings(const std::string& path, std::string& warning) {
  Settings s;
  warning.clear();
  if (path.empty() || !std::filesystem::exists(path)) return s;
  try {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read the file");
    std::stringstream text;
    text << in.rdbuf();
    const nlohmann::json j = nlohmann::json::parse(text.str());
    if (!j.is_object()) throw std::runtime_error("not a JSON object");
    if (j.value("version", 0) != kVersion) throw std::runtime_error("unknown version");
    Settings out;
    if (j.contains("overlays")) {
      for (const render::OverlayInfo& o : render::overlay_infos())
        if (j["overlays"].contains(o.name)) out.overlays.*o.flag = j["overlays"][o.name].get<bool>();
    }
    if (j.contains("panels")) out.panels = j["panels"].get<std::map<std::string, bool>>();
    if (j.contains("last_scene")) out.last_scene = j["last_scene"].get<std::string>();
    if (j.contains("algorithm")) out.algorithm = j["algorithm"].get<std::string>();
    if (j.contains("camera")) {
      const auto c = j["camera"].get<std::array<double, 3>>();
      if (std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]) && c[2] > 0) out.camera = c;
    }
    out.speed = j.value("speed", 1.0);
    if (!(out.speed > 0.0 && out.speed <= 100.0)) out.speed = 1.0;
    const std::int64_t mb = j.contains("history_mb") && j["history_mb"].is_number_integer() ? j["history_mb"].get<std::int64_t>() : 256;
    out.history_mb = mb >= 0 && mb <= 1'000'000 ? mb : 256;
    return out;
  } catch (const std::exception& e) {
    warning = path + ": " + e.what() + " (settings ignored)";
    return s;
  }
}

std::optional<std::array<double, 3>> camera_to_save(const render::Camera& camera) {
  if (camera.at_home()) return std::nullopt;
  return std::array<double, 3>{camera.centre().x(), camera.centre().y(), camera.pixels_per_metre()};
}

bool restore_camera(const Settings& s, const std::string& scene, render::Camera& camera) {
  if (!s.camera || !s.last_scene || *s.last_scene != scene) return false;
  camera.set({(*s.camera)[0], (*s.camera)[1]}, (*s.camera)[2]);
  return true;
}

void save_settings(const std::string& path, const Settings& s) {
  if (path.empty()) throw Error("settings: no config directory (neither XDG_CONFIG_HOME nor HOME is set)");
  nlohmann::json j;
  j["version"] = kVersion;
  for (const render::OverlayInfo& o : render::overlay_infos()) j["overlays"][o.name] = s.overlays.*o.flag;
  j["panels"] = s.panels;
  if (s.last_scene) j["last_scene"] = *s.last_scene;
  if (s.algorithm) j["algorithm"] = *s.algorithm;
  if (s.camera) j["camera"] = *s.camera;
  j["speed"] = s.speed;
  j["history_mb"] = s.history_mb;
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  if (ec) throw Error(path + ": cannot write: " + ec.message());
  write_file_atomically(path, [&](std::ostream& out) { out << j.dump(2) << "\n"; });
}

}  // namespace nbscope::ui

#include "ui/settings.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "core/detector.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/excerpt.hpp"
#include "io/input_file.hpp"
#include "ui/settings_json.hpp"

namespace nbscope::ui {

std::string settings_path() {
  const char* xdg = std::getenv("XDG_CONFIG_HOME");
  if (xdg != nullptr && *xdg == '/') return std::string(xdg) + "/nbscope/settings.json";
  const char* home = std::getenv("HOME");
  if (home != nullptr && *home != '\0') return std::string(home) + "/.config/nbscope/settings.json";
  return "";
}

Settings load_settings(const std::string& path, std::vector<std::string>& ignored,
                       const std::function<void(const std::string&)>& load_library) {
  Settings s;
  ignored.clear();
  std::error_code ec;
  if (path.empty() || !std::filesystem::exists(path, ec)) return s;
  std::vector<std::string_view> overlay_names;
  for (const render::OverlayInfo& o : render::overlay_infos()) overlay_names.emplace_back(o.name);
  SettingsValues v;
  try {
    v = parse_settings_json(read_input_file(path, "settings file", kMaxSettingsBytes), overlay_names, ignored);
  } catch (const Error& e) {
    // read_input_file's messages start with the path the note names anyway.
    std::string why = e.what();
    if (why.rfind(path + ": ", 0) == 0) why.erase(0, path.size() + 2);
    ignored.assign(1, "the whole file (" + why + ")");
    return s;
  }
  for (const render::OverlayInfo& o : render::overlay_infos())
    if (const auto it = v.overlays.find(o.name); it != v.overlays.end()) s.overlays.*o.flag = it->second;
  s.panels = std::move(v.panels);
  s.last_scene = std::move(v.last_scene);
  for (std::string& library : v.detector_libs) {
    try {
      if (load_library) load_library(library);
      s.detector_libs.push_back(std::move(library));
    } catch (const Error& e) {
      ignored.push_back("detector_libs \"" + excerpt(library) + "\" (" + e.what() + ")");
    }
  }
  if (v.algorithm) {
    // Registered at start-up (box2d too) before any window: the names this nbscope has now.
    const auto& infos = detector_infos();
    const auto known = std::find_if(infos.begin(), infos.end(), [&](const DetectorInfo& d) { return d.name == *v.algorithm; });
    if (known != infos.end() && known->dim2) s.algorithm = std::move(v.algorithm);
    else ignored.push_back("algorithm \"" + excerpt(*v.algorithm) + "\" (not one of " + detector_names() + ")");
  }
  s.camera = v.camera;
  s.speed = v.speed;
  s.history_mb = v.history_mb;
  s.side_view_yz = v.side_view_yz;
  s.window_size = v.window_size;
  return s;
}

std::string settings_note(const std::string& path, const std::vector<std::string>& ignored) {
  if (ignored.empty()) return "";
  std::string line = path + ": ignored ";
  for (std::size_t k = 0; k < ignored.size(); ++k) line += (k > 0 ? ", " : "") + ignored[k];
  return line + (ignored.size() == 1 && ignored[0].rfind("the whole file", 0) == 0 ? "; the defaults are used" : "; the rest is used");
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

std::array<int, 2> opening_window_size(const std::optional<std::array<int, 2>>& saved, const std::optional<std::array<int, 2>>& work_area) {
  if (!work_area || (*work_area)[0] < kMinWindowSide || (*work_area)[1] < kMinWindowSide) return saved.value_or(kFallbackWindowSize);
  if (!saved) return *work_area;
  return {std::min((*saved)[0], (*work_area)[0]), std::min((*saved)[1], (*work_area)[1])};
}

void save_settings(const std::string& path, const Settings& s) {
  if (path.empty()) throw Error("settings: no config directory (neither XDG_CONFIG_HOME nor HOME is set)");
  SettingsValues values{{}, s.panels, s.last_scene, s.algorithm, s.detector_libs, s.camera, s.speed, s.history_mb,
                        s.side_view_yz, s.window_size};
  for (const render::OverlayInfo& o : render::overlay_infos()) values.overlays[o.name] = s.overlays.*o.flag;
  const std::string text = settings_json_text(values);
  std::error_code ec;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
  if (ec) throw Error(path + ": cannot write: " + ec.message());
  write_file_atomically(path, [&](std::ostream& out) { out << text << "\n"; });
}

}  // namespace nbscope::ui

// nbscope ui: the settings file — overlays, open panels, camera, last scene and algorithm — kept as
// a small JSON file in the user's config directory, so the window reopens as it was left.
#pragma once
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "render/camera.hpp"
#include "render/overlays.hpp"

namespace nbscope::ui {

struct Settings {
  render::OverlayFlags overlays;
  std::map<std::string, bool> panels;
  std::optional<std::string> last_scene;
  std::optional<std::string> algorithm;
  // Detector plugin libraries (--detector-lib) the window had loaded, absolute paths: loaded again at the
  // next start before the algorithm is looked up, so a plugin chosen last time is chosen again.
  std::vector<std::string> detector_libs;
  // Centre x, y and pixels per metre, for last_scene: only a camera the user panned or zoomed (a
  // fitted one is fitted again at the next start, into the panels that start opens).
  std::optional<std::array<double, 3>> camera;
  double speed = 1.0;
  std::int64_t history_mb = 256;  // the Timeline's memory budget for kept frames
  bool side_view_yz = false;      // the Layers panel's side view shows y-z (UiState::side_view_yz)
  std::optional<std::array<int, 2>> window_size;  // the window's size when it last closed
};

// The size a window opens at without --size when nothing better is known (no monitor, a tiny one).
inline constexpr std::array<int, 2> kFallbackWindowSize{1280, 720};
// The size an interactive window opens at without --size: the size it was closed at (`saved`), made
// no larger than the monitor's work area; else the work area; else the saved size or
// kFallbackWindowSize when the work area is unknown or under 320 px a side.
std::array<int, 2> opening_window_size(const std::optional<std::array<int, 2>>& saved, const std::optional<std::array<int, 2>>& work_area);

// $XDG_CONFIG_HOME/nbscope/settings.json, else $HOME/.config/nbscope/settings.json, else "".
std::string settings_path();
// Reads `path` (ui/settings_json.hpp). A missing file gives the defaults. A stale or broken one must
// not keep the window from opening: what cannot be used keeps its default and is named in `ignored`
// — the whole file (unreadable, not JSON, another version) or single keys (a wrong type, a value out
// of range, an algorithm this nbscope does not have, e.g. "bogus").
// `load_library` (when given) loads one saved detector library before the algorithm is looked up; an
// Error it throws (the file is gone, another plugin API) drops that library with its reason in `ignored`.
Settings load_settings(const std::string& path, std::vector<std::string>& ignored,
                       const std::function<void(const std::string&)>& load_library = {});
// The one line that says so: "<path>: ignored <what>, <what>; the rest is used" ("" when nothing was).
std::string settings_note(const std::string& path, const std::vector<std::string>& ignored);
// The camera to save: none while it is where the last fit (or Home) put it, so that the next start
// fits the scene and keeps refitting it as panels open and close; else its centre and scale.
std::optional<std::array<double, 3>> camera_to_save(const render::Camera& camera);
// Puts the saved camera back when it was saved for `scene` (absolute path), after the start's fit;
// true when it did. A restored camera is the user's: the view stays there until Home.
bool restore_camera(const Settings& s, const std::string& scene, render::Camera& camera);
// Writes `s` to `path` atomically, creating its directory; Error("<path>: cannot write: ...").
void save_settings(const std::string& path, const Settings& s);

}  // namespace nbscope::ui

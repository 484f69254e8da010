// nbscope ui: the settings file's text to plain values, key by key. No GL, no ImGui, no file: the
// window's settings (ui/settings.hpp) are built from it, and fuzz/fuzz_settings.cpp compiles it alone.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace nbscope::ui {

inline constexpr int kSettingsVersion = 1;
// A settings file is a few hundred bytes; anything past this is not one (read no further).
inline constexpr std::size_t kMaxSettingsBytes = std::size_t{1} << 20;

// What a settings file holds, each value already checked (a missing or wrong key keeps the default).
struct SettingsValues {
  std::map<std::string, bool> overlays;  // only names of `overlay_names`
  std::map<std::string, bool> panels;    // panel title -> open
  std::optional<std::string> last_scene;
  std::optional<std::string> algorithm;  // a non-empty string; whether nbscope has it is the caller's check
  std::vector<std::string> detector_libs;  // plugin libraries (--detector-lib), non-empty paths; loading them is the caller's
  std::optional<std::array<double, 3>> camera;  // finite centre x, y and pixels per metre > 0
  double speed = 1.0;                           // in (0, 100]
  std::int64_t history_mb = 256;                // in [0, 1,000,000]
  bool side_view_yz = false;                    // the Layers panel's side view shows y-z (else x-z)
  std::optional<std::array<int, 2>> window_size;  // the window's size when it closed, each side in [kMinWindowSide, 100000]
};

// The smallest side of a window worth opening (a saved or work-area size is never made smaller).
inline constexpr int kMinWindowSide = 320;

// Parses `text`. Error (its what() a short phrase, no path) when the whole file is unusable: not
// JSON, not an object, another "version", past kMaxSettingsBytes or the JSON limits. Otherwise each
// key that has the wrong type or an out-of-range value keeps its default and adds one phrase to
// `ignored` (`speed "fast" (not a number in (0, 100])`); unknown keys are left alone (a newer nbscope's).
SettingsValues parse_settings_json(std::string_view text, std::span<const std::string_view> overlay_names,
                                   std::vector<std::string>& ignored);

// The file's text for `values`, as the window writes it (parse_settings_json reads it back whole).
std::string settings_json_text(const SettingsValues& values);

}  // namespace nbscope::ui

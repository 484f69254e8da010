// Fuzz target: the settings file's reader (ui/settings_json.hpp) on arbitrary bytes. It refuses a
// whole file only with nbscope::Error; what it keeps must be in range (speed, history budget,
// camera, overlay names), and written back by the window's own writer (settings_json_text) and
// read again it must give the same values with nothing ignored.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "fuzz_check.hpp"
#include "ui/settings_json.hpp"

namespace {

// The overlay names of render/overlays.cpp (that file needs the renderer; the reader takes names).
constexpr std::string_view kOverlays[] = {"bodies", "pairs", "grid", "lists", "ids"};


}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  nbscope::ui::SettingsValues v;
  std::vector<std::string> ignored;
  try {
    v = nbscope::ui::parse_settings_json(text, kOverlays, ignored);
    if (nbscope::fuzz::planted_fault() == "foreign-exception") throw std::logic_error("planted");
  } catch (const nbscope::Error&) {
    return 0;  // the whole file refused: the window uses the defaults
  }
  if (nbscope::fuzz::planted_fault() == "bad-row") v.speed = -v.speed;
  FUZZ_CHECK(v.speed > 0 && v.speed <= 100, "settings: speed " + std::to_string(v.speed));
  FUZZ_CHECK(v.history_mb >= 0 && v.history_mb <= 1'000'000, "settings: history_mb " + std::to_string(v.history_mb));
  if (v.camera) FUZZ_CHECK((*v.camera)[2] > 0 && std::isfinite((*v.camera)[0]) && std::isfinite((*v.camera)[1]), "settings: camera");
  for (const auto& [name, on] : v.overlays) {
    bool known = false;
    for (const std::string_view k : kOverlays) known = known || k == name;
    FUZZ_CHECK(known, "settings: kept an unknown overlay " + name);
  }
  FUZZ_CHECK(!v.algorithm || !v.algorithm->empty(), "settings: an empty algorithm kept");
  FUZZ_CHECK(!v.last_scene || !v.last_scene->empty(), "settings: an empty last_scene kept");
  for (const std::string& phrase : ignored) FUZZ_CHECK(phrase.find('\n') == std::string::npos, "settings: a note phrase of two lines");

  // Written back and read again: the same values, nothing ignored.
  std::vector<std::string> again_ignored;
  nbscope::ui::SettingsValues again;
  try {
    again = nbscope::ui::parse_settings_json(nbscope::ui::settings_json_text(v), kOverlays, again_ignored);
  } catch (const nbscope::Error& e) {
    nbscope::fuzz::fuzz_fail(std::string("settings: its own values refused: ") + e.what());
  }
  FUZZ_CHECK(again_ignored.empty(), "settings: its own values partly ignored: " + again_ignored.front());
  FUZZ_CHECK(again.overlays == v.overlays && again.panels == v.panels && again.last_scene == v.last_scene &&
                 again.algorithm == v.algorithm && again.camera == v.camera && again.speed == v.speed && again.history_mb == v.history_mb,
             "settings: values changed when written and read again");
  return 0;
}

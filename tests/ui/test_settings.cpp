// The settings file's reader key by key (ui/settings_json.hpp, ui/settings.hpp): a stale or broken
// value keeps its default and is named once; only an unusable file is ignored whole; the note is
// one line naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/detector.hpp"
#include "core/error.hpp"
#include "render/overlays.hpp"
#include "ui/settings.hpp"
#include "ui/settings_json.hpp"

namespace nbscope::ui {
namespace {

constexpr std::string_view kOverlays[] = {"bodies", "grid", "ids"};

SettingsValues parse(const std::string& text, std::vector<std::string>& ignored) { return parse_settings_json(text, kOverlays, ignored); }

bool mentions(const std::vector<std::string>& ignored, const std::string& phrase) {
  for (const std::string& p : ignored)
    if (p.find(phrase) != std::string::npos) return true;
  return false;
}

TEST(SettingsJson, GoodValuesAreKeptWithNothingIgnored) {
  std::vector<std::string> ignored;
  const SettingsValues v = parse(R"({"version": 1, "overlays": {"grid": false, "ids": true}, "panels": {"Metrics": true},
    "last_scene": "/s.json", "algorithm": "screen", "camera": [1, -2, 30], "speed": 100, "history_mb": 0})",
                                 ignored);
  EXPECT_TRUE(ignored.empty()) << ignored.front();
  EXPECT_EQ(v.overlays, (std::map<std::string, bool>{{"grid", false}, {"ids", true}}));
  EXPECT_EQ(v.panels.at("Metrics"), true);
  EXPECT_EQ(v.last_scene, "/s.json");
  EXPECT_EQ(v.algorithm, "screen");
  EXPECT_EQ(v.camera, (std::array<double, 3>{1, -2, 30}));
  EXPECT_EQ(v.speed, 100);
  EXPECT_EQ(v.history_mb, 0);
}

TEST(SettingsJson, EachWrongKeyKeepsItsDefaultAndIsNamed) {
  std::vector<std::string> ignored;
  const SettingsValues v = parse(R"({"version": 1, "overlays": {"grid": 1, "sparkles": true, "ids": true}, "panels": [],
    "last_scene": 7, "algorithm": "", "camera": [0, 0, 0], "speed": "fast", "history_mb": 2.5, "future_key": {}})",
                                 ignored);
  EXPECT_EQ(v.overlays, (std::map<std::string, bool>{{"ids", true}}));  // the good entry stays
  EXPECT_TRUE(v.panels.empty());
  EXPECT_FALSE(v.last_scene);
  EXPECT_FALSE(v.algorithm);
  EXPECT_FALSE(v.camera);
  EXPECT_EQ(v.speed, 1.0);
  EXPECT_EQ(v.history_mb, 256);
  EXPECT_EQ(ignored.size(), 8u);
  for (const char* phrase : {"overlays.grid 1 (not true or false)", "overlays.sparkles (no such overlay)", "panels [] (not an object)",
                             "last_scene 7 (", "algorithm \"\" (", "camera [0,0,0] (", "speed \"fast\" (not a number in (0, 100])",
                             "history_mb 2.5 ("})
    EXPECT_TRUE(mentions(ignored, phrase)) << phrase;
  EXPECT_FALSE(mentions(ignored, "future_key"));  // a newer nbscope's key is left alone
}

TEST(SettingsJson, RangesAreHeld) {
  std::vector<std::string> ignored;
  EXPECT_EQ(parse(R"({"version": 1, "speed": 0})", ignored).speed, 1.0);
  EXPECT_EQ(parse(R"({"version": 1, "speed": 1e308})", ignored).speed, 1.0);
  EXPECT_EQ(parse(R"({"version": 1, "history_mb": -1})", ignored).history_mb, 256);
  EXPECT_EQ(parse(R"({"version": 1, "history_mb": 18446744073709551615})", ignored).history_mb, 256);
  EXPECT_FALSE(parse(R"({"version": 1, "camera": [1, 2]})", ignored).camera);
  EXPECT_FALSE(parse(R"({"version": 1, "camera": [1, 2, -3]})", ignored).camera);
}

TEST(SettingsJson, AnUnusableFileIsRefusedWhole) {
  std::vector<std::string> ignored;
  const auto refusal = [&](const std::string& text) {
    try {
      parse(text, ignored);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal("{ not json").rfind("not JSON: ", 0), 0u);
  EXPECT_EQ(refusal("[1, 2]"), "not a JSON object");
  EXPECT_EQ(refusal("{}"), "no \"version\"");
  EXPECT_EQ(refusal(R"({"version": 2})"), "version 2 (this nbscope reads version 1)");
  EXPECT_EQ(refusal(std::string(100, '[') + std::string(100, ']')).rfind("line 1: ", 0), 0u);
  EXPECT_EQ(refusal("{\"version\": 1, \"x\": \"" + std::string(kMaxSettingsBytes, 'a') + "\"}"), "larger than 1 MB");
}

TEST(Settings, AnUnknownAlgorithmIsIgnoredAndTheNoteNamesTheFile) {
  const std::string dir = std::string(NBSCOPE_TEST_OUT) + "/settings_unknown_algorithm";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/settings.json";
  std::ofstream(path) << R"({"version": 1, "algorithm": "bogus", "speed": 3, "overlays": {"ids": true}})";
  std::vector<std::string> ignored;
  const Settings s = load_settings(path, ignored);
  EXPECT_FALSE(s.algorithm);
  EXPECT_EQ(s.speed, 3);
  EXPECT_TRUE(s.overlays.ids);
  ASSERT_EQ(ignored.size(), 1u);
  EXPECT_EQ(ignored[0].rfind("algorithm \"bogus\" (not one of ", 0), 0u) << ignored[0];
  EXPECT_NE(ignored[0].find("nbs"), std::string::npos);
  EXPECT_EQ(settings_note(path, ignored), path + ": ignored " + ignored[0] + "; the rest is used");
  EXPECT_EQ(settings_note(path, {}), "");

  std::ofstream(path) << R"({"version": 1, "algorithm": "tree"})";
  EXPECT_EQ(load_settings(path, ignored).algorithm, "tree");
  EXPECT_TRUE(ignored.empty());
}

TEST(SettingsJson, DetectorLibrariesRoundTripAndAWrongListIsNamed) {
  std::vector<std::string> ignored;
  SettingsValues v = parse(R"({"version": 1, "detector_libs": ["/a/nbs_mine.so", "/b/tree.so"]})", ignored);
  EXPECT_TRUE(ignored.empty());
  EXPECT_EQ(v.detector_libs, (std::vector<std::string>{"/a/nbs_mine.so", "/b/tree.so"}));
  EXPECT_EQ(parse(settings_json_text(v), ignored).detector_libs, v.detector_libs);
  for (const char* bad : {R"({"version": 1, "detector_libs": "/a.so"})", R"({"version": 1, "detector_libs": ["/a.so", 3]})",
                          R"({"version": 1, "detector_libs": [""]})"}) {
    ignored.clear();
    v = parse(bad, ignored);
    EXPECT_TRUE(v.detector_libs.empty()) << bad;
    ASSERT_EQ(ignored.size(), 1u) << bad;
    EXPECT_TRUE(mentions(ignored, "(not a list of file names)")) << ignored[0];
  }
}

// A plugin chosen last time is chosen again: its library is loaded before the algorithm is looked up,
// and a library that no longer loads is dropped with its reason while the rest is used.
TEST(Settings, SavedDetectorLibrariesAreLoadedBeforeTheAlgorithmIsLookedUp) {
  const std::string dir = std::string(NBSCOPE_TEST_OUT) + "/settings_detector_libs";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/settings.json";
  std::ofstream(path) << R"({"version": 1, "algorithm": "settings_plugin", "detector_libs": ["/gone.so", "/here.so"]})";
  std::vector<std::string> loaded;
  const auto load = [&](const std::string& library) {
    if (library == "/gone.so") throw Error("/gone.so: cannot open shared object file");
    loaded.push_back(library);
    register_detector(DetectorInfo{.name = "settings_plugin", .summary = "a plugin the settings test registers", .library = library,
                                   .make = [] { return make_detector("brute"); }});
  };
  std::vector<std::string> ignored;
  Settings s = load_settings(path, ignored, load);
  EXPECT_EQ(loaded, (std::vector<std::string>{"/here.so"}));
  EXPECT_EQ(s.detector_libs, (std::vector<std::string>{"/here.so"}));
  EXPECT_EQ(s.algorithm, "settings_plugin");  // found: the library was loaded first
  ASSERT_EQ(ignored.size(), 1u);
  EXPECT_EQ(ignored[0], "detector_libs \"/gone.so\" (/gone.so: cannot open shared object file)");

  save_settings(path, s);
  s = load_settings(path, ignored);  // no loader: the names are kept as they are
  EXPECT_EQ(s.detector_libs, (std::vector<std::string>{"/here.so"}));
}

// The window's size when it closed is kept; a size it could not open at is named and ignored.
TEST(SettingsJson, TheWindowSizeRoundTripsAndABadOneIsNamed) {
  std::vector<std::string> ignored;
  SettingsValues v;
  v.window_size = std::array<int, 2>{1500, 930};
  EXPECT_EQ(parse(settings_json_text(v), ignored).window_size, v.window_size);
  EXPECT_TRUE(ignored.empty());
  for (const char* bad : {R"([100, 900])", R"([1500])", R"("big")", R"([1500.5, 900])", R"([-1, 900])"}) {
    ignored.clear();
    EXPECT_FALSE(parse(std::string(R"({"version": 1, "window_size": )") + bad + "}", ignored).window_size) << bad;
    EXPECT_TRUE(mentions(ignored, "window_size")) << bad;
  }
}

// Without --size the window opens at the size it closed at, within the work area; else the work
// area; with no monitor known (or a tiny one) at the saved size, else 1280x720.
TEST(Settings, TheWindowOpensToTheWorkAreaAndRemembersItsSize) {
  using Size = std::optional<std::array<int, 2>>;
  const Size screen = std::array<int, 2>{1600, 1000};
  EXPECT_EQ(opening_window_size(std::nullopt, screen), (std::array<int, 2>{1600, 1000}));
  EXPECT_EQ(opening_window_size(std::array<int, 2>{1400, 800}, screen), (std::array<int, 2>{1400, 800}));
  EXPECT_EQ(opening_window_size(std::array<int, 2>{2400, 800}, screen), (std::array<int, 2>{1600, 800})) << "another, smaller screen";
  EXPECT_EQ(opening_window_size(std::nullopt, std::nullopt), kFallbackWindowSize);
  EXPECT_EQ(opening_window_size(std::nullopt, std::array<int, 2>{200, 100}), kFallbackWindowSize);
  EXPECT_EQ(opening_window_size(std::array<int, 2>{1400, 800}, std::nullopt), (std::array<int, 2>{1400, 800}));
}

}  // namespace
}  // namespace nbscope::ui

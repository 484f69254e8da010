// --detector-lib, --detector-timeout and --detector-isolation (cli.hpp): the plugins load before any algorithm name is
// resolved, so --algorithm, --compare lanes, the Algorithm panel and `nbscope algorithms` see them
// as they see the built-ins. A library named without --algorithm is the one that runs (a built-in
// run instead would pass the user's bug unseen), and --algorithm takes a library's file name too.
#include <algorithm>
#include <filesystem>

#include "app/cli.hpp"
#include "core/detector.hpp"
#include "core/error.hpp"
#include "io/excerpt.hpp"
#include "io/plugin_library.hpp"

namespace nbscope {
namespace {

struct LoadedLibrary {
  std::string path;
  std::string name;  // the detector it declares
};

// The commands whose --algorithm is one name; the others take NAME[,NAME...].
bool takes_one_algorithm(const std::string& command) { return command == "gui" || command == "pairs" || command == "dump"; }

// A library's file names a user may write for it: "nbs_bug_mask" for nbs_bug_mask.so, "my" for libmy.so too.
bool is_file_name_of(const std::string& name, const std::string& path) {
  const std::string stem = std::filesystem::path(path).stem().string();
  return name == stem || (stem.rfind("lib", 0) == 0 && name == stem.substr(3));
}

std::string join(const std::vector<std::string>& names, const char* separator = ", ") {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : separator) + n;
  return s;
}

// `name` if it is a registered detector or no library's file name, else the name that library declares.
std::string declared_name(const std::string& name, const std::vector<LoadedLibrary>& libraries) {
  for (const DetectorInfo& d : detector_infos())
    if (d.name == name) return name;
  std::vector<const LoadedLibrary*> matches;
  for (const LoadedLibrary& l : libraries)
    if (is_file_name_of(name, l.path)) matches.push_back(&l);
  if (matches.empty()) return name;  // the command says it is unknown, naming the known ones
  if (matches.size() > 1 && matches[0]->name != matches[1]->name) {
    std::vector<std::string> which;
    for (const LoadedLibrary* l : matches) which.push_back(l->path + " declares '" + l->name + "'");
    throw Error("--algorithm: '" + excerpt(name) + "' is the file name of " + std::to_string(matches.size()) + " libraries (" +
                join(which) + "): name the detector");
  }
  return matches[0]->name;
}

}  // namespace

void load_detector_libs(Args& args, const std::string& command) {
  if (!args.offers("--detector-lib")) return;
  // Their ranges and choices are their rows' (command_table.cpp: plugin_options), refused when parsed.
  if (const auto seconds = args.number("--detector-timeout")) set_detector_timeout(*seconds);
  if (const auto isolation = args.value("--detector-isolation"))
    set_plugin_isolation(*isolation == "process" ? PluginIsolation::process : PluginIsolation::none);
  std::vector<LoadedLibrary> libraries;
  std::vector<std::string> declared;  // each detector once (the same file named twice loads once)
  for (const std::string& path : args.values("--detector-lib")) {
    libraries.push_back({path, load_detector_plugin(path)});
    if (std::find(declared.begin(), declared.end(), libraries.back().name) == declared.end()) declared.push_back(libraries.back().name);
  }
  if (libraries.empty() || command == "algorithms") return;
  if (const auto given = args.value("--algorithm")) {
    std::vector<std::string> names;
    for (const std::string& name : split_names("--algorithm", *given)) names.push_back(declared_name(name, libraries));
    args.set("--algorithm", join(names, ","));
  } else if (takes_one_algorithm(command) && declared.size() > 1) {
    throw Error("--detector-lib: the libraries declare " + std::to_string(declared.size()) + " detectors (" + join(declared) +
                "): choose one with --algorithm");
  } else {
    args.set("--algorithm", join(declared, ","));
  }
}

}  // namespace nbscope

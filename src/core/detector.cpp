#include "core/detector.hpp"

#include "core/detectors.hpp"
#include "core/error.hpp"

namespace nbscope {

namespace {
std::vector<DetectorInfo>& registry() {
  static std::vector<DetectorInfo> infos = builtin_detectors();
  return infos;
}
}  // namespace

void throw_if_misbehaved(const Detector& detector) {
  if (const Misbehaviour* m = detector.misbehaviour()) throw DetectorBug(m->where + m->text);
}

const std::vector<const char*>& Detector::pseudocode(int /*dim*/) const {
  static const std::vector<const char*> none;
  return none;
}

const std::vector<DetectorInfo>& detector_infos() { return registry(); }

void register_detector(DetectorInfo info) {
  for (const DetectorInfo& d : registry())
    if (d.name == info.name) return;
  registry().push_back(std::move(info));
}

std::string detector_names() {
  std::string s;
  for (const DetectorInfo& d : registry()) s += (s.empty() ? "" : ", ") + d.name;
  return s;
}

std::string detector_label(std::string_view name) {
  for (const DetectorInfo& d : registry()) {
    if (d.name != name || d.library.empty()) continue;
    const std::size_t slash = d.library.find_last_of('/');
    return d.name + " (" + d.library.substr(slash == std::string::npos ? 0 : slash + 1) + ")";
  }
  return std::string(name);
}

const DetectorInfo& detector_info(std::string_view name) {
  for (const DetectorInfo& d : registry())
    if (d.name == name) return d;
  throw Error("unknown algorithm '" + std::string(name) + "' (known: " + detector_names() + ")");
}

std::unique_ptr<Detector> make_detector(std::string_view name) { return detector_info(name).make(); }

}  // namespace nbscope

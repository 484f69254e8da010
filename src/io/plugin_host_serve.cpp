// The host process's side of an isolated plugin (plugin_host.hpp): load, then answer requests.
#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <new>

#include "core/error.hpp"
#include "io/plugin_host.hpp"
#include "io/plugin_library.hpp"
#include "io/plugin_wire.hpp"

#ifndef NBSCOPE_INSTALL_HOST_RELATIVE  // a build that never installs (the fuzz targets)
#define NBSCOPE_INSTALL_HOST_RELATIVE "nbscope-plugin-host"
#endif
#ifndef NBSCOPE_BUILD_PLUGIN_HOST
#define NBSCOPE_BUILD_PLUGIN_HOST ""
#define NBSCOPE_BUILD_DIR ""
#endif

namespace nbscope {

namespace {

constexpr int kSocketFd = 3;    // the host's end of the socket (plugin_host.cpp spawns it so)
constexpr int kProgressFd = 4;  // the shared page of its PluginProgress

std::filesystem::path running_binary_dir() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : self.parent_path();
}

bool is_file(const std::filesystem::path& path) {
  std::error_code ec;
  return !path.empty() && std::filesystem::is_regular_file(path, ec) && ::access(path.c_str(), X_OK) == 0;
}

// One detection as the request asks, its outcome into `reply`.
void detect(PluginDetector& detector, const DetectRequest& request, DetectReply& reply, TraceLog& trace) {
  detector.set_operation_limit(request.operation_limit);
  trace.set_keep_tests(request.keep_tests);
  PairList pairs = std::move(reply.pairs);  // its memory kept from frame to frame, as in-process
  reply = DetectReply{};
  reply.pairs = std::move(pairs);
  try {
    if (request.traced)
      detector.detect_traced(request.elements, request.options, reply.pairs, trace);
    else
      detector.detect(request.elements, request.options, reply.pairs);
  } catch (const PluginError& e) {
    reply.error = WireError::plugin_error;
    reply.message = e.what();
  } catch (const DetectorBug& e) {
    reply.error = WireError::detector_bug;
    reply.message = e.what();
  } catch (const Error& e) {
    reply.error = WireError::error;
    reply.message = e.what();
  } catch (const std::bad_alloc&) {
    reply.error = WireError::error;
    reply.message = "out of memory in the plugin's host process";
  }
  if (const auto* cells = detector.own_cells()) {
    reply.has_cells = true;
    reply.cells = *cells;
  }
  if (const WalkCheck* walks = detector.walk_check()) {
    reply.walks_checked = true;
    reply.walks = *walks;
  }
  if (const Misbehaviour* m = detector.misbehaviour()) reply.misbehaviour = *m;
}

}  // namespace

std::string plugin_host_path() {
  const char* given = std::getenv("NBSCOPE_PLUGIN_HOST");
  if (given != nullptr && *given != '\0') {
    if (!is_file(given)) throw Error(std::string("NBSCOPE_PLUGIN_HOST: ") + given + " is not an executable file");
    return given;
  }
  const std::filesystem::path dir = running_binary_dir();
  for (const std::filesystem::path& candidate : {dir / "nbscope-plugin-host", dir / NBSCOPE_INSTALL_HOST_RELATIVE})
    if (is_file(candidate)) return candidate.lexically_normal().string();
  // A test binary of the build tree (never an installed one: its host must be where it was installed).
  const std::string build_dir = NBSCOPE_BUILD_DIR;
  if (!build_dir.empty() && dir.string().rfind(build_dir + "/", 0) == 0 && is_file(NBSCOPE_BUILD_PLUGIN_HOST)) return NBSCOPE_BUILD_PLUGIN_HOST;
  throw Error("the plugin host nbscope-plugin-host is not beside " + dir.string() +
              "/nbscope nor installed: --detector-isolation none runs plugins in nbscope's own process");
}

int serve_plugin_host(int argc, char** argv) {
  if (argc != 3) {
    std::fputs("nbscope-plugin-host: started by nbscope (--detector-lib), not by hand\n", stderr);
    return 2;
  }
  void* page = ::mmap(nullptr, sizeof(PluginProgress), PROT_READ | PROT_WRITE, MAP_SHARED, kProgressFd, 0);
  if (page == MAP_FAILED) {
    std::fputs("nbscope-plugin-host: no shared progress page on fd 4\n", stderr);
    return 2;
  }
  auto* progress = static_cast<PluginProgress*>(page);  // constructed by nbscope before the spawn
  std::unique_ptr<Detector> detector;
  try {
    set_detector_timeout(std::strtod(argv[2], nullptr));
    set_plugin_isolation(PluginIsolation::none);  // this is the process of its own
    detector = make_detector(load_detector_plugin(argv[1]));
  } catch (const Error& e) {
    std::fprintf(stderr, "nbscope: error: %s\n", printable_line(e.what()).c_str());
    return 2;
  }
  auto* plugin = dynamic_cast<PluginDetector*>(detector.get());
  if (plugin == nullptr) return 2;  // not reached: the loader makes PluginDetectors when not isolating
  plugin->set_progress(progress);
  std::vector<char> message;
  if (!send_message(kSocketFd, message)) return 0;  // ready (an empty message)
  DetectReply reply;
  TraceLog trace;
  WireWriter out;
  while (receive_message(kSocketFd, message)) {
    if (message.empty()) return 2;
    WireReader in(message.data() + 1, message.size() - 1);
    out.restart(64 + reply.pairs.capacity() * sizeof(Pair));
    if (static_cast<HostRequest>(message[0]) == HostRequest::own_bytes) {
      out.value(static_cast<std::uint64_t>(plugin->own_bytes()));
    } else {
      const DetectRequest request = decode_request(in);
      trace.reset();
      detect(*plugin, request, reply, trace);
      encode(reply, request.traced ? &trace : nullptr, out);
    }
    if (!send_message(kSocketFd, out.bytes())) break;
  }
  return 0;  // the detector's destructor releases the plugin's state (guarded)
}

}  // namespace nbscope

// Loading detector plugins (plugin_library.hpp), and the guard around each call into one: the crash
// report of io/signals.hpp and one watchdog thread, armed per call.
#include "io/plugin_library.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

#include "core/error.hpp"
#include "core/plugin_detector.hpp"
#include "io/atomic_file.hpp"
#include "io/signals.hpp"

namespace nbscope {

namespace {

using Clock = std::chrono::steady_clock;

double g_timeout_seconds = kDefaultDetectorTimeout;
PluginIsolation g_isolation = PluginIsolation::process;

// One thread that ends the process when a plugin's call outlives its deadline. Arming costs two
// uncontended locks: the thread is woken only when it sleeps without a deadline, and otherwise wakes
// at the deadline it last saw, finds the call over (or a later deadline) and sleeps again.
class Watchdog {
 public:
  static Watchdog& instance() {
    static Watchdog* watchdog = new Watchdog();  // never destroyed: its thread runs until the process ends
    return *watchdog;
  }
  // Ends the process with `message` (which stays valid until disarm()), then where `progress` says the
  // call got to, unless disarm() comes within `seconds`.
  void arm(double seconds, const char* message, const PluginProgress* progress) {
    const std::lock_guard<std::mutex> lock(mutex_);
    message_ = message;
    progress_ = progress;
    deadline_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    armed_ = true;
    if (idle_) wake_.notify_one();
  }
  // The call returned in time.
  void disarm() {
    const std::lock_guard<std::mutex> lock(mutex_);
    armed_ = false;
  }

 private:
  Watchdog() { std::thread([this] { watch(); }).detach(); }
  void watch() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      while (!armed_) {
        idle_ = true;
        wake_.wait(lock);
        idle_ = false;
      }
      wake_.wait_until(lock, deadline_);
      if (armed_ && Clock::now() >= deadline_) {
        const std::string line = message_ + progress_text(progress_) + "\n";
        const ssize_t written = ::write(STDERR_FILENO, line.data(), line.size());
        (void)written;  // nothing better to do: the process ends either way
        remove_live_temporaries();
        ::_exit(2);
      }
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  bool armed_ = false;
  bool idle_ = false;
  Clock::time_point deadline_{};
  const char* message_ = "";
  const PluginProgress* progress_ = nullptr;
};

// Held during every plugin call: detector.h promises a library one thread at a time (the window's
// Scaling panel detects on a thread of its own), and the crash report and watchdog serve one call.
std::mutex g_plugin_call;

// The words after "crashed with SIGSEGV" or "did not return within S s" that name the call.
std::string call_text(PluginCallKind kind, std::int64_t frame) {
  switch (kind) {
    case PluginCallKind::load: return " while loading (dlopen, in its constructors)";
    case PluginCallKind::describe: return " in nbscope_detector_describe()";
    case PluginCallKind::detect: return " in nbscope_detect() on frame " + std::to_string(frame);
    case PluginCallKind::release: return " in nbscope_release()";
    case PluginCallKind::own_bytes: return " in nbscope_own_bytes()";
  }
  return "";
}

// Brackets every call into one library (load, describe, detect, release, own_bytes): the crash
// report and the watchdog, their lines prepared here, before the call.
class PluginGuard final : public PluginCallGuard {
 public:
  // `who`: "PATH (NAME)", or "PATH" before the name is known.
  PluginGuard(const std::string& who, double timeout)
      : who_("nbscope: error: " + who + ": "), crash_head_(who_ + "crashed with "), timeout_(timeout) {}
  void enter(PluginCallKind kind, std::int64_t frame) override {
    g_plugin_call.lock();  // unlocked by leave(), on this thread
    if (kind != kind_ || frame != frame_ || crash_tail_.empty()) {  // the lines change with the call only
      kind_ = kind;
      frame_ = frame;
      crash_tail_ = call_text(kind, frame);  // the report adds where the call got to, and the newline
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%g", timeout_);
      hang_line_ = who_ + "did not return within " + seconds + " s" + crash_tail_;
    }
    const PluginProgress* progress = kind == PluginCallKind::detect ? progress_ : nullptr;
    arm_crash_report(crash_head_.c_str(), crash_tail_.c_str(), progress);
    if (timeout_ > 0) Watchdog::instance().arm(timeout_, hang_line_.c_str(), progress);
  }
  void follow(const PluginProgress* progress) override { progress_ = progress; }
  void leave() override {
    if (timeout_ > 0) Watchdog::instance().disarm();
    disarm_crash_report();
    g_plugin_call.unlock();
  }

 private:
  std::string who_, crash_head_, crash_tail_, hang_line_;
  const PluginProgress* progress_ = nullptr;  // the detect call's, while one is followed
  PluginCallKind kind_ = PluginCallKind::detect;
  std::int64_t frame_ = 0;
  double timeout_;
};

// Which library registered each plugin name (a clash names both).
std::map<std::string, std::string>& plugin_libraries() {
  static std::map<std::string, std::string> libraries;
  return libraries;
}

// The libraries loaded, as absolute paths, in load order.
std::vector<std::string>& loaded_paths() {
  static std::vector<std::string> paths;
  return paths;
}

// The name each library already loaded registered, by its dlopen handle (one file, one handle).
std::map<void*, std::string>& loaded_handles() {
  static std::map<void*, std::string> handles;
  return handles;
}

void* open_library(const std::string& path, PluginGuard& guard) {
  // A name without a slash is a file here, not a search of the system's library paths.
  const std::string opened = path.find('/') == std::string::npos ? "./" + path : path;
  void* handle = nullptr;
  {
    const PluginCallScope guarded(&guard, PluginCallKind::load);  // dlopen runs the library's constructors
    handle = ::dlopen(opened.c_str(), RTLD_NOW | RTLD_LOCAL);
  }
  if (handle != nullptr) return handle;
  std::string why = ::dlerror();
  if (why.rfind(opened + ": ", 0) == 0) why = why.substr(opened.size() + 2);  // dlerror names the file too
  throw Error(path + ": cannot load: " + why);
}

template <class T>
T symbol(void* handle, const char* name) {
  return reinterpret_cast<T>(::dlsym(handle, name));
}

void check_name_free(const std::string& path, const std::string& name) {
  if (name == kAllAlgorithms || name == kRecordedAlgorithm)
    throw Error(path + ": its name '" + name + "' is reserved (--algorithm " + name + " means something else)");
  for (const DetectorInfo& known : detector_infos()) {
    if (known.name != name) continue;
    const auto other = plugin_libraries().find(name);
    if (other == plugin_libraries().end()) throw Error(path + ": its name '" + name + "' is a built-in detector's");
    throw Error(path + ": its name '" + name + "' is taken by " + other->second + ", loaded before it");
  }
}

}  // namespace

void set_detector_timeout(double seconds) { g_timeout_seconds = seconds; }

void set_plugin_isolation(PluginIsolation isolation) { g_isolation = isolation; }

std::string load_detector_plugin(const std::string& path) {
  PluginGuard unnamed(printable_line(path), g_timeout_seconds);  // until its describe names it
  void* handle = open_library(path, unnamed);  // never closed: its code may be running until the process ends
  // The same file again (--detector-lib given twice, or also saved in the window's settings): loaded once.
  if (const auto again = loaded_handles().find(handle); again != loaded_handles().end()) return again->second;
  const auto* version = symbol<const std::uint32_t*>(handle, "nbscope_api_version");
  if (version == nullptr) throw Error(path + ": no symbol nbscope_api_version: not an nbscope detector plugin");
  if (*version != NBSCOPE_DETECTOR_API_VERSION)
    throw Error(path + ": built for plugin API version " + std::to_string(*version) + "; this nbscope speaks " +
                std::to_string(NBSCOPE_DETECTOR_API_VERSION));
  PluginSymbols symbols;
  symbols.library = path;
  symbols.describe = symbol<nbscope_describe_fn>(handle, "nbscope_detector_describe");
  symbols.detect = symbol<nbscope_detect_fn>(handle, "nbscope_detect");
  symbols.release = symbol<nbscope_release_fn>(handle, "nbscope_release");
  symbols.own_bytes = symbol<nbscope_own_bytes_fn>(handle, "nbscope_own_bytes");
  for (const auto& [name, found] : {std::pair{"nbscope_detector_describe", symbols.describe != nullptr},
                                    std::pair{"nbscope_detect", symbols.detect != nullptr}})
    if (!found) throw Error(path + ": no symbol " + name + " (plugin API version 1 requires it)");
  // Its first call, and every read of what it returns (checked, then copied into nbscope's memory)
  // under the same guard: a bad pointer in its description is a crash of the plugin's too.
  std::shared_ptr<const PluginDescription> description;
  {
    const PluginCallScope guarded(&unnamed, PluginCallKind::describe);
    const nbscope_detector_info* info = symbols.describe();
    try {
      check_plugin_info(info);
    } catch (const Error& e) {
      throw Error(path + ": " + e.what());
    }
    description = std::make_shared<const PluginDescription>(*info);
  }
  const std::string name = description->name;
  check_name_free(path, name);
  symbols.guard = std::make_shared<PluginGuard>(printable_line(path) + " (" + name + ")", g_timeout_seconds);
  DetectorInfo entry = plugin_detector_info(symbols, description);
  if (g_isolation == PluginIsolation::process) {
    plugin_host_path();  // a missing host is said now, at the load, not at the first frame
    entry.make = [path, description, timeout = g_timeout_seconds]() -> std::unique_ptr<Detector> {
      return std::make_unique<IsolatedPluginDetector>(path, description, timeout);
    };
  }
  register_detector(std::move(entry));
  plugin_libraries()[name] = path;
  loaded_handles()[handle] = name;
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
  loaded_paths().push_back(ec ? path : absolute.lexically_normal().string());
  return name;
}

std::vector<std::string> loaded_detector_libraries() { return loaded_paths(); }

}  // namespace nbscope

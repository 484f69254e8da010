// The memory budget: the rule over faked or real sources, and the real sources.
#include "physics/memory_budget.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cctype>
#include <sstream>

namespace nbscope {

namespace {

// A whole decimal number at the start of `text` (leading blanks skipped), if any.
std::optional<std::uint64_t> leading_number(const std::string& text, std::size_t from = 0) {
  while (from < text.size() && (text[from] == ' ' || text[from] == '\t')) ++from;
  std::uint64_t v = 0;
  std::size_t digits = 0;
  for (; from < text.size() && std::isdigit(static_cast<unsigned char>(text[from])) != 0; ++from, ++digits) {
    if (v > (UINT64_MAX - 9) / 10) return std::nullopt;  // past 2^64: no sensible limit
    v = v * 10 + static_cast<std::uint64_t>(text[from] - '0');
  }
  if (digits == 0) return std::nullopt;
  return v;
}

// One cgroup hierarchy that may limit memory: where it is mounted and its two files.
struct CgroupFiles {
  const char* mount;
  const char* limit;
  const char* usage;
  const char* source;
};
constexpr CgroupFiles kCgroupV2{"/sys/fs/cgroup", "memory.max", "memory.current", "cgroup memory.max"};
constexpr CgroupFiles kCgroupV1{"/sys/fs/cgroup/memory", "memory.limit_in_bytes", "memory.usage_in_bytes", "cgroup memory.limit_in_bytes"};
// cgroup v1 writes "no limit" as a page-rounded 2^63 - 1.
constexpr std::uint64_t kNoLimitAbove = std::uint64_t{1} << 62;

// The process's cgroup path in /proc/self/cgroup's text: the line "0::/path" (v2) or
// "N:...,memory,...:/path" (v1).
std::optional<std::string> cgroup_path(const std::string& proc_self_cgroup, bool v2) {
  std::istringstream lines(proc_self_cgroup);
  std::string line;
  while (std::getline(lines, line)) {
    const std::size_t a = line.find(':');
    const std::size_t b = a == std::string::npos ? a : line.find(':', a + 1);
    if (b == std::string::npos) continue;
    const std::string id = line.substr(0, a), controllers = line.substr(a + 1, b - a - 1), path = line.substr(b + 1);
    if (path.empty() || path[0] != '/') continue;
    if (v2 && id == "0" && controllers.empty()) return path;
    if (!v2) {
      const std::string list = "," + controllers + ",";
      if (list.find(",memory,") != std::string::npos) return path;
    }
  }
  return std::nullopt;
}

// The least (limit - usage) of the cgroup at `path` and its ancestors in one hierarchy.
std::optional<std::uint64_t> cgroup_room(const MemorySources& s, const CgroupFiles& files, std::string path) {
  std::optional<std::uint64_t> room;
  while (true) {
    while (path.size() > 1 && path.back() == '/') path.pop_back();
    const std::string dir = std::string(files.mount) + (path == "/" ? "" : path) + "/";
    if (const auto text = s.read_file(dir + files.limit)) {
      const auto limit = leading_number(*text);  // "max" (v2) reads as none
      if (limit && *limit < kNoLimitAbove) {
        const auto usage_text = s.read_file(dir + files.usage);
        const std::uint64_t usage = usage_text ? leading_number(*usage_text).value_or(0) : 0;
        const std::uint64_t left = *limit > usage ? *limit - usage : 0;
        if (!room || left < *room) room = left;
      }
    }
    if (path == "/" || path.empty()) break;
    path = path.substr(0, path.find_last_of('/'));
    if (path.empty()) path = "/";
  }
  return room;
}

void consider(MemoryBudget& budget, std::optional<std::uint64_t> bytes, const char* source) {
  if (bytes && (!budget.bytes || *bytes < *budget.bytes)) {
    budget.bytes = bytes;
    budget.source = source;
  }
}

// Up to 64 kB of a file (the /proc and cgroup files are far smaller), without iostreams.
std::optional<std::string> read_small_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  std::string text;
  char buf[4096];
  ssize_t got = 0;
  while (text.size() < 65536 && (got = ::read(fd, buf, sizeof buf)) > 0) text.append(buf, static_cast<std::size_t>(got));
  ::close(fd);
  if (got < 0) return std::nullopt;
  return text;
}

std::optional<std::uint64_t> soft_limit(int resource) {
  rlimit r{};
  if (::getrlimit(resource, &r) != 0 || r.rlim_cur == RLIM_INFINITY) return std::nullopt;
  return static_cast<std::uint64_t>(r.rlim_cur);
}

}  // namespace

std::optional<std::uint64_t> proc_kilobytes(const std::string& text, const std::string& key) {
  const std::string prefix = key + ":";
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    if (text.compare(at, prefix.size(), prefix) == 0) {
      const auto kb = leading_number(text.substr(at + prefix.size(), end - at - prefix.size()));
      if (kb && *kb <= UINT64_MAX / 1024) return *kb * 1024;
      return std::nullopt;
    }
    at = end + 1;
  }
  return std::nullopt;
}

MemoryBudget memory_budget(const MemorySources& s) {
  MemoryBudget budget;
  const auto status = s.read_file("/proc/self/status");
  const auto used = [&](const char* key) { return status ? proc_kilobytes(*status, key).value_or(0) : 0; };
  if (s.rlimit_as) {
    const std::uint64_t size = used("VmSize");
    consider(budget, *s.rlimit_as > size ? *s.rlimit_as - size : 0, "RLIMIT_AS");
  }
  if (s.rlimit_data) {
    const std::uint64_t data = used("VmData");
    consider(budget, *s.rlimit_data > data ? *s.rlimit_data - data : 0, "RLIMIT_DATA");
  }
  if (const auto cgroups = s.read_file("/proc/self/cgroup")) {
    if (const auto path = cgroup_path(*cgroups, true)) consider(budget, cgroup_room(s, kCgroupV2, *path), kCgroupV2.source);
    if (const auto path = cgroup_path(*cgroups, false)) consider(budget, cgroup_room(s, kCgroupV1, *path), kCgroupV1.source);
  }
  if (const auto meminfo = s.read_file("/proc/meminfo")) consider(budget, proc_kilobytes(*meminfo, "MemAvailable"), "MemAvailable");
  return budget;
}

MemoryBudget memory_budget_now() {
  MemorySources s;
  s.read_file = read_small_file;
  s.rlimit_as = soft_limit(RLIMIT_AS);
  s.rlimit_data = soft_limit(RLIMIT_DATA);
  return memory_budget(s);
}

}  // namespace nbscope

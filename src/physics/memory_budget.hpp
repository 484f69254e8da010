// nbscope physics: how much more memory this process can get, so that a Box2D world is refused
// before its contacts would need more than that (physics/world_limits.hpp).
//
// The budget is the smallest of what each source leaves:
//   RLIMIT_AS   (soft, `ulimit -v`) less the process's address space now (VmSize);
//   RLIMIT_DATA (soft, `ulimit -d`) less its data segment now (VmData);
//   every cgroup v2 memory.max (under /sys/fs/cgroup) from the process's own cgroup
//     (/proc/self/cgroup, "0::/path") up to the root, less that cgroup's memory.current ("max" is
//     no limit); likewise cgroup v1's memory.limit_in_bytes less memory.usage_in_bytes (under
//     /sys/fs/cgroup/memory, the "memory" line; 2^62 and above is no limit);
//   MemAvailable (/proc/meminfo), which already leaves out what this process uses.
// A source that is missing or unreadable limits nothing; with none at all the budget is unknown.
// Swap is not counted.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace nbscope {

struct MemoryBudget {
  std::optional<std::uint64_t> bytes;  // what the process can still get; nullopt: nothing limits it
  std::string source;                  // the source that set it: "RLIMIT_AS", "RLIMIT_DATA", "cgroup memory.max", "MemAvailable"
};

// The file contents the rule reads (nullopt: missing or unreadable), and the soft limits
// (nullopt: RLIM_INFINITY), passed in so that tests can fake them.
struct MemorySources {
  std::function<std::optional<std::string>(const std::string& path)> read_file;
  std::optional<std::uint64_t> rlimit_as, rlimit_data;
};

// The budget by the rule above.
[[nodiscard]] MemoryBudget memory_budget(const MemorySources& sources);
// The budget of this process now (reads /proc, /sys/fs/cgroup and getrlimit; about 0.1 ms).
[[nodiscard]] MemoryBudget memory_budget_now();

// The value of `key` ("MemAvailable", "VmSize") in a /proc file of "Key:   123 kB" lines, in bytes.
[[nodiscard]] std::optional<std::uint64_t> proc_kilobytes(const std::string& text, const std::string& key);

}  // namespace nbscope

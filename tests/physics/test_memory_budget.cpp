// The memory budget (physics/memory_budget.hpp): the rule over faked sources (/proc files, cgroup v1
// and v2 files, resource limits) with every expected budget worked by hand, and the real sources.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "physics/memory_budget.hpp"

namespace nbscope {
namespace {

// Sources read from `files` (path -> contents; a path not there is missing).
MemorySources faked(const std::map<std::string, std::string>& files, std::optional<std::uint64_t> as = std::nullopt,
                    std::optional<std::uint64_t> data = std::nullopt) {
  MemorySources s;
  s.read_file = [files](const std::string& path) -> std::optional<std::string> {
    const auto it = files.find(path);
    if (it == files.end()) return std::nullopt;
    return it->second;
  };
  s.rlimit_as = as;
  s.rlimit_data = data;
  return s;
}

constexpr std::uint64_t kGiB = std::uint64_t{1} << 30;
const std::string kMeminfo = "MemTotal:       24683620 kB\nMemFree:         1000 kB\nMemAvailable:    4000000 kB\nBuffers: 1 kB\n";
const std::string kStatus = "Name:\tnbscope\nVmPeak:\t  300000 kB\nVmSize:\t  250000 kB\nVmData:\t  100000 kB\n";

// A /proc file's "Key: N kB" field is N * 1024 bytes; a prefix, a bad number or no line is none.
TEST(MemoryBudget, ReadsKilobyteFieldsOfProcFiles) {
  EXPECT_EQ(proc_kilobytes(kMeminfo, "MemAvailable"), std::uint64_t{4000000} * 1024);
  EXPECT_EQ(proc_kilobytes(kStatus, "VmSize"), std::uint64_t{250000} * 1024);
  EXPECT_EQ(proc_kilobytes(kMeminfo, "MemAvail"), std::nullopt);  // a prefix of a key is not the key
  EXPECT_EQ(proc_kilobytes("MemAvailable: lots kB\n", "MemAvailable"), std::nullopt);
  EXPECT_EQ(proc_kilobytes("", "MemAvailable"), std::nullopt);
}

// With no source readable the budget is unknown, not zero.
TEST(MemoryBudget, NothingKnownLimitsNothing) {
  const MemoryBudget b = memory_budget(faked({}));
  EXPECT_FALSE(b.bytes.has_value());
  EXPECT_EQ(b.source, "");
}

// With /proc alone the budget is MemAvailable.
TEST(MemoryBudget, MemAvailableAlone) {
  const MemoryBudget b = memory_budget(faked({{"/proc/meminfo", kMeminfo}, {"/proc/self/status", kStatus}}));
  EXPECT_EQ(b.bytes, std::uint64_t{4000000} * 1024);
  EXPECT_EQ(b.source, "MemAvailable");
}

// RLIMIT_AS less VmSize and RLIMIT_DATA less VmData, the smaller source winning, worked by hand.
TEST(MemoryBudget, ResourceLimitsLessWhatTheProcessHolds) {
  const std::map<std::string, std::string> files{{"/proc/meminfo", kMeminfo}, {"/proc/self/status", kStatus}};
  const MemoryBudget as = memory_budget(faked(files, kGiB));
  EXPECT_EQ(as.bytes, kGiB - std::uint64_t{250000} * 1024);  // less VmSize
  EXPECT_EQ(as.source, "RLIMIT_AS");
  const MemoryBudget data = memory_budget(faked(files, 2 * kGiB, kGiB / 2));
  EXPECT_EQ(data.bytes, kGiB / 2 - std::uint64_t{100000} * 1024);  // less VmData
  EXPECT_EQ(data.source, "RLIMIT_DATA");
  // A limit the process already passes leaves nothing; one far above the machine leaves MemAvailable.
  EXPECT_EQ(memory_budget(faked(files, 1000)).bytes, 0u);
  EXPECT_EQ(memory_budget(faked(files, 1000 * kGiB)).source, "MemAvailable");
  // Without /proc/self/status the limit itself.
  EXPECT_EQ(memory_budget(faked({}, kGiB)).bytes, kGiB);
}

// Every cgroup v2 memory.max from the process's own up to the root, less its use: the smallest wins.
TEST(MemoryBudget, CgroupV2FromTheOwnCgroupUpToTheRoot) {
  std::map<std::string, std::string> files{{"/proc/meminfo", kMeminfo},
                                           {"/proc/self/cgroup", "0::/app.slice/run-1.scope\n"},
                                           {"/sys/fs/cgroup/app.slice/run-1.scope/memory.max", "max\n"},
                                           {"/sys/fs/cgroup/app.slice/run-1.scope/memory.current", "5000\n"},
                                           {"/sys/fs/cgroup/app.slice/memory.max", "3000000000\n"},
                                           {"/sys/fs/cgroup/app.slice/memory.current", "1000000000\n"}};
  MemoryBudget b = memory_budget(faked(files));
  EXPECT_EQ(b.bytes, 2000000000u);  // the parent's limit less its use: "max" limits nothing
  EXPECT_EQ(b.source, "cgroup memory.max");
  // The nearest limit is not always the smallest.
  files["/sys/fs/cgroup/app.slice/run-1.scope/memory.max"] = "1500000000\n";
  EXPECT_EQ(memory_budget(faked(files)).bytes, 1500000000u - 5000);
  // A cgroup over its limit leaves nothing; missing usage counts as none.
  files["/sys/fs/cgroup/app.slice/memory.current"] = "4000000000\n";
  EXPECT_EQ(memory_budget(faked(files)).bytes, 0u);
  files.erase("/sys/fs/cgroup/app.slice/memory.current");
  EXPECT_EQ(memory_budget(faked(files)).bytes, 1500000000u - 5000);
  // A container's root: "0::/" and /sys/fs/cgroup/memory.max.
  EXPECT_EQ(memory_budget(faked({{"/proc/self/cgroup", "0::/\n"}, {"/sys/fs/cgroup/memory.max", "1073741824\n"}})).bytes, kGiB);
}

// Missing or garbled cgroup files limit nothing: MemAvailable stays the source.
TEST(MemoryBudget, CgroupFilesMissingOrUnreadableLimitNothing) {
  const std::map<std::string, std::string> files{{"/proc/meminfo", kMeminfo}, {"/proc/self/cgroup", "0::/a/b\n"}};
  EXPECT_EQ(memory_budget(faked(files)).source, "MemAvailable");
  std::map<std::string, std::string> garbled = files;
  garbled["/sys/fs/cgroup/a/memory.max"] = "a lot\n";
  EXPECT_EQ(memory_budget(faked(garbled)).source, "MemAvailable");
  garbled["/proc/self/cgroup"] = "nonsense";
  garbled["/sys/fs/cgroup/memory.max"] = "1000\n";  // not reached: no cgroup line names a path
  EXPECT_EQ(memory_budget(faked(garbled)).source, "MemAvailable");
}

// cgroup v1's memory controller: limit_in_bytes less usage_in_bytes, its "no limit" ignored.
TEST(MemoryBudget, CgroupV1MemoryController) {
  std::map<std::string, std::string> files{{"/proc/meminfo", kMeminfo},
                                           {"/proc/self/cgroup", "5:devices:/\n4:memory:/jobs/j1\n0::/\n"},
                                           {"/sys/fs/cgroup/memory/jobs/j1/memory.limit_in_bytes", "9223372036854771712\n"},
                                           {"/sys/fs/cgroup/memory/jobs/memory.limit_in_bytes", "500000000\n"},
                                           {"/sys/fs/cgroup/memory/jobs/memory.usage_in_bytes", "100000000\n"}};
  const MemoryBudget b = memory_budget(faked(files));
  EXPECT_EQ(b.bytes, 400000000u);  // v1's "no limit" (2^63 rounded to pages) limits nothing
  EXPECT_EQ(b.source, "cgroup memory.limit_in_bytes");
}

// This process's budget now names one of the four sources, or none with no bytes.
TEST(MemoryBudget, ThisProcesssBudgetNamesItsSource) {
  const MemoryBudget b = memory_budget_now();
  if (!b.bytes) {
    EXPECT_EQ(b.source, "");
    return;
  }
  EXPECT_TRUE(b.source == "RLIMIT_AS" || b.source == "RLIMIT_DATA" || b.source == "cgroup memory.max" ||
              b.source == "cgroup memory.limit_in_bytes" || b.source == "MemAvailable")
      << b.source;
}

}  // namespace
}  // namespace nbscope

// The contact estimate's counter (physics/world_limits.hpp) against a loop over all pairs, on
// random boxes with many exact ties (touching boxes overlap, as b2TestOverlap says), bodies of
// several fixtures and non-dynamic bodies; and the digits grouped in messages. The memory budget
// (physics/memory_budget.hpp) over faked sources; what Box2D's float makes of a body
// (physics/fixture_shape.hpp); a failed allocation inside Box2D (physics/box2d_memory.hpp).
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include "core/error.hpp"
#include "physics/fixture_shape.hpp"
#include "physics/memory_budget.hpp"
#include "physics/world.hpp"
#include "physics/world_limits.hpp"

namespace nbscope {
namespace {

std::int64_t count_by_loop(const std::vector<CountBox>& boxes) {
  std::int64_t n = 0;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      const CountBox &a = boxes[i], &b = boxes[j];
      if (a.body == b.body || (!a.dynamic && !b.dynamic)) continue;
      if (a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1) ++n;
    }
  return n;
}

TEST(ContactEstimate, CountsWhatALoopOverAllPairsCounts) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + static_cast<int>(rng() % 300);
    const int span = 2 + static_cast<int>(rng() % 40);  // small integer grids: many shared edges
    std::uniform_int_distribution<int> at(0, span), size(0, 4);
    std::vector<CountBox> boxes;
    std::int32_t body = 0;
    while (static_cast<int>(boxes.size()) < n) {
      const int fixtures = 1 + static_cast<int>(rng() % 3);
      const bool dynamic = rng() % 4 != 0;
      for (int f = 0; f < fixtures; ++f) {
        const float x = static_cast<float>(at(rng)), y = static_cast<float>(at(rng));
        boxes.push_back({x, y, x + static_cast<float>(size(rng)), y + static_cast<float>(size(rng)), body, dynamic});
      }
      ++body;
    }
    ASSERT_EQ(count_overlapping_boxes(boxes), count_by_loop(boxes)) << "trial " << trial;
  }
}

TEST(ContactEstimate, EveryBoxOnOnePointPairsWithEveryOther) {
  std::vector<CountBox> boxes;
  for (std::int32_t b = 0; b < 1000; ++b) boxes.push_back({0, 0, 1, 1, b, true});
  EXPECT_EQ(count_overlapping_boxes(boxes), 1000 * 999 / 2);
  boxes.push_back({1, 1, 2, 2, 1000, false});  // touching at one corner: a pair with each
  EXPECT_EQ(count_overlapping_boxes(boxes), 1000 * 999 / 2 + 1000);
  boxes.push_back({1.5f, 1.5f, 3, 3, 1001, false});  // two static boxes never pair
  EXPECT_EQ(count_overlapping_boxes(boxes), 1000 * 999 / 2 + 1000);
}

TEST(ContactEstimate, GroupsDigits) {
  EXPECT_EQ(grouped(0), "0");
  EXPECT_EQ(grouped(999), "999");
  EXPECT_EQ(grouped(1000), "1,000");
  EXPECT_EQ(grouped(4498500), "4,498,500");
  EXPECT_EQ(grouped(-1234567), "-1,234,567");
}

// ---- the memory budget ---------------------------------------------------------------------

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

TEST(MemoryBudget, ReadsKilobyteFieldsOfProcFiles) {
  EXPECT_EQ(proc_kilobytes(kMeminfo, "MemAvailable"), std::uint64_t{4000000} * 1024);
  EXPECT_EQ(proc_kilobytes(kStatus, "VmSize"), std::uint64_t{250000} * 1024);
  EXPECT_EQ(proc_kilobytes(kMeminfo, "MemAvail"), std::nullopt);  // a prefix of a key is not the key
  EXPECT_EQ(proc_kilobytes("MemAvailable: lots kB\n", "MemAvailable"), std::nullopt);
  EXPECT_EQ(proc_kilobytes("", "MemAvailable"), std::nullopt);
}

TEST(MemoryBudget, NothingKnownLimitsNothing) {
  const MemoryBudget b = memory_budget(faked({}));
  EXPECT_FALSE(b.bytes.has_value());
  EXPECT_EQ(b.source, "");
}

TEST(MemoryBudget, MemAvailableAlone) {
  const MemoryBudget b = memory_budget(faked({{"/proc/meminfo", kMeminfo}, {"/proc/self/status", kStatus}}));
  EXPECT_EQ(b.bytes, std::uint64_t{4000000} * 1024);
  EXPECT_EQ(b.source, "MemAvailable");
}

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

// ---- what Box2D's float makes of a body ----------------------------------------------------

BodySpec circle_body(double radius, BodyType type = BodyType::Dynamic, Vec2 offset = {}) {
  BodySpec b;
  b.type = type;
  ShapeSpec s;
  s.radius = radius;
  s.offset = offset;
  b.fixtures.push_back(s);
  return b;
}

TEST(Box2dFloats, ARadiusThatIsZeroInFloatIsNamed) {
  EXPECT_EQ(box2d_float_trouble(circle_body(0.5)), "");
  const std::string t = box2d_float_trouble(circle_body(1e-300, BodyType::Static));
  EXPECT_NE(t.find("radius 1e-300 m is 0 in Box2D's float"), std::string::npos) << t;
  EXPECT_NE(box2d_float_trouble(circle_body(1e-40, BodyType::Static)).find("is a denormal"), std::string::npos);
}

TEST(Box2dFloats, ADynamicBodyWhoseFloatMassIsADenormalIsNamed) {
  // pi * (1e-20)^2 = 3.1e-40 kg: below FLT_MIN (1.2e-38), its inverse infinite.
  const std::string t = box2d_float_trouble(circle_body(1e-20));
  EXPECT_NE(t.find("its mass in Box2D's float is a denormal"), std::string::npos) << t;
  EXPECT_EQ(box2d_float_trouble(circle_body(1e-20, BodyType::Static)), "");  // Box2D gives static bodies no mass
  EXPECT_EQ(box2d_float_trouble(circle_body(1e-19)), "");                      // 3.1e-38 kg: a normal float
  BodySpec light = circle_body(1);
  light.fixtures[0].density = 1e-40;
  EXPECT_NE(box2d_float_trouble(light).find("density 1e-40"), std::string::npos);
  light.fixtures[0].density = 0;  // no density: Box2D makes it 1 kg
  EXPECT_EQ(box2d_float_trouble(light), "");
}

TEST(Box2dFloats, AnInertiaThatRoundsAwayIsNamed) {
  // I = m (r^2 / 2 + 1) - m * 1: r^2 / 2 = 5e-9 is below float's step at 1, so I rounds to 0 and
  // b2Body::ResetMassData's assertion would abort.
  const std::string t = box2d_float_trouble(circle_body(1e-4, BodyType::Dynamic, {1, 0}));
  EXPECT_NE(t.find("rotational inertia"), std::string::npos) << t;
  EXPECT_EQ(box2d_float_trouble(circle_body(1e-2, BodyType::Dynamic, {1, 0})), "");
  EXPECT_EQ(box2d_float_trouble(circle_body(1e-4, BodyType::Kinematic, {1, 0})), "");
}

TEST(Box2dFloats, TheWorldRefusesSuchABodyNamingItBeforeMakingAny) {
  Scene scene;
  scene.path = "tiny.json";
  GeneratorSpec g;
  g.kind = GeneratorKind::RandomBox;
  g.count = 10;
  g.max = {10, 10};
  g.radius_range = std::array<double, 2>{1e-40, 1e-39};
  g.body = circle_body(0.5);
  g.body.where = "tiny.json:3: generators[0].body: ";
  scene.bodies.push_back(circle_body(0.5));
  scene.generators.push_back(g);
  try {
    PhysicsWorld world(scene);
    FAIL() << "built";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("tiny.json:3: generators[0].body: body #0: radius ", 0), 0u) << e.what();
  }
  // An emitter's bodies are the same every time: its template is checked when the world is built.
  scene.generators[0].kind = GeneratorKind::Emitter;
  scene.generators[0].body.fixtures[0].radius = 1e-40;
  try {
    PhysicsWorld world(scene);
    FAIL() << "built";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("tiny.json:3: generators[0].body: every body it pours: ", 0), 0u) << e.what();
  }
}

// ---- a failed allocation inside Box2D ------------------------------------------------------

// This process's address space now (VmSize), in bytes.
std::uint64_t address_space_now() {
  std::ifstream status("/proc/self/status");
  std::stringstream text;
  text << status.rdbuf();
  return proc_kilobytes(text.str(), "VmSize").value_or(0);
}

// Builds the world, then holds the address space to 16 MB more than the process has, and steps.
[[noreturn]] void step_with_little_address_space(const Scene& scene) {
  PhysicsWorld world(scene);
  rlimit tight{};
  tight.rlim_cur = address_space_now() + (16u << 20);
  tight.rlim_max = RLIM_INFINITY;
  if (setrlimit(RLIMIT_AS, &tight) != 0) std::_Exit(3);
  world.step();
  std::_Exit(4);  // not reached: the step cannot make its contacts
}

// 600 bodies on one point: ~180,000 contacts (~300 MB) fit the memory at load; then the address
// space is held to 16 MB more than the process has, and Box2D's step runs out of it making them.
// Box2D 2.4.1 would dereference the null malloc gave it: a segfault.
TEST(Box2dMemory, AFailedAllocationInsideBox2DEndsTheProcessWithOneLineAndExit2) {
#ifdef NBSCOPE_SANITIZED_BUILD
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: RLIMIT_AS cannot be lowered under it";
#endif
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  Scene scene;
  scene.path = "pile.json";
  scene.gravity = {0, 0};
  scene.max_contacts = kMaxMaxContacts;
  GeneratorSpec g;
  g.kind = GeneratorKind::RandomBox;
  g.count = 600;
  g.max = {0.001, 0.001};
  g.body = circle_body(0.5);
  scene.generators.push_back(g);
  EXPECT_EXIT(step_with_little_address_space(scene), testing::ExitedWithCode(2),
      "^nbscope: error: pile\\.json: frame 1: Box2D ran out of memory: an allocation of [0-9]+ (bytes|MB) failed \\(600 bodies, [0-9,]+ contacts\\)\n$");
}

}  // namespace
}  // namespace nbscope

// Box2D's allocations, watched (physics/box2d_memory.hpp): the line a failed allocation prints,
// worked by hand for each size and with a world's bodies and contacts, and a real failed allocation
// inside Box2D's step ending the process with that one line.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "physics/box2d_memory.hpp"
#include "physics/memory_budget.hpp"
#include "physics/world.hpp"
#include "support/physics_context.hpp"

namespace nbscope {
namespace {

using testphysics::circle_body;

// What a scope over `world` (or none) prints for a failed allocation of `bytes`.
std::string failure_line(const b2World* world, int uncounted, const std::string& where, long long bytes) {
  const Box2dAllocScope scope(world, uncounted, where);
  char line[2048];
  scope.describe_failure(bytes, line, sizeof line);
  return line;
}

// Without a world the line names where and the size, in bytes, MB or GB as it is large.
TEST(Box2dMemory, TheFailureLineNamesWhereAndTheSize) {
  EXPECT_EQ(failure_line(nullptr, 0, "s.json: frame 3: ", 512), "s.json: frame 3: Box2D ran out of memory: an allocation of 512 bytes failed");
  EXPECT_EQ(failure_line(nullptr, 0, "", 64'000'000), "Box2D ran out of memory: an allocation of 64 MB failed");
  EXPECT_EQ(failure_line(nullptr, 0, "", 1'500'000'000), "Box2D ran out of memory: an allocation of 1.5 GB failed");
  EXPECT_EQ(failure_line(nullptr, 0, "", -1), "Box2D ran out of memory: an allocation of more than 2.1 GB failed");
}

// With a world the line adds its bodies (less the uncounted ground) and contacts, digits grouped.
TEST(Box2dMemory, TheFailureLineCountsTheWorldsBodiesAndContacts) {
  Scene scene;
  scene.path = "heap.json";
  scene.gravity = {0, 0};
  GeneratorSpec g;
  g.kind = GeneratorKind::RandomBox;
  g.count = 60;
  g.max = {0.001, 0.001};
  g.body = circle_body(0.5);
  scene.generators.push_back(g);
  PhysicsWorld world(scene);
  world.step();
  const int contacts = world.world().GetContactCount();
  ASSERT_GE(contacts, 1000);  // 60 bodies on one point: up to 1,770 pairs
  const std::string thousands = std::to_string(contacts / 1000), units = std::to_string(contacts % 1000);
  const std::string grouped_by_hand = thousands + "," + std::string(3 - units.size(), '0') + units;
  EXPECT_EQ(failure_line(&world.world(), 1, "heap.json: frame 2: ", 2'000'000),
            "heap.json: frame 2: Box2D ran out of memory: an allocation of 2 MB failed (60 bodies, " + grouped_by_hand + " contacts)");
}

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
// A failed allocation inside Box2D's step ends the process with one line naming the frame, exit 2.
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

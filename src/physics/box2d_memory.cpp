// Box2D's allocator (physics/box2d_memory.hpp): malloc, and one line and exit 2 when it fails.
#include "physics/box2d_memory.hpp"

#include <box2d/box2d.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>


namespace nbscope {

namespace {

thread_local Box2dAllocScope* t_scope = nullptr;

// "1,234,567" into `out`, without allocating.
const char* grouped_into(long long n, char* out, std::size_t size) {
  char digits[32];
  const int len = std::snprintf(digits, sizeof digits, "%lld", n < 0 ? -n : n);
  std::size_t k = 0;
  if (n < 0 && k + 1 < size) out[k++] = '-';
  for (int i = 0; i < len && k + 1 < size; ++i) {
    if (i > 0 && (len - i) % 3 == 0 && k + 1 < size) out[k++] = ',';
    if (k + 1 < size) out[k++] = digits[i];
  }
  out[k] = '\0';
  return out;
}

std::atomic<OutOfMemoryCleanup> g_cleanup{nullptr};

[[noreturn]] void out_of_memory(long long bytes) {
  char line[1400];
  std::memcpy(line, "nbscope: error: ", 16);
  if (t_scope != nullptr) {
    t_scope->describe_failure(bytes, line + 16, sizeof line - 17);
  } else {
    const Box2dAllocScope nowhere(nullptr, 0, "");
    nowhere.describe_failure(bytes, line + 16, sizeof line - 17);
  }
  const std::size_t len = std::strlen(line);
  line[len] = '\n';
  if (const OutOfMemoryCleanup cleanup = g_cleanup) cleanup();
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, line, len + 1);
  ::_exit(2);
}

}  // namespace

Box2dAllocScope::Box2dAllocScope(const b2World* world, int uncounted_bodies, const std::string& where)
    : outer_(t_scope), world_(world), uncounted_bodies_(uncounted_bodies) {
  std::snprintf(where_, sizeof where_, "%s", where.c_str());
  t_scope = this;
}

Box2dAllocScope::~Box2dAllocScope() { t_scope = outer_; }

void set_box2d_out_of_memory_cleanup(OutOfMemoryCleanup cleanup) { g_cleanup = cleanup; }

void Box2dAllocScope::describe_failure(long long bytes, char* out, std::size_t size) const {
  char amount[32];
  const double b = static_cast<double>(bytes);
  if (bytes < 0) std::snprintf(amount, sizeof amount, "more than 2.1 GB");  // past Box2D's int32 sizes
  else if (b >= 1e9) std::snprintf(amount, sizeof amount, "%.1f GB", b / 1e9);
  else if (b >= 1e6) std::snprintf(amount, sizeof amount, "%.0f MB", b / 1e6);
  else std::snprintf(amount, sizeof amount, "%lld bytes", bytes);
  if (world_ == nullptr) {
    std::snprintf(out, size, "%sBox2D ran out of memory: an allocation of %s failed", where_, amount);
    return;
  }
  char bodies[32], contacts[32];
  std::snprintf(out, size, "%sBox2D ran out of memory: an allocation of %s failed (%s bodies, %s contacts)", where_, amount,
                grouped_into(world_->GetBodyCount() - uncounted_bodies_, bodies, sizeof bodies),
                grouped_into(world_->GetContactCount(), contacts, sizeof contacts));
}

}  // namespace nbscope

// Replaces libbox2d's own definition (see the header): the same malloc, but never a null return.
// A negative size is a count Box2D overflowed in int32: more than it can ask for.
void* b2Alloc_Default(int32 size) {
  if (size < 0) nbscope::out_of_memory(-1);
  void* p = std::malloc(static_cast<std::size_t>(size));
  if (p == nullptr && size > 0) nbscope::out_of_memory(size);
  return p;
}

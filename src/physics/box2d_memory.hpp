// nbscope physics: Box2D's allocations, watched. Box2D 2.4.1 takes all its memory through
// b2Alloc_Default (malloc) and uses what it gets without checking, so a failed allocation (a
// `ulimit -v`, a cgroup's limit) is a segfault somewhere inside Box2D. box2d_memory.cpp defines
// b2Alloc_Default for the whole program: libbox2d calls it through its PLT, so the program's
// definition is the one called. A failed allocation there cannot be thrown past Box2D (its
// stack allocator asserts on the unwound frames), so it ends the process: one line, the live
// temporaries removed, exit 2. The contact estimate (physics/world_limits.hpp) refuses before
// Box2D steps into most such failures; this is the last line behind it.
#pragma once
#include <string>

class b2World;

namespace nbscope {

// While it lives, a failed Box2D allocation on this thread says what was being done:
//   nbscope: error: <where>Box2D ran out of memory: an allocation of 64 MB failed (3,000 bodies, 1,234,567 contacts)
// `where` is e.g. "scene.json: frame 3: "; `world` (may be null) gives the bodies, less
// `uncounted_bodies` of its own (the mouse joint's ground), and the contacts.
class Box2dAllocScope {
 public:
  Box2dAllocScope(const b2World* world, int uncounted_bodies, const std::string& where);
  ~Box2dAllocScope();
  Box2dAllocScope(const Box2dAllocScope&) = delete;
  Box2dAllocScope& operator=(const Box2dAllocScope&) = delete;

  // What a failed allocation of `bytes` prints (without "nbscope: error: " and the newline), into
  // `out` of `size` bytes; allocation-free. Exposed for tests.
  void describe_failure(long long bytes, char* out, std::size_t size) const;

 private:
  Box2dAllocScope* outer_;
  const b2World* world_;
  int uncounted_bodies_;
  char where_[1024];
};

// Called (async-signal-safe, allocation-free) just before a failed Box2D allocation ends the
// process: the program sets it to remove its live temporaries (io/atomic_file.hpp), which physics,
// a floor below io, cannot name.
using OutOfMemoryCleanup = void (*)();
void set_box2d_out_of_memory_cleanup(OutOfMemoryCleanup cleanup);

}  // namespace nbscope

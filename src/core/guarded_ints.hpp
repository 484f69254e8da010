// nbscope core: integers whose end touches a page nobody may touch, for a buffer a plugin writes
// (nbscope_output.cells). A write past the end faults at once, inside the plugin's call, where the
// crash report locates it, instead of corrupting nbscope's heap behind the buffer (a loop to k <= n).
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>

namespace nbscope {

class GuardedInts {
 public:
  GuardedInts() = default;
  ~GuardedInts();
  GuardedInts(const GuardedInts&) = delete;
  GuardedInts& operator=(const GuardedInts&) = delete;

  // `count` integers set to `value`, ending at the guard page (the mapping is kept while it fits).
  // Throws std::bad_alloc when the pages cannot be mapped.
  void assign(std::size_t count, std::int32_t value);
  [[nodiscard]] std::int32_t* data() { return data_; }
  [[nodiscard]] std::span<const std::int32_t> view() const { return {data_, size_}; }

 private:
  void* map_ = nullptr;
  std::size_t map_bytes_ = 0;  // the mapping, its last page the guard
  std::int32_t* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace nbscope

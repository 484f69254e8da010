// nbscope core: an allocator for large scratch arrays that asks Linux for transparent huge pages.
// nbs's counting sort writes each element's record into one of ny streams of a N-record array: with
// 4 KiB pages every stream is on its own page and the TLB (about 2,000 entries) misses on nearly
// every write past a few thousand rows; with 2 MiB pages a 1e7-element array is a few dozen pages.
// Elsewhere (or when the kernel says no) it is plain memory.
#pragma once
#include <cstddef>
#include <new>

namespace nbscope {

// Allocates `bytes`, 2 MiB-aligned and advised for huge pages when at least 2 MiB; frees with huge_free.
void* huge_alloc(std::size_t bytes);
// Frees what huge_alloc returned.
void huge_free(void* p) noexcept;

// std::allocator's interface over huge_alloc, for std::vector<T, HugePageAllocator<T>>.
template <class T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) {}  // NOLINT: converting, as allocators are
  T* allocate(std::size_t n) { return static_cast<T*>(huge_alloc(n * sizeof(T))); }
  void deallocate(T* p, std::size_t) noexcept { huge_free(p); }
  friend bool operator==(const HugePageAllocator&, const HugePageAllocator&) { return true; }
};

}  // namespace nbscope

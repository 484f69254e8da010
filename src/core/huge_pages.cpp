// nbscope core: huge_pages.hpp.
#include "core/huge_pages.hpp"

#include <cstdlib>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace nbscope {

namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;
}

void* huge_alloc(std::size_t bytes) {
  if (bytes < kHugePage) {
    void* p = std::malloc(bytes == 0 ? 1 : bytes);
    if (!p) throw std::bad_alloc();
    return p;
  }
  const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  void* p = std::aligned_alloc(kHugePage, rounded);
  if (!p) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
  madvise(p, rounded, MADV_HUGEPAGE);  // advice only: without huge pages the memory works the same
#endif
  return p;
}

void huge_free(void* p) noexcept { std::free(p); }

}  // namespace nbscope

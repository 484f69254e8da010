// nbscope core: integers ending at a guard page (guarded_ints.hpp).
#include "core/guarded_ints.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <new>

namespace nbscope {

GuardedInts::~GuardedInts() {
  if (map_ != nullptr) ::munmap(map_, map_bytes_);
}

void GuardedInts::assign(std::size_t count, std::int32_t value) {
  const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
  const std::size_t bytes = count * sizeof(std::int32_t);
  const std::size_t need = (bytes + page - 1) / page * page + page;  // the data's pages, then the guard
  if (map_ == nullptr || map_bytes_ < need) {
    if (map_ != nullptr) ::munmap(map_, map_bytes_);
    map_ = nullptr;
    void* map = ::mmap(nullptr, need, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (map == MAP_FAILED) throw std::bad_alloc();
    char* guard = static_cast<char*>(map) + need - page;
    if (::mprotect(guard, page, PROT_NONE) != 0) {
      ::munmap(map, need);
      throw std::bad_alloc();
    }
    map_ = map;
    map_bytes_ = need;
  }
  char* guard = static_cast<char*>(map_) + map_bytes_ - page;
  data_ = reinterpret_cast<std::int32_t*>(guard - bytes);
  size_ = count;
  std::fill(data_, data_ + count, value);
}

}  // namespace nbscope

// nbscope fuzz targets: the input read a byte at a time (the detectors and plugin targets decode it).
#pragma once
#include <cstddef>
#include <cstdint>

namespace nbscope::fuzz {

// Reads the input a byte at a time; zeros once it is used up.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  // The next byte, or 0 past the end.
  std::uint8_t u8() { return pos_ < size_ ? data_[pos_++] : 0; }
  // The next four bytes, big-endian.
  std::uint32_t u32() {
    std::uint32_t v = 0;
    for (int k = 0; k < 4; ++k) v = (v << 8) | u8();
    return v;
  }
  // True once every byte was read.
  [[nodiscard]] bool done() const { return pos_ >= size_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

}  // namespace nbscope::fuzz

// nbscope io: RGBA images, PNG files, and the screenshot comparison the golden tests use.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace nbscope {

// An 8-bit RGBA image, rows top to bottom.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes

  // Makes a width x height image filled with one colour.
  static Image filled(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a = 255);
  // Pointer to the 4 bytes of pixel (x, y); no bounds check.
  [[nodiscard]] std::uint8_t* at(int x, int y) { return rgba.data() + (static_cast<std::size_t>(y) * width + x) * 4; }
  [[nodiscard]] const std::uint8_t* at(int x, int y) const {
    return rgba.data() + (static_cast<std::size_t>(y) * width + x) * 4;
  }
};

// Writes `image` as a PNG, atomically (whole or not at all); Error("<path>: cannot write: ...").
void write_png(const std::string& path, const Image& image);
// Reads a PNG (any channel count) as RGBA; Error("<path>: ...") when missing or not a PNG.
Image read_png(const std::string& path);

// Result of comparing two images pixel by pixel.
struct ImageDiff {
  bool same_size = false;
  std::int64_t differing = 0;  // pixels where some channel differs by more than the tolerance
  std::int64_t total = 0;      // pixels compared
  int max_channel_delta = 0;   // largest channel difference seen
  Image diff;                  // differing pixels red over a dimmed copy of `expected`

  // Share of differing pixels in [0, 1] (1 when the sizes differ).
  [[nodiscard]] double share() const { return same_size && total > 0 ? double(differing) / double(total) : 1.0; }
};

// Compares RGB of `actual` with `expected`: a pixel differs when any of R, G, B differs by more
// than `channel_tolerance` (alpha is ignored: screenshots are opaque).
ImageDiff compare_images(const Image& actual, const Image& expected, int channel_tolerance);

// True when every pixel has the same RGB (a blank screenshot).
bool is_uniform(const Image& image);

}  // namespace nbscope

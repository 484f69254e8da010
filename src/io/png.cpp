#include "io/png.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

// stb is header-only here (static functions), so nothing clashes with libstb or ImGui's copy.
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace nbscope {

Image Image::filled(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a) {
  Image img;
  img.width = width;
  img.height = height;
  img.rgba.resize(static_cast<std::size_t>(width) * height * 4);
  for (std::size_t i = 0; i < img.rgba.size(); i += 4) {
    img.rgba[i] = r;
    img.rgba[i + 1] = g;
    img.rgba[i + 2] = b;
    img.rgba[i + 3] = a;
  }
  return img;
}

namespace {
void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(context);
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}
}  // namespace

void write_png(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4)
    throw Error(path + ": cannot write: the image is empty or malformed");
  std::vector<std::uint8_t> encoded;
  encoded.reserve(image.rgba.size() / 4);
  if (stbi_write_png_to_func(&append_bytes, &encoded, image.width, image.height, 4, image.rgba.data(),
                             image.width * 4) == 0)
    throw Error(path + ": cannot write: PNG encoding failed");
  write_bytes_atomically(path, encoded.data(), encoded.size());
}

Image read_png(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in || std::filesystem::is_directory(path)) throw Error(path + ": cannot read the file");
  const std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  int w = 0, h = 0, channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &w, &h, &channels, 4);
  if (pixels == nullptr) throw Error(path + ": not a PNG image (" + stbi_failure_reason() + ")");
  Image img;
  img.width = w;
  img.height = h;
  img.rgba.assign(pixels, pixels + static_cast<std::size_t>(w) * h * 4);
  stbi_image_free(pixels);
  return img;
}

ImageDiff compare_images(const Image& actual, const Image& expected, int channel_tolerance) {
  ImageDiff d;
  d.same_size = actual.width == expected.width && actual.height == expected.height &&
                actual.rgba.size() == expected.rgba.size();
  if (!d.same_size) return d;
  d.total = static_cast<std::int64_t>(actual.width) * actual.height;
  d.diff = expected;
  for (std::size_t i = 0; i < actual.rgba.size(); i += 4) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(actual.rgba[i + c]) - int(expected.rgba[i + c])));
    d.max_channel_delta = std::max(d.max_channel_delta, worst);
    std::uint8_t* px = d.diff.rgba.data() + i;
    if (worst > channel_tolerance) {
      ++d.differing;
      px[0] = 255;
      px[1] = 0;
      px[2] = 0;
    } else {
      for (int c = 0; c < 3; ++c) px[c] = static_cast<std::uint8_t>(px[c] / 4);
    }
    px[3] = 255;
  }
  return d;
}

bool is_uniform(const Image& image) {
  for (std::size_t i = 4; i < image.rgba.size(); i += 4)
    if (!std::equal(image.rgba.begin() + i, image.rgba.begin() + i + 3, image.rgba.begin())) return false;
  return true;
}

}  // namespace nbscope

#include "render/gl_context.hpp"

#include <cstring>

#include "render/gl.hpp"

namespace nbscope::render {

Image GlContext::read_pixels() const {
  Image img;
  img.width = width();
  img.height = height();
  img.rgba.resize(static_cast<std::size_t>(img.width) * img.height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  // GL's rows run bottom to top; images run top to bottom.
  const std::size_t row = static_cast<std::size_t>(img.width) * 4;
  std::vector<std::uint8_t> tmp(row);
  for (int y = 0; y < img.height / 2; ++y) {
    std::uint8_t* a = img.rgba.data() + y * row;
    std::uint8_t* b = img.rgba.data() + (img.height - 1 - y) * row;
    std::memcpy(tmp.data(), a, row);
    std::memcpy(a, b, row);
    std::memcpy(b, tmp.data(), row);
  }
  // The screenshot is what the user sees: opaque.
  for (std::size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;
  return img;
}

std::string GlContext::describe() const {
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return std::string(version != nullptr ? version : "?") + " / " + (renderer != nullptr ? renderer : "?");
}

void gl_finish_all() { glFinish(); }

}  // namespace nbscope::render

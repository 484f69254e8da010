#include "render/gl_context.hpp"

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/error.hpp"
#include "render/gl.hpp"
#include "render/gl_offscreen.hpp"

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

// ---- choosing the off-screen backend ------------------------------------------------------------

std::unique_ptr<GlContext> make_offscreen_context(int width, int height, const std::string& backend) {
  if (backend != "osmesa" && backend != "egl" && backend != "auto")
    throw Error("--gl: '" + printable_line(backend) + "' is not one of osmesa, egl, auto");
  if (width < 1 || height < 1 || width > 8192 || height > 8192)
    throw Error("--gl " + backend + ": " + std::to_string(width) + "x" + std::to_string(height) +
                " is not a usable buffer size (1..8192 each way)");
  std::string missing;
  if (backend == "osmesa") {
    auto context = make_osmesa_context(width, height, "--gl osmesa", &missing);
    if (!context) throw Error("--gl osmesa: " + missing + "; use --gl egl");
    return context;
  }
  if (backend == "egl") {
    auto context = make_egl_context(width, height, "--gl egl", &missing);
    if (!context)
      throw Error(missing.rfind("not built", 0) == 0 ? "--gl egl: " + missing : "--gl egl: no EGL display (" + missing + ")");
    return context;
  }
  // auto: OSMesa when its library is there at run time (Mesa before 25.1), else EGL.
  if (auto context = make_osmesa_context(width, height, "--gl auto (osmesa)", &missing)) return context;
  std::string egl_missing;
  if (auto context = make_egl_context(width, height, "--gl auto (egl)", &egl_missing)) return context;
  throw Error("--gl auto: no off-screen renderer (osmesa: " + missing + "; egl: " + egl_missing + ")");
}

void* open_gl_library(const char* env_var, const char* soname, std::string* missing) {
  const char* override_name = std::getenv(env_var);
  const std::string name = override_name != nullptr && *override_name != '\0' ? override_name : soname;
  // RTLD_LOCAL: the library's gl* symbols must never pre-empt anyone else's (all GL goes through glad).
  void* handle = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle != nullptr) return handle;
  const char* why = dlerror();
  const std::string reason = why != nullptr ? why : "";
  const std::string shown = printable_line(name) + (override_name != nullptr && *override_name != '\0' ? std::string(" (from ") + env_var + ")" : "");
  if (reason.empty() || reason.find("No such file") != std::string::npos)
    *missing = shown + " not found";
  else
    *missing = "cannot load " + shown + ": " + printable_line(reason);
  return nullptr;
}

void* gl_library_symbol(void* library, const char* name, const std::string& where, const char* what) {
  void* symbol = dlsym(library, name);
  if (symbol == nullptr) throw Error(where + ": the " + what + " library has no " + name);
  return symbol;
}

// ---- the framebuffer of a context without a default one -----------------------------------------

OffscreenFramebuffer::OffscreenFramebuffer(int width, int height, const std::string& where) {
  try {
    glGenFramebuffers(1, &framebuffer_);
    glGenRenderbuffers(1, &colour_);
    glGenRenderbuffers(1, &depth_stencil_);
    glBindRenderbuffer(GL_RENDERBUFFER, colour_);
    // Plain RGBA8, single-sampled: the same pixels OSMesa's RGBA buffer holds (no sRGB, no MSAA).
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_stencil_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_stencil_);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      char buf[16];
      std::snprintf(buf, sizeof buf, "0x%04x", status);
      throw Error(where + ": framebuffer of " + std::to_string(width) + "x" + std::to_string(height) +
                  " incomplete (status " + buf + ")");
    }
    glDrawBuffer(GL_COLOR_ATTACHMENT0);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    // A context made current without a surface starts with a 0x0 viewport and scissor box.
    glViewport(0, 0, width, height);
    glScissor(0, 0, width, height);
    check_gl(where.c_str());
  } catch (...) {
    release();
    throw;
  }
}

OffscreenFramebuffer::~OffscreenFramebuffer() { release(); }

void OffscreenFramebuffer::release() {
  if (framebuffer_ != 0) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer_);
  }
  if (colour_ != 0) glDeleteRenderbuffers(1, &colour_);
  if (depth_stencil_ != 0) glDeleteRenderbuffers(1, &depth_stencil_);
  framebuffer_ = colour_ = depth_stencil_ = 0;
}

void OffscreenFramebuffer::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_); }

}  // namespace nbscope::render

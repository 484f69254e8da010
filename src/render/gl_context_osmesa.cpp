// The OSMesa context. This file includes OSMesa's header (and so GL/gl.h) and therefore no glad;
// it calls no gl* function itself, only OSMesa's, and hands OSMesaGetProcAddress to glad.
#include <GL/osmesa.h>

#include <string>
#include <vector>

#include "core/error.hpp"
#include "render/gl_context.hpp"

namespace nbscope::render {

// Defined in gl_loader.cpp (which includes glad); repeated here to keep GL/gl.h and glad apart.
using GlProcLoader = void* (*)(const char* name);
void load_gl(GlProcLoader loader, const char* where);

namespace {

void* osmesa_proc(const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }

class OsmesaContext final : public GlContext {
 public:
  OsmesaContext(int width, int height) : width_(width), height_(height) {
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_STENCIL_BITS,
                           8,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           3,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           3,
                           0};
    context_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (context_ == nullptr) throw Error("osmesa: cannot create a GL 3.3 core context");
    buffer_.resize(static_cast<std::size_t>(width) * height * 4);
    try {
      make_current();
      load_gl(&osmesa_proc, "osmesa");
    } catch (...) {
      if (context_ != nullptr) OSMesaDestroyContext(context_);
      throw;
    }
  }
  ~OsmesaContext() override {
    if (context_ != nullptr) OSMesaDestroyContext(context_);
  }
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  [[nodiscard]] const char* kind() const override { return "osmesa"; }
  [[nodiscard]] int width() const override { return width_; }
  [[nodiscard]] int height() const override { return height_; }
  void make_current() override {
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
      OSMesaDestroyContext(context_);
      context_ = nullptr;
      throw Error("osmesa: cannot make the context current at " + std::to_string(width_) + "x" +
                  std::to_string(height_));
    }
  }
  void present() override { gl_finish_all(); }

 private:
  int width_, height_;
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<GlContext> make_offscreen_context(int width, int height, const std::string& backend) {
  if (backend == "egl")
    throw Error("--gl egl: not built (this build renders off-screen with OSMesa only; use --gl osmesa)");
  if (backend != "osmesa" && backend != "auto")
    throw Error("--gl: '" + backend + "' is not one of osmesa, egl, auto");
  if (width < 1 || height < 1 || width > 8192 || height > 8192)
    throw Error("osmesa: " + std::to_string(width) + "x" + std::to_string(height) + " is not a usable buffer size");
  return std::make_unique<OsmesaContext>(width, height);
}

}  // namespace nbscope::render

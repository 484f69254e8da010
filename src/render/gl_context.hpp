// nbscope render: where GL draws. Three implementations: off-screen through OSMesa or EGL
// (headless, no X server, no GPU; gl_offscreen.hpp) and a GLFW window. No header pulls in GL, so
// callers choose freely.
#pragma once
#include <memory>
#include <string>

#include "io/png.hpp"

namespace nbscope::render {

class GlContext {
 public:
  virtual ~GlContext() = default;
  // "osmesa", "egl" or "window".
  [[nodiscard]] virtual const char* kind() const = 0;
  // Framebuffer size in pixels.
  [[nodiscard]] virtual int width() const = 0;
  [[nodiscard]] virtual int height() const = 0;
  // Makes this context current on the calling thread.
  virtual void make_current() = 0;
  // Shows the frame (window) or waits for it to finish (off-screen).
  virtual void present() = 0;

  // The framebuffer as RGBA, rows top to bottom (call before present()).
  [[nodiscard]] Image read_pixels() const;
  // GL_VERSION and GL_RENDERER, e.g. "4.5 (Core Profile) Mesa 22.3.6 / llvmpipe (LLVM 15.0.6, 256 bits)".
  [[nodiscard]] std::string describe() const;
};

// An off-screen context of width x height, current and drawing into its width x height buffer.
// `backend` is "osmesa", "egl" or "auto" (OSMesa when libOSMesa.so.8 loads at run time, else EGL);
// Error("--gl <backend>: ...") when it is unknown, not built, not installed or fails.
std::unique_ptr<GlContext> make_offscreen_context(int width, int height, const std::string& backend);

// Waits until GL has finished every command (through glad, never libGL).
void gl_finish_all();

}  // namespace nbscope::render

// nbscope render, internal: the two off-screen backends behind make_offscreen_context and what
// they share. Both load their library with dlopen at run time, so the binary needs neither
// libOSMesa nor libEGL to start, and the headless path never pulls in libGL/GLX.
#pragma once
#include <memory>
#include <string>

#include "render/gl_context.hpp"

namespace nbscope::render {

// As in gl.hpp, which the backends cannot include (OSMesa's header brings GL/gl.h, which clashes
// with glad's): a context's "address of GL function `name`", and loading glad through it.
using GlProcLoader = void* (*)(const char* name);
void load_gl(GlProcLoader loader, const char* where);
// load_gl unless GL was last loaded through `loader` already: a context made current again after
// another backend's was (glad's pointers are global) gets its own functions back.
void reload_gl_if_other(GlProcLoader loader, const char* where);

// An OSMesa context, or nullptr with `*missing` set when the backend is not built in or its
// library cannot be loaded. Error("<where>: ...") for any other failure.
std::unique_ptr<GlContext> make_osmesa_context(int width, int height, const std::string& where, std::string* missing);

// An EGL context (surfaceless or device platform) drawing into an FBO of its own; nullptr and
// `*missing` as above. Error("<where>: ...") for any other failure.
std::unique_ptr<GlContext> make_egl_context(int width, int height, const std::string& where, std::string* missing);

// Opens `env_var`'s library if set, else `soname`, for the process's life (never closed: GL's
// function pointers point into it). nullptr and `*missing` ("libX not found") when it cannot.
void* open_gl_library(const char* env_var, const char* soname, std::string* missing);
// The symbol `name` of `library` into `out`; Error("<where>: the <what> library has no <name>") when
// it is missing (a library that is not the backend it claims to be).
void* gl_library_symbol(void* library, const char* name, const std::string& where, const char* what);
template <typename F>
void bind_gl_symbol(void* library, const char* name, F& out, const std::string& where, const char* what) {
  out = reinterpret_cast<F>(gl_library_symbol(library, name, where, what));
}

// A colour (RGBA8) + depth24/stencil8 framebuffer object for a context without a default one.
// Needs the context current (GL loaded) to create, bind and delete it.
class OffscreenFramebuffer {
 public:
  // Creates and binds it for drawing and reading, and sets viewport and scissor to its size;
  // Error("<where>: framebuffer incomplete ...") when GL refuses it.
  OffscreenFramebuffer(int width, int height, const std::string& where);
  ~OffscreenFramebuffer();
  OffscreenFramebuffer(const OffscreenFramebuffer&) = delete;
  OffscreenFramebuffer& operator=(const OffscreenFramebuffer&) = delete;
  // Binds it for drawing and reading again (after another framebuffer was bound).
  void bind() const;

 private:
  void release();
  unsigned framebuffer_ = 0, colour_ = 0, depth_stencil_ = 0;
};

}  // namespace nbscope::render

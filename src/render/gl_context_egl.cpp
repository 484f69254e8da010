// The EGL context: libEGL.so.1 (glvnd's, from libegl1 — never libGL/GLX) loaded at run time, on
// the surfaceless platform (EGL_MESA_platform_surfaceless) or else a device of the device platform
// (EGL_EXT_platform_device), a GL 3.3 core context made current without a surface, drawing into an
// FBO of its own (a surfaceless context has no default framebuffer). glad loads GL through
// eglGetProcAddress; this file includes EGL's headers only, no GL.
#include "render/gl_offscreen.hpp"

#ifdef NBSCOPE_HAVE_EGL
#define EGL_NO_X11  // no X11 types in eglplatform.h: the headless path knows no display server
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <vector>
#endif

#include "core/error.hpp"

namespace nbscope::render {

#ifdef NBSCOPE_HAVE_EGL

namespace {

// The EGL entry points nbscope uses: EGL 1.5 core from the library, extensions through
// eglGetProcAddress (nullptr when not offered).
struct EglApi {
  decltype(&eglGetProcAddress) get_proc_address = nullptr;
  decltype(&eglQueryString) query_string = nullptr;
  decltype(&eglGetError) get_error = nullptr;
  decltype(&eglInitialize) initialize = nullptr;
  decltype(&eglBindAPI) bind_api = nullptr;
  decltype(&eglChooseConfig) choose_config = nullptr;
  decltype(&eglCreateContext) create_context = nullptr;
  decltype(&eglMakeCurrent) make_current = nullptr;
  decltype(&eglDestroyContext) destroy_context = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display = nullptr;
  PFNEGLQUERYDEVICESEXTPROC query_devices = nullptr;
};

const EglApi* egl_api(const std::string& where, std::string* missing) {
  static std::string why;
  static void* const library = open_gl_library("NBSCOPE_EGL_LIBRARY", "libEGL.so.1", &why);
  if (library == nullptr) {
    *missing = why;
    return nullptr;
  }
  static EglApi api;
  if (api.get_proc_address == nullptr) {
    bind_gl_symbol(library, "eglQueryString", api.query_string, where, "EGL");
    bind_gl_symbol(library, "eglGetError", api.get_error, where, "EGL");
    bind_gl_symbol(library, "eglInitialize", api.initialize, where, "EGL");
    bind_gl_symbol(library, "eglBindAPI", api.bind_api, where, "EGL");
    bind_gl_symbol(library, "eglChooseConfig", api.choose_config, where, "EGL");
    bind_gl_symbol(library, "eglCreateContext", api.create_context, where, "EGL");
    bind_gl_symbol(library, "eglMakeCurrent", api.make_current, where, "EGL");
    bind_gl_symbol(library, "eglDestroyContext", api.destroy_context, where, "EGL");
    bind_gl_symbol(library, "eglGetProcAddress", api.get_proc_address, where, "EGL");
    // EGL_EXT_platform_base's entry point takes the same arguments as 1.5's and is in every glvnd.
    api.get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(api.get_proc_address("eglGetPlatformDisplayEXT"));
    api.query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(api.get_proc_address("eglQueryDevicesEXT"));
  }
  return &api;
}

const EglApi* g_api = nullptr;  // set before any context exists; glad's loader needs it
void* egl_proc(const char* name) { return reinterpret_cast<void*>(g_api->get_proc_address(name)); }

// EGL's error code by name, for one-line messages.
std::string egl_error(const EglApi& api) {
  const EGLint code = api.get_error();
  switch (code) {
#define NBSCOPE_EGL_ERROR(e) \
  case e:                    \
    return #e;
    NBSCOPE_EGL_ERROR(EGL_SUCCESS)
    NBSCOPE_EGL_ERROR(EGL_NOT_INITIALIZED)
    NBSCOPE_EGL_ERROR(EGL_BAD_ACCESS)
    NBSCOPE_EGL_ERROR(EGL_BAD_ALLOC)
    NBSCOPE_EGL_ERROR(EGL_BAD_ATTRIBUTE)
    NBSCOPE_EGL_ERROR(EGL_BAD_CONFIG)
    NBSCOPE_EGL_ERROR(EGL_BAD_CONTEXT)
    NBSCOPE_EGL_ERROR(EGL_BAD_CURRENT_SURFACE)
    NBSCOPE_EGL_ERROR(EGL_BAD_DISPLAY)
    NBSCOPE_EGL_ERROR(EGL_BAD_MATCH)
    NBSCOPE_EGL_ERROR(EGL_BAD_NATIVE_PIXMAP)
    NBSCOPE_EGL_ERROR(EGL_BAD_NATIVE_WINDOW)
    NBSCOPE_EGL_ERROR(EGL_BAD_PARAMETER)
    NBSCOPE_EGL_ERROR(EGL_BAD_SURFACE)
    NBSCOPE_EGL_ERROR(EGL_CONTEXT_LOST)
    NBSCOPE_EGL_ERROR(EGL_BAD_DEVICE_EXT)
#undef NBSCOPE_EGL_ERROR
    default: {
      char buf[16];
      std::snprintf(buf, sizeof buf, "0x%04x", static_cast<unsigned>(code));
      return buf;
    }
  }
}

// True when the space-separated extension list `list` names `name`.
bool has_extension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

// An initialised display: the surfaceless platform's, else the first device's that initialises.
// Opened once per process and never terminated (EGL displays are not reference-counted, and
// another context may still use it).
EGLDisplay egl_display(const EglApi& api, const std::string& where) {
  static EGLDisplay display = EGL_NO_DISPLAY;
  if (display != EGL_NO_DISPLAY) return display;
  const char* client = api.query_string(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  const bool surfaceless = has_extension(client, "EGL_MESA_platform_surfaceless");
  const bool device = has_extension(client, "EGL_EXT_platform_device") && api.query_devices != nullptr;
  if (api.get_platform_display == nullptr || (!surfaceless && !device))
    throw Error(where + ": no EGL display (neither EGL_MESA_platform_surfaceless nor EGL_EXT_platform_device is offered)");
  std::string failure;
  const auto try_display = [&](EGLenum platform, void* native) {
    EGLDisplay d = api.get_platform_display(platform, native, nullptr);
    if (d == EGL_NO_DISPLAY) {
      failure = "eglGetPlatformDisplay failed (" + egl_error(api) + ")";
      return false;
    }
    EGLint major = 0, minor = 0;
    if (api.initialize(d, &major, &minor) != EGL_TRUE) {
      failure = "eglInitialize failed (" + egl_error(api) + ")";
      return false;
    }
    display = d;
    return true;
  };
  if (surfaceless && try_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY)) return display;
  if (device) {
    EGLint count = 0;
    if (api.query_devices(0, nullptr, &count) == EGL_TRUE && count > 0) {
      std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
      if (api.query_devices(count, devices.data(), &count) == EGL_TRUE)
        for (EGLint i = 0; i < count; ++i)
          if (try_display(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<std::size_t>(i)])) return display;
    } else if (failure.empty()) {
      failure = "no EGL device";
    }
  }
  throw Error(where + ": " + failure);
}

class EglContext final : public GlContext {
 public:
  EglContext(const EglApi& api, int width, int height, const std::string& where)
      : api_(api), width_(width), height_(height), where_(where) {
    display_ = egl_display(api_, where_);
    if (api_.bind_api(EGL_OPENGL_API) != EGL_TRUE)
      throw Error(where_ + ": eglBindAPI(EGL_OPENGL_API) failed (" + egl_error(api_) + ")");
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!has_extension(api_.query_string(display_, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
      // Any config that renders desktop GL; the FBO, not the config, decides the pixel format.
      const EGLint attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
      EGLint count = 0;
      if (api_.choose_config(display_, attribs, &config, 1, &count) != EGL_TRUE || count < 1)
        throw Error(where_ + ": no EGL config renders OpenGL (" + egl_error(api_) + ")");
    }
    const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                      3,
                                      EGL_CONTEXT_MINOR_VERSION,
                                      3,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                      EGL_NONE};
    context_ = api_.create_context(display_, config, EGL_NO_CONTEXT, context_attribs);
    if (context_ == EGL_NO_CONTEXT)
      throw Error(where_ + ": cannot create a GL 3.3 core context (" + egl_error(api_) + ")");
    try {
      make_current();  // loads GL through EGL
      framebuffer_ = std::make_unique<OffscreenFramebuffer>(width_, height_, where_);
    } catch (...) {
      release();
      throw;
    }
  }
  ~EglContext() override { release(); }
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  [[nodiscard]] const char* kind() const override { return "egl"; }
  [[nodiscard]] int width() const override { return width_; }
  [[nodiscard]] int height() const override { return height_; }
  void make_current() override {
    // The bound API is per thread, as is the current context.
    if (api_.bind_api(EGL_OPENGL_API) != EGL_TRUE ||
        api_.make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) != EGL_TRUE)
      throw Error(where_ + ": cannot make the context current without a surface (" + egl_error(api_) + ")");
    reload_gl_if_other(&egl_proc, where_.c_str());
    if (framebuffer_) framebuffer_->bind();
  }
  void present() override { gl_finish_all(); }

 private:
  void release() {
    if (context_ == EGL_NO_CONTEXT) return;
    // The FBO goes while its context is current; then nothing is left current on this thread.
    if (api_.make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) == EGL_TRUE) framebuffer_.reset();
    framebuffer_.release();  // its context is gone if it could not be made current
    api_.make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    api_.destroy_context(display_, context_);
    context_ = EGL_NO_CONTEXT;
  }

  const EglApi& api_;
  int width_, height_;
  std::string where_;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  std::unique_ptr<OffscreenFramebuffer> framebuffer_;
};

}  // namespace

std::unique_ptr<GlContext> make_egl_context(int width, int height, const std::string& where, std::string* missing) {
  const EglApi* api = egl_api(where, missing);
  if (api == nullptr) return nullptr;
  g_api = api;
  return std::make_unique<EglContext>(*api, width, height, where);
}

#else  // built without EGL/egl.h

std::unique_ptr<GlContext> make_egl_context(int, int, const std::string&, std::string* missing) {
  *missing = "not built (EGL/egl.h was not found when nbscope was configured)";
  return nullptr;
}

#endif

}  // namespace nbscope::render

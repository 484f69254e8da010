// The OSMesa context, loaded from libOSMesa.so.8 at run time (Mesa 25.1 and later ship none, and
// a binary built here must still run headless there, through EGL). This file includes OSMesa's
// header (and so GL/gl.h) for its types and constants only, and therefore no glad; it calls no gl*
// function itself, only OSMesa's through dlsym, and hands OSMesaGetProcAddress to glad.
#include "render/gl_offscreen.hpp"

#ifdef NBSCOPE_HAVE_OSMESA
#include <GL/osmesa.h>

#include <vector>
#endif

#include "core/error.hpp"

namespace nbscope::render {

#ifdef NBSCOPE_HAVE_OSMESA

namespace {

// The four OSMesa entry points nbscope uses, from the library opened once per process.
struct OsmesaApi {
  decltype(&OSMesaCreateContextAttribs) create_context_attribs = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaDestroyContext) destroy_context = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;
};

// nullptr (and `*missing`) when the library is not there; the same answer on every call.
const OsmesaApi* osmesa_api(const std::string& where, std::string* missing) {
  static std::string why;
  static void* const library = open_gl_library("NBSCOPE_OSMESA_LIBRARY", "libOSMesa.so.8", &why);
  if (library == nullptr) {
    *missing = why;
    return nullptr;
  }
  static OsmesaApi api;
  if (api.get_proc_address == nullptr) {
    bind_gl_symbol(library, "OSMesaCreateContextAttribs", api.create_context_attribs, where, "OSMesa");
    bind_gl_symbol(library, "OSMesaMakeCurrent", api.make_current, where, "OSMesa");
    bind_gl_symbol(library, "OSMesaDestroyContext", api.destroy_context, where, "OSMesa");
    bind_gl_symbol(library, "OSMesaGetProcAddress", api.get_proc_address, where, "OSMesa");
  }
  return &api;
}

const OsmesaApi* g_api = nullptr;  // set before any context exists; glad's loader needs it
void* osmesa_proc(const char* name) { return reinterpret_cast<void*>(g_api->get_proc_address(name)); }

class OsmesaContext final : public GlContext {
 public:
  OsmesaContext(const OsmesaApi& api, int width, int height, const std::string& where)
      : api_(api), width_(width), height_(height), where_(where) {
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
    context_ = api_.create_context_attribs(attribs, nullptr);
    if (context_ == nullptr) throw Error(where_ + ": cannot create a GL 3.3 core context");
    buffer_.resize(static_cast<std::size_t>(width) * height * 4);
    try {
      make_current();  // loads GL through OSMesa
    } catch (...) {
      if (context_ != nullptr) api_.destroy_context(context_);
      throw;
    }
  }
  ~OsmesaContext() override {
    if (context_ != nullptr) api_.destroy_context(context_);
  }
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  [[nodiscard]] const char* kind() const override { return "osmesa"; }
  [[nodiscard]] int width() const override { return width_; }
  [[nodiscard]] int height() const override { return height_; }
  void make_current() override {
    if (!api_.make_current(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
      api_.destroy_context(context_);
      context_ = nullptr;
      throw Error(where_ + ": cannot make the context current at " + std::to_string(width_) + "x" +
                  std::to_string(height_));
    }
    reload_gl_if_other(&osmesa_proc, where_.c_str());
  }
  void present() override { gl_finish_all(); }

 private:
  const OsmesaApi& api_;
  int width_, height_;
  std::string where_;
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<GlContext> make_osmesa_context(int width, int height, const std::string& where, std::string* missing) {
  const OsmesaApi* api = osmesa_api(where, missing);
  if (api == nullptr) return nullptr;
  g_api = api;
  return std::make_unique<OsmesaContext>(*api, width, height, where);
}

#else  // built without GL/osmesa.h

std::unique_ptr<GlContext> make_osmesa_context(int, int, const std::string&, std::string* missing) {
  *missing = "not built (GL/osmesa.h was not found when nbscope was configured)";
  return nullptr;
}

#endif

}  // namespace nbscope::render

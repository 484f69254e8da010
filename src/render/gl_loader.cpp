#include <cstdio>
#include <string>

#include "core/error.hpp"
#include "render/gl.hpp"
#include "render/gl_offscreen.hpp"

namespace nbscope::render {

namespace {
GlProcLoader g_loader = nullptr;
GLADapiproc call_loader(const char* name) { return reinterpret_cast<GLADapiproc>(g_loader(name)); }
}  // namespace

void load_gl(GlProcLoader loader, const char* where) {
  g_loader = loader;
  const int version = gladLoadGL(&call_loader);
  if (version == 0) throw Error(std::string(where) + ": cannot load OpenGL functions");
  if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33)
    throw Error(std::string(where) + ": OpenGL 3.3 core is required, the context offers " +
                std::to_string(GLAD_VERSION_MAJOR(version)) + "." + std::to_string(GLAD_VERSION_MINOR(version)));
}

void reload_gl_if_other(GlProcLoader loader, const char* where) {
  if (loader != g_loader) load_gl(loader, where);
}

void check_gl(const char* where) {
  const GLenum err = glGetError();
  if (err != GL_NO_ERROR) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "0x%04x", err);
    throw Error(std::string(where) + ": GL error " + buf);
  }
}

}  // namespace nbscope::render

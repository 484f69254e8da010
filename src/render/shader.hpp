// nbscope render: GLSL programs loaded from the shader directory at run time.
#pragma once
#include <string>

#include "render/gl.hpp"

namespace nbscope::render {

// The shader directory: `override_dir` if not empty, else $NBSCOPE_SHADER_DIR, else
// $NBSCOPE_DATA_DIR/shaders, else the installed one beside the binary, else the source tree's. Error("shaders: DIR: ...") when it
// is not a directory holding circle.vert.
std::string resolve_shader_dir(const std::string& override_dir);

// A linked GLSL program; owns the GL object (a GL context must be current).
class Program {
 public:
  Program() = default;
  // Compiles DIR/NAME.vert and DIR/NAME.frag and links them; Error names the file and the log.
  Program(const std::string& dir, const std::string& name);
  Program(Program&& other) noexcept : id_(other.id_) { other.id_ = 0; }
  Program& operator=(Program&& other) noexcept;
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;
  ~Program();

  [[nodiscard]] GLuint id() const { return id_; }
  // Location of a uniform (-1 when the compiler removed it).
  [[nodiscard]] GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

 private:
  GLuint id_ = 0;
};

}  // namespace nbscope::render

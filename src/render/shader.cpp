#include "render/shader.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/error.hpp"
#include "io/data_dir.hpp"

namespace nbscope::render {

namespace {

std::string read_source(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("shaders: " + path + ": cannot read the file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// First line of a GL info log, trimmed: keeps the error to one line.
std::string first_line(std::string log) {
  const auto nl = log.find('\n');
  if (nl != std::string::npos) log.resize(nl);
  while (!log.empty() && (log.back() == '\r' || log.back() == ' ')) log.pop_back();
  return log.empty() ? "unknown error" : log;
}

GLuint compile(GLenum kind, const std::string& path) {
  const std::string source = read_source(path);
  const GLuint shader = glCreateShader(kind);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(std::max(length, 1)));
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    throw Error("shaders: " + path + ": does not compile: " + first_line(log.data()));
  }
  return shader;
}

}  // namespace

std::string resolve_shader_dir(const std::string& override_dir) {
  std::string dir = override_dir;
  if (dir.empty()) dir = default_shader_dir().path;  // $NBSCOPE_SHADER_DIR, else the data directory's
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw Error("shaders: " + dir + ": no such directory (use --shader-dir, NBSCOPE_SHADER_DIR or NBSCOPE_DATA_DIR)");
  if (!std::filesystem::is_regular_file(dir + "/circle.vert", ec))
    throw Error("shaders: " + dir + ": holds no nbscope shaders (circle.vert is missing)");
  return dir;
}

Program::Program(const std::string& dir, const std::string& name) {
  const std::string base = dir + "/" + name;
  const GLuint vs = compile(GL_VERTEX_SHADER, base + ".vert");
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, base + ".frag");
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glLinkProgram(id_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(std::max(length, 1)));
    glGetProgramInfoLog(id_, length, nullptr, log.data());
    glDeleteProgram(id_);
    id_ = 0;
    throw Error("shaders: " + base + ": does not link: " + first_line(log.data()));
  }
}

Program& Program::operator=(Program&& other) noexcept {
  if (this != &other) {
    if (id_ != 0) glDeleteProgram(id_);
    id_ = other.id_;
    other.id_ = 0;
  }
  return *this;
}

Program::~Program() {
  if (id_ != 0) glDeleteProgram(id_);
}

}  // namespace nbscope::render

#include "viz/gl_program.hpp"

#include <stdexcept>
#include <vector>

namespace firn::viz {
namespace {

// Throws `failure` and the driver's log, after deleting the object, unless its `status` is set:
// `get` is glGetShaderiv or glGetProgramiv, `log` and `destroy` the matching functions.
template <class Get, class Log, class Destroy>
void require(GLuint id, GLenum status, Get get, Log log, Destroy destroy, const std::string& failure) {
  GLint ok = 0, length = 0;
  get(id, status, &ok);
  if (ok) return;
  get(id, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> text(std::size_t(length) + 1);
  log(id, length, nullptr, text.data());
  destroy(id);
  throw std::runtime_error(failure + ": " + text.data());
}

}  // namespace

GLuint GlProgram::compile(GLenum type, const std::string& source, const std::string& name) const {
  const GLuint s = gl_.glCreateShader(type);
  const char* text = source.c_str();
  gl_.glShaderSource(s, 1, &text, nullptr);
  gl_.glCompileShader(s);
  require(s, GL_COMPILE_STATUS, gl_.glGetShaderiv, gl_.glGetShaderInfoLog, gl_.glDeleteShader,
          "shader " + name + (type == GL_VERTEX_SHADER ? " (vertex)" : " (fragment)") + " does not compile");
  return s;
}

GlProgram::GlProgram(const Gl& gl, const std::string& name, const std::string& vertex, const std::string& fragment)
    : gl_(gl) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex, name), fs = compile(GL_FRAGMENT_SHADER, fragment, name);
  id_ = gl_.glCreateProgram();
  gl_.glAttachShader(id_, vs);
  gl_.glAttachShader(id_, fs);
  gl_.glLinkProgram(id_);
  gl_.glDeleteShader(vs);
  gl_.glDeleteShader(fs);
  require(id_, GL_LINK_STATUS, gl_.glGetProgramiv, gl_.glGetProgramInfoLog, gl_.glDeleteProgram,
          "shader program " + name + " does not link");
}

GlProgram::~GlProgram() { gl_.glDeleteProgram(id_); }

}  // namespace firn::viz

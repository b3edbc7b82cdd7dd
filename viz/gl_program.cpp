#include "viz/gl_program.hpp"

#include <stdexcept>
#include <vector>

namespace firn::viz {

GLuint GlProgram::compile(GLenum type, const std::string& source, const std::string& name) const {
  const GLuint s = gl_.glCreateShader(type);
  const char* text = source.c_str();
  gl_.glShaderSource(s, 1, &text, nullptr);
  gl_.glCompileShader(s);
  GLint ok = 0, length = 0;
  gl_.glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    gl_.glGetShaderiv(s, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(std::size_t(length) + 1);
    gl_.glGetShaderInfoLog(s, length, nullptr, log.data());
    gl_.glDeleteShader(s);
    throw std::runtime_error("shader " + name + (type == GL_VERTEX_SHADER ? " (vertex)" : " (fragment)") +
                             " does not compile: " + log.data());
  }
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
  GLint ok = 0, length = 0;
  gl_.glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    gl_.glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(std::size_t(length) + 1);
    gl_.glGetProgramInfoLog(id_, length, nullptr, log.data());
    gl_.glDeleteProgram(id_);
    throw std::runtime_error("shader program " + name + " does not link: " + log.data());
  }
}

GlProgram::~GlProgram() { gl_.glDeleteProgram(id_); }

}  // namespace firn::viz

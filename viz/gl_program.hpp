// A linked GLSL program and its uniforms by name.
#pragma once

#include <string>

#include "viz/gl_functions.hpp"
#include "viz/mat4.hpp"

namespace firn::viz {

class GlProgram {
 public:
  // Compiles and links; throws std::runtime_error with the driver's log naming `name`.
  GlProgram(const Gl& gl, const std::string& name, const std::string& vertex, const std::string& fragment);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  void use() const { gl_.glUseProgram(id_); }
  // Setters for the program in use; a uniform the compiler removed is silently skipped.
  void set(const char* name, int v) const { gl_.glUniform1i(location(name), v); }
  void set(const char* name, float v) const { gl_.glUniform1f(location(name), v); }
  void set(const char* name, float a, float b) const { gl_.glUniform2f(location(name), a, b); }
  void set(const char* name, int a, int b) const { gl_.glUniform2i(location(name), a, b); }
  void set(const char* name, const float v[3]) const { gl_.glUniform3fv(location(name), 1, v); }
  void set(const char* name, const Mat4& m) const { gl_.glUniformMatrix4fv(location(name), 1, GL_FALSE, m.m.data()); }

 private:
  GLint location(const char* name) const { return gl_.glGetUniformLocation(id_, name); }
  GLuint compile(GLenum type, const std::string& source, const std::string& name) const;

  const Gl& gl_;
  GLuint id_ = 0;
};

}  // namespace firn::viz

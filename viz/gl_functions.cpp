#include "viz/gl_functions.hpp"

#include <stdexcept>

namespace firn::viz {

void Gl::require(bool present, const char* name) {
  if (!present) throw std::runtime_error(std::string("OpenGL entry point ") + name + " is missing");
}

void Gl::check(const char* what) const {
  const GLenum e = glGetError();
  if (e != GL_NO_ERROR) throw std::runtime_error(std::string("OpenGL error ") + std::to_string(e) + " in " + what);
}

}  // namespace firn::viz

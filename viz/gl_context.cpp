#include "viz/gl_context.hpp"

#include <stdexcept>

namespace firn::viz {

GlApi parse_gl_api(const std::string& name) {
  if (name.empty()) return GlApi::automatic;
  if (name == "egl") return GlApi::egl;
  if (name == "osmesa") return GlApi::osmesa;
  throw std::invalid_argument("unknown OpenGL API '" + name + "' (egl or osmesa)");
}

std::string GlContext::description() const {
  auto text = [&](GLenum what) {
    const GLubyte* s = gl_.glGetString(what);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return api() + ": OpenGL " + text(GL_VERSION) + ", " + text(GL_RENDERER);
}

std::unique_ptr<GlContext> make_gl_context(GlApi api) {
  if (api == GlApi::egl) return make_egl_context();
  if (api == GlApi::osmesa) return make_osmesa_context();
  try {
    return make_egl_context();
  } catch (const std::exception& egl) {
    try {
      return make_osmesa_context();
    } catch (const std::exception& osmesa) {
      throw std::runtime_error(std::string("no OpenGL context: EGL: ") + egl.what() + "; OSMesa: " + osmesa.what());
    }
  }
}

}  // namespace firn::viz

// A headless OpenGL context (DESIGN.md section 7): EGL on a GPU's device platform or on Mesa's
// surfaceless platform, or OSMesa; core profile 4.5 where the driver gives it, else the highest
// core profile down to 3.3. The renderer draws into its own framebuffer objects, so neither
// context needs a window or a default framebuffer of a useful size.
#pragma once

#include <memory>
#include <string>

#include "viz/gl_functions.hpp"

namespace firn::viz {

enum class GlApi { automatic, egl, osmesa };

// "egl", "osmesa" or "" (automatic); throws std::invalid_argument otherwise.
GlApi parse_gl_api(const std::string& name);

class GlContext {
 public:
  virtual ~GlContext() = default;
  const Gl& gl() const { return gl_; }
  // e.g. "egl surfaceless: 4.5 (Core Profile) Mesa 22.3.6, llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string description() const;
  virtual std::string api() const = 0;

 protected:
  Gl gl_;
};

std::unique_ptr<GlContext> make_egl_context();
std::unique_ptr<GlContext> make_osmesa_context();

// `automatic` tries EGL and falls back to OSMesa; throws std::runtime_error with both reasons if
// neither can be made.
std::unique_ptr<GlContext> make_gl_context(GlApi api);

}  // namespace firn::viz

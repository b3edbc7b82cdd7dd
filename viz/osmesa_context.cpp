// Mesa's off-screen context (OSMesa), the fallback when EGL fails: a core-profile context made
// current on a small client-memory buffer that nothing reads; all drawing goes to framebuffer
// objects. Mesa's OSMesaCreateContextAttribs takes the profile and version (GL/osmesa.h).
#include <stdexcept>
#include <vector>

#include "viz/core_profile_versions.hpp"
#include "viz/gl_context.hpp"
#include "viz/shared_library.hpp"
// After glcorearb.h, so that the legacy GL/gl.h that osmesa.h includes finds it declared.
#include <GL/osmesa.h>

namespace firn::viz {
namespace {

using CreateContextAttribs = OSMesaContext (*)(const int*, OSMesaContext);
using MakeCurrent = GLboolean (*)(OSMesaContext, void*, GLenum, GLsizei, GLsizei);
using DestroyContext = void (*)(OSMesaContext);
using GetProcAddress = OSMESAproc (*)(const char*);

class OsMesaContext : public GlContext {
 public:
  OsMesaContext() : lib_({"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"}) {
    auto create = lib_.function<CreateContextAttribs>("OSMesaCreateContextAttribs");
    auto make_current = lib_.function<MakeCurrent>("OSMesaMakeCurrent");
    auto get_proc = lib_.function<GetProcAddress>("OSMesaGetProcAddress");
    for (const GlVersion v : kCoreProfileVersions) {
      const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                             OSMESA_CONTEXT_MAJOR_VERSION, v.major, OSMESA_CONTEXT_MINOR_VERSION, v.minor, 0};
      context_ = create(attribs, nullptr);
      if (context_) break;
    }
    if (!context_) throw std::runtime_error("OSMesa cannot create an OpenGL 3.3+ core context");
    if (!make_current(context_, buffer_.data(), GL_UNSIGNED_BYTE, kSide, kSide)) {
      release();
      throw std::runtime_error("OSMesaMakeCurrent failed");
    }
    gl_.load([&](const char* name) { return reinterpret_cast<void*>(get_proc(name)); });
  }

  ~OsMesaContext() override { release(); }

  std::string api() const override { return "osmesa"; }

 private:
  // Unbinds the context from this thread (so that Mesa drops its framebuffer for our buffer) and
  // destroys it. What Mesa keeps after that (its compiler's and driver's state, loaded once per
  // process) is the library's own: tests/lsan_suppressions.txt.
  void release() {
    lib_.function<MakeCurrent>("OSMesaMakeCurrent")(nullptr, nullptr, 0, 0, 0);
    lib_.function<DestroyContext>("OSMesaDestroyContext")(context_);
  }

  static constexpr int kSide = 16;
  SharedLibrary lib_;
  std::vector<unsigned char> buffer_ = std::vector<unsigned char>(4 * kSide * kSide);
  OSMesaContext context_ = nullptr;
};

}  // namespace

std::unique_ptr<GlContext> make_osmesa_context() { return std::make_unique<OsMesaContext>(); }

}  // namespace firn::viz

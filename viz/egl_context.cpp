// EGL without a window: the device platform (EGL_EXT_platform_device) when a hardware device is
// enumerated, else Mesa's surfaceless platform (EGL_MESA_platform_surfaceless), which on a machine
// with no GPU runs llvmpipe. The context is made current with no surface
// (EGL_KHR_surfaceless_context); all drawing goes to framebuffer objects.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <stdexcept>
#include <string>

#include "viz/core_profile_versions.hpp"
#include "viz/gl_context.hpp"
#include "viz/shared_library.hpp"

namespace firn::viz {
namespace {

class EglContext : public GlContext {
 public:
  EglContext() : lib_({"libEGL.so.1", "libEGL.so"}) {
    get_proc_ = lib_.function<PFNEGLGETPROCADDRESSPROC>("eglGetProcAddress");
    auto initialize = lib_.function<PFNEGLINITIALIZEPROC>("eglInitialize");
    auto bind_api = lib_.function<PFNEGLBINDAPIPROC>("eglBindAPI");
    auto choose_config = lib_.function<PFNEGLCHOOSECONFIGPROC>("eglChooseConfig");
    auto create_context = lib_.function<PFNEGLCREATECONTEXTPROC>("eglCreateContext");
    auto make_current = lib_.function<PFNEGLMAKECURRENTPROC>("eglMakeCurrent");
    auto get_error = lib_.function<PFNEGLGETERRORPROC>("eglGetError");
    auto query_string = lib_.function<PFNEGLQUERYSTRINGPROC>("eglQueryString");

    const char* client = query_string(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto has = [](const char* list, const char* ext) { return list && std::strstr(list, ext) != nullptr; };
    auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(get_proc_("eglGetPlatformDisplayEXT"));
    if (!get_platform_display || !has(client, "EGL_EXT_platform_base"))
      throw std::runtime_error("EGL lacks EGL_EXT_platform_base");

    display_ = hardware_device_display(get_platform_display, client);
    if (display_ == EGL_NO_DISPLAY) {
      if (!has(client, "EGL_MESA_platform_surfaceless")) throw std::runtime_error("EGL lacks the surfaceless platform");
      display_ = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      platform_ = "surfaceless";
    }
    EGLint major = 0, minor = 0;
    if (display_ == EGL_NO_DISPLAY || !initialize(display_, &major, &minor))
      throw std::runtime_error("eglInitialize failed (error " + std::to_string(get_error()) + ")");
    if (!bind_api(EGL_OPENGL_API)) throw std::runtime_error("EGL cannot bind the OpenGL API");
    // No surface will be made, so no config is needed where EGL_KHR_no_config_context allows it.
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!has(query_string(display_, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) {
      const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
      EGLint configs = 0;
      if (!choose_config(display_, config_attribs, &config, 1, &configs) || configs < 1)
        throw std::runtime_error("EGL has no OpenGL config");
    }
    for (const GlVersion v : kCoreProfileVersions) {
      const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, v.major, EGL_CONTEXT_MINOR_VERSION, v.minor,
                                EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
      context_ = create_context(display_, config, EGL_NO_CONTEXT, attribs);
      if (context_ != EGL_NO_CONTEXT) break;
    }
    if (context_ == EGL_NO_CONTEXT) throw std::runtime_error("EGL cannot create an OpenGL 3.3+ core context");
    if (!make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw std::runtime_error("eglMakeCurrent without a surface failed (error " + std::to_string(get_error()) + ")");
    gl_.load([this](const char* name) { return get_proc_(name); });
  }

  ~EglContext() override {
    lib_.function<PFNEGLMAKECURRENTPROC>("eglMakeCurrent")(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    lib_.function<PFNEGLDESTROYCONTEXTPROC>("eglDestroyContext")(display_, context_);
  }

  std::string api() const override { return "egl " + platform_; }

 private:
  // The first enumerated device that is not Mesa's software device, or EGL_NO_DISPLAY.
  EGLDisplay hardware_device_display(PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display, const char* client) {
    if (!client || !std::strstr(client, "EGL_EXT_platform_device")) return EGL_NO_DISPLAY;
    auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(get_proc_("eglQueryDevicesEXT"));
    auto device_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(get_proc_("eglQueryDeviceStringEXT"));
    if (!query_devices || !device_string) return EGL_NO_DISPLAY;
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (!query_devices(16, devices, &count)) return EGL_NO_DISPLAY;
    for (EGLint i = 0; i < count; ++i) {
      const char* ext = device_string(devices[i], EGL_EXTENSIONS);
      if (ext && std::strstr(ext, "EGL_MESA_device_software")) continue;
      platform_ = "device";
      return get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
    }
    return EGL_NO_DISPLAY;
  }

  SharedLibrary lib_;
  PFNEGLGETPROCADDRESSPROC get_proc_ = nullptr;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  std::string platform_;
};

}  // namespace

std::unique_ptr<GlContext> make_egl_context() { return std::make_unique<EglContext>(); }

}  // namespace firn::viz

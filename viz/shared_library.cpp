#include "viz/shared_library.hpp"

#include <dlfcn.h>

#include <stdexcept>

namespace firn::viz {

SharedLibrary::SharedLibrary(const std::vector<std::string>& names) {
  std::string tried;
  for (const std::string& n : names) {
    handle_ = ::dlopen(n.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle_) {
      name_ = n;
      return;
    }
    tried += (tried.empty() ? "" : ", ") + n;
  }
  throw std::runtime_error("cannot load " + tried + " (" + ::dlerror() + ")");
}

void* SharedLibrary::symbol(const char* name) const {
  void* s = ::dlsym(handle_, name);
  if (!s) throw std::runtime_error(name_ + " has no " + name);
  return s;
}

}  // namespace firn::viz

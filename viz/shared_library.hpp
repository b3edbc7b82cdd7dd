// A shared library opened at run time (dlopen), so that firn builds and runs without libEGL or
// libOSMesa installed and only a run that renders needs them. It is never closed: Mesa's drivers
// keep thread-local state and exit handlers that must outlive the process's last use of GL.
#pragma once

#include <string>
#include <vector>

namespace firn::viz {

class SharedLibrary {
 public:
  // Opens the first of `names` that loads; throws std::runtime_error listing them otherwise.
  explicit SharedLibrary(const std::vector<std::string>& names);
  SharedLibrary(const SharedLibrary&) = delete;
  SharedLibrary& operator=(const SharedLibrary&) = delete;

  // The symbol's address; throws std::runtime_error if the library lacks it.
  void* symbol(const char* name) const;
  template <class F>
  F function(const char* name) const {
    return reinterpret_cast<F>(symbol(name));
  }

 private:
  void* handle_ = nullptr;
  std::string name_;
};

}  // namespace firn::viz

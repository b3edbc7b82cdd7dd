#include "engine/backend_kind.hpp"

#include <stdexcept>

#include "engine/cuda_device.hpp"

namespace firn {

const char* backend_name(BackendKind kind) {
  switch (kind) {
    case BackendKind::serial: return "serial";
    case BackendKind::cuda: return "cuda";
    case BackendKind::openmp: break;
  }
  return "openmp";
}

BackendKind backend_named(const std::string& name) {
  for (BackendKind kind : {BackendKind::serial, BackendKind::openmp, BackendKind::cuda})
    if (name == backend_name(kind)) return kind;
  throw std::invalid_argument("unknown backend '" + name + "' (serial, openmp or cuda)");
}

std::string backend_unavailable(BackendKind kind) { return kind == BackendKind::cuda ? cuda_unavailable_reason() : ""; }

}  // namespace firn

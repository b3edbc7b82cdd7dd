#include <cuda_runtime.h>

#include "engine/cuda_device.hpp"

namespace firn {

std::string cuda_unavailable_reason() {
  int count = 0;
  if (cudaGetDeviceCount(&count) != cudaSuccess || count == 0) return "no CUDA device";
  // The backend's buffers are managed memory (kernels/backend/cuda.hpp).
  int managed = 0;
  if (cudaDeviceGetAttribute(&managed, cudaDevAttrManagedMemory, 0) != cudaSuccess || !managed)
    return "the CUDA device does not support managed memory, which the CUDA backend's buffers use";
  return "";
}

}  // namespace firn

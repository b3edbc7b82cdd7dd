#include <cuda_runtime.h>

#include "engine/cuda_device.hpp"

namespace firn {

std::string cuda_unavailable_reason() {
  int count = 0;
  if (cudaGetDeviceCount(&count) != cudaSuccess || count == 0) return "no CUDA device";
  // Until particle storage and the grid live in device memory (issue 14, item 3), kernels read and
  // write the host's arrays: the device must access pageable host memory (HMM or ATS).
  int pageable = 0;
  if (cudaDeviceGetAttribute(&pageable, cudaDevAttrPageableMemoryAccess, 0) != cudaSuccess || !pageable)
    return "the CUDA device cannot access pageable host memory (HMM), which the CUDA backend needs for now";
  return "";
}

}  // namespace firn

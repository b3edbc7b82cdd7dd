// Runs code written once for any backend on the backend chosen at run time: with_backend(kind,
// threads, run) calls run(backend) with backend::Serial, backend::OpenMP (`threads`, 0: all cores)
// or backend::Cuda, with the backend's memory space as the default (memory_space.hpp). The CUDA
// backend exists only in translation units that nvcc compiles (FIRN_CUDA builds list them in
// CMakeLists.txt); elsewhere asking for it throws, with the line that backend_unavailable gives,
// which the commands print before they get this far.
#pragma once

#include <stdexcept>

#include "engine/backend_kind.hpp"
#include "kernels/backend/openmp.hpp"
#include "kernels/backend/serial.hpp"
#if defined(__CUDACC__)
#include "kernels/backend/cuda.hpp"
#endif

namespace firn {

template <class Backend, class Run>
auto run_in_memory_of(const Backend& backend, Run& run) {
  const backend::UseMemorySpace memory(Backend::memory());
  return run(backend);
}

template <class Run>
auto with_backend(BackendKind kind, int threads, Run&& run) {
  if (kind == BackendKind::serial) return run_in_memory_of(backend::Serial{}, run);
  if (kind == BackendKind::cuda) {
#if defined(__CUDACC__)
    return run_in_memory_of(backend::Cuda{}, run);
#else
    throw std::runtime_error(backend_unavailable(kind));
#endif
  }
  return run_in_memory_of(backend::OpenMP(threads), run);
}

}  // namespace firn

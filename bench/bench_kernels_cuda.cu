// The step's kernels (bench/step_kernels.hpp) on the CUDA backend, in builds with it; they report
// "no CUDA device" where none is found.
#include "bench/step_kernels.hpp"
#include "kernels/backend/cuda.hpp"

namespace firn::bench_kernels {
namespace {

const bool registered = [] {
  register_step_kernels<backend::Cuda>([](const benchmark::State&) { return backend::Cuda{}; });
  return true;
}();

}  // namespace
}  // namespace firn::bench_kernels

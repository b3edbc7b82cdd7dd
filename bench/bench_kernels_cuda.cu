// The step's kernels (bench/step_kernels.hpp) on the CUDA backend, in builds with it, over the
// 64,000-particle cube and (suffix /512k) a 512,000-particle one; they report "no CUDA device"
// where none is found. kernel/p2g/cuda_atomic times the P2G scatter with float atomics
// (backend::ScatterOrder::atomic) beside the deterministic one, to measure what determinism costs,
// and kernel/p2g/cuda_64threads the deterministic one with 64 threads per block (one per staged
// particle) against the default 256.
#include "bench/step_kernels.hpp"
#include "kernels/backend/cuda.hpp"

namespace firn::bench_kernels {
namespace {

const bool registered = [] {
  const auto fixed = [](const benchmark::State&) { return backend::Cuda{}; };
  const auto atomic = [](const benchmark::State&) {
    backend::Cuda cuda;
    cuda.scatter_order = backend::ScatterOrder::atomic;
    return cuda;
  };
  register_step_kernels<backend::Cuda>(fixed);
  register_step_kernels<backend::Cuda>(fixed, {}, kLargeSide, "/512k");
  const auto narrow = [](const benchmark::State&) {
    backend::Cuda cuda;
    cuda.scatter_block_threads = 64;
    return cuda;
  };
  for (const auto& [side, suffix] : {std::pair{kSide, ""}, std::pair{kLargeSide, "/512k"}}) {
    register_step_kernel<backend::Cuda>(std::string("kernel/p2g/cuda_atomic") + suffix, "p2g", "neo_hookean", side, atomic);
    register_step_kernel<backend::Cuda>(std::string("kernel/p2g/cuda_64threads") + suffix, "p2g", "neo_hookean", side,
                                        narrow);
  }
  return true;
}();

}  // namespace
}  // namespace firn::bench_kernels

// A build without FIRN_CUDA: the commands refuse --backend cuda before they get here
// (apps/backend_option.hpp), so this only completes the link.
#include <stdexcept>

#include "engine/cuda_device.hpp"
#include "studies/bench/step_benchmark_impl.hpp"

namespace firn::bench {

StepBenchmarkResult benchmark_step_cuda(const StepBenchmarkOptions&) {
  throw std::runtime_error(cuda_unavailable_reason());
}

}  // namespace firn::bench

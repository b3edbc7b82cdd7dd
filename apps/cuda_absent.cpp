// A build without FIRN_CUDA: the commands refuse --backend cuda before they get here
// (apps/backend_option.hpp), so this only completes the link.
#include <stdexcept>

#include "apps/bench_step.hpp"
#include "engine/cuda_device.hpp"

namespace firn::app {

void bench_step_cuda(const BenchStepOptions&) { throw std::runtime_error(cuda_unavailable_reason()); }

}  // namespace firn::app

#include "apps/bench_step.hpp"
#include "kernels/backend/cuda.hpp"

namespace firn::app {

void bench_step_cuda(const BenchStepOptions& o) { bench_step_on(o, backend::Cuda{}); }

}  // namespace firn::app

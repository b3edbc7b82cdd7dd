#include "studies/bench/step_benchmark.hpp"

#include "kernels/backend/cuda.hpp"

namespace firn::bench {

void bench_step_cuda(const BenchStepOptions& o) { bench_step_on(o, backend::Cuda{}); }

}  // namespace firn::bench

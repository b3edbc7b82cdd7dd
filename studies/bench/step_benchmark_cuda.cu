#include "studies/bench/step_benchmark_impl.hpp"

#include "kernels/backend/cuda.hpp"

namespace firn::bench {

StepBenchmarkResult benchmark_step_cuda(const StepBenchmarkOptions& o) {
  return benchmark_step_on(o, backend::Cuda{});
}

}  // namespace firn::bench

#include "studies/bench/step_benchmark.hpp"

#include "kernels/backend/openmp.hpp"
#include "studies/bench/step_benchmark_impl.hpp"

namespace firn::bench {

StepBenchmarkResult benchmark_step(const StepBenchmarkOptions& o) {
  switch (o.backend) {
    case BackendKind::serial: return benchmark_step_serial(o);
    case BackendKind::cuda: return benchmark_step_cuda(o);
    case BackendKind::openmp: break;
  }
  return benchmark_step_on(o, backend::OpenMP(o.threads));
}

}  // namespace firn::bench

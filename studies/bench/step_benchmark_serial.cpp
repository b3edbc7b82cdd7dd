#include "studies/bench/step_benchmark_impl.hpp"

#include "kernels/backend/serial.hpp"

namespace firn::bench {

StepBenchmarkResult benchmark_step_serial(const StepBenchmarkOptions& o) {
  return benchmark_step_on(o, backend::Serial{});
}

}  // namespace firn::bench

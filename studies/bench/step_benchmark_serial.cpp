#include "studies/bench/step_benchmark.hpp"

#include "kernels/backend/serial.hpp"

namespace firn::bench {

void bench_step_serial(const BenchStepOptions& o) { bench_step_on(o, backend::Serial{}); }

}  // namespace firn::bench

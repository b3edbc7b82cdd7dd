#include "apps/bench_step.hpp"
#include "kernels/backend/serial.hpp"

namespace firn::app {

void bench_step_serial(const BenchStepOptions& o) { bench_step_on(o, backend::Serial{}); }

}  // namespace firn::app

// The step's kernels (bench/step_kernels.hpp) on the serial backend and on OpenMP with 1 and 2
// threads (the argument):
//   build/release/bench/firn_bench_kernels --benchmark_filter='p2g/openmp'
#include "bench/step_kernels.hpp"
#include "kernels/backend/openmp.hpp"
#include "kernels/backend/serial.hpp"

namespace firn::bench_kernels {
namespace {

const bool registered = [] {
  register_step_kernels<backend::Serial>([](const benchmark::State&) { return backend::Serial{}; });
  register_step_kernels<backend::OpenMP>([](const benchmark::State& s) { return backend::OpenMP(int(s.range(0))); },
                                         {1, 2});
  return true;
}();

}  // namespace
}  // namespace firn::bench_kernels

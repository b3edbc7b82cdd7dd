// The backend-parameterised tests (tests/backend_cases.hpp) on the CPU backends.
#include "kernels/backend/openmp.hpp"
#include "kernels/backend/serial.hpp"
#include "tests/backend_cases.hpp"

namespace firn {

using CpuBackends = ::testing::Types<backend::Serial, backend::OpenMP>;
INSTANTIATE_TYPED_TEST_SUITE_P(Cpu, BackendCases, CpuBackends);

}  // namespace firn

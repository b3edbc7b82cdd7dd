// The backend-parameterised tests (tests/backend_cases.hpp) on the CUDA backend; they skip where no
// CUDA device is found.
#include "kernels/backend/cuda.hpp"
#include "tests/backend_cases.hpp"

namespace firn {

INSTANTIATE_TYPED_TEST_SUITE_P(Cuda, BackendCases, ::testing::Types<backend::Cuda>);

}  // namespace firn

// The backend-parameterised tests (tests/backend_cases.hpp) on the CUDA backend, and the CUDA
// scatter's launch choices; they skip where no CUDA device is found.
#include "kernels/backend/cuda.hpp"
#include "tests/backend_cases.hpp"

namespace firn {

INSTANTIATE_TYPED_TEST_SUITE_P(Cuda, BackendCases, ::testing::Types<backend::Cuda>);

class CudaScatter : public BackendCases<backend::Cuda> {};

// The fixed-order scatter adds in the same order whatever the block's thread count.
TEST_F(CudaScatter, ThreadsPerBlockKeepTheBits) {
  backend::Cuda narrow;
  narrow.scatter_block_threads = 64;
  for (const Shape shape : {Shape::quadratic, Shape::cubic})
    EXPECT_EQ(run_two_bodies(narrow, Transfer::apic, shape).hash,
              run_two_bodies(backend::Cuda{}, Transfer::apic, shape).hash);
}

// The float-atomic order (kept to measure what determinism costs) reaches the OpenMP state to
// rounding, as the fixed order does; its bits may change from run to run.
TEST_F(CudaScatter, AtomicOrderAgreesWithOpenMP) {
  backend::Cuda atomic;
  atomic.scatter_order = backend::ScatterOrder::atomic;
  for (const Transfer transfer : {Transfer::apic, Transfer::flip})
    for (const Shape shape : {Shape::quadratic, Shape::cubic})
      expect_openmp_positions(run_two_bodies(atomic, transfer, shape), transfer, shape);
}

}  // namespace firn

// Tests written once per backend (DESIGN.md section 8, the Kokkos/Cabana way): each backend's
// launches and the whole step through it. Instantiated for serial and OpenMP by
// test_backend_cases.cpp and for CUDA by test_backend_cases_cuda.cu (FIRN_CUDA builds); an instance
// whose backend cannot run here (no CUDA device) skips, saying why.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "engine/aligned_vector.hpp"
#include "engine/backend_kind.hpp"
#include "kernels/combine.hpp"
#include "kernels/hd.hpp"
#include "tests/two_bodies.hpp"

namespace firn {

// out[i] = i^2.
struct SquareInto {
  long* out;
  FIRN_HD void operator()(std::size_t i) const { out[i] = long(i) * long(i); }
};

// Partial sums of the harmonic series, H_n = ln n + 0.5772...
struct HarmonicTerm {
  FIRN_HD void operator()(std::size_t i, float& acc) const { acc += 1.0f / float(i + 1); }
};

// Each case runs with its backend's memory space as the default, as the commands do.
template <class Backend>
class BackendCases : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string why = backend_unavailable(backend_named(Backend::kName));
    if (!why.empty()) GTEST_SKIP() << Backend::kName << ": " << why;
  }
  const backend::UseMemorySpace memory_{Backend::memory()};
};

TYPED_TEST_SUITE_P(BackendCases);

TYPED_TEST_P(BackendCases, ParallelForReachesEveryItem) {
  const std::size_t n = 100003;
  AlignedVector<long> out(n, -1);
  TypeParam{}.parallel_for("square", n, SquareInto{out.data()});
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(out[i], long(i) * long(i)) << "item " << i;
}

TYPED_TEST_P(BackendCases, ParallelReduceRepeatsItsBits) {
  const std::size_t n = 100003;  // several chunks and thread blocks, not a multiple of either
  const float first = TypeParam{}.parallel_reduce("sum", n, 0.0f, HarmonicTerm{}, Sum{});
  EXPECT_NEAR(first, 12.09, 0.01);
  EXPECT_EQ(TypeParam{}.parallel_reduce("sum", n, 0.0f, HarmonicTerm{}, Sum{}), first);
  EXPECT_EQ(TypeParam{}.parallel_reduce("empty", 0, 5.0f, HarmonicTerm{}, Sum{}), 5.0f);
}

// The whole step (binning, constitutive update, the P2G scatter, the grid update, the G2P gather):
// the same state on two runs, and the OpenMP backend's to rounding (1e-3 of a cell).
TYPED_TEST_P(BackendCases, StepRepeatsAndAgreesWithOpenMP) {
  for (const Transfer transfer : {Transfer::apic, Transfer::flip})
    for (const Shape shape : {Shape::quadratic, Shape::cubic}) {
      const TwoBodiesOutcome a = run_two_bodies(TypeParam{}, transfer, shape);
      EXPECT_EQ(run_two_bodies(TypeParam{}, transfer, shape).hash, a.hash);
      const TwoBodiesOutcome reference = openmp_two_bodies(transfer, shape);
      ASSERT_EQ(reference.positions.size(), a.positions.size());
      for (std::size_t i = 0; i < a.positions.size(); ++i)
        ASSERT_NEAR(reference.positions[i], a.positions[i], 1e-5f) << "coordinate " << i;
    }
}

REGISTER_TYPED_TEST_SUITE_P(BackendCases, ParallelForReachesEveryItem, ParallelReduceRepeatsItsBits,
                            StepRepeatsAndAgreesWithOpenMP);

}  // namespace firn

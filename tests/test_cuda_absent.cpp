// A build without FIRN_CUDA has no CUDA instances of tests/backend_cases.hpp; this says so in the
// test report and checks the one line the commands answer --backend cuda with.
#include <gtest/gtest.h>

#include "engine/backend_kind.hpp"

namespace firn {

TEST(CudaBackend, AbsentFromThisBuild) {
  EXPECT_EQ(backend_unavailable(BackendKind::cuda), "this build has no CUDA backend");
  GTEST_SKIP() << "this build has no CUDA backend";
}

}  // namespace firn

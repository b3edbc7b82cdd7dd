// The known-answer problems of `firn verify` (DESIGN.md section 6): every error within its bound.
#include <gtest/gtest.h>

#include "engine/verification/verification.hpp"

namespace firn {
namespace {

class Verification : public ::testing::TestWithParam<std::string> {};

TEST_P(Verification, ErrorsWithinBounds) {
  const std::vector<VerificationRow> rows = run_verification(GetParam(), {});
  ASSERT_FALSE(rows.empty());
  for (const VerificationRow& r : rows)
    EXPECT_TRUE(r.passed()) << r.problem << " level " << r.level << ": error " << r.error << " > bound " << r.bound;
}

INSTANTIATE_TEST_SUITE_P(Problems, Verification, ::testing::ValuesIn(verification_problems()));

TEST(Verification, RejectsUnknownProblem) { EXPECT_THROW(run_verification("nope", {}), std::invalid_argument); }

}  // namespace
}  // namespace firn

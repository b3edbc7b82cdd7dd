// J2 hardening laws (linear, thesis Eq. 4.5 nonlinear, floor) and the safeguarded Newton solve of the
// radial-return consistency equation (kernels/constitutive/j2_hardening.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "kernels/constitutive/j2_hardening.hpp"

namespace firn {
namespace {

const double kSqrt23 = std::sqrt(2.0 / 3.0);

double residual(const J2Hardening<double>& h, double alpha_n, double s_norm, double mu_bar, double dgamma) {
  return s_norm - 2 * mu_bar * dgamma - kSqrt23 * h.yield_stress(alpha_n + kSqrt23 * dgamma);
}

TEST(J2Hardening, LinearLaw) {
  const J2Hardening<double> h{HardeningLaw::linear, 100, 5e3, 0, 0, 0};
  EXPECT_DOUBLE_EQ(h.yield_stress(0), 100);
  EXPECT_DOUBLE_EQ(h.yield_stress(0.02), 100 + 5e3 * 0.02);
  EXPECT_DOUBLE_EQ(h.slope(0.3), 5e3);
}

TEST(J2Hardening, NonlinearLawAndSlope) {
  const J2Hardening<double> h{HardeningLaw::nonlinear, 100, 0, 15, 0.02, 0};  // thesis shell
  EXPECT_DOUBLE_EQ(h.yield_stress(0), 100);
  EXPECT_NEAR(h.yield_stress(0.5), 100 * std::pow(1 + 15 * 0.5, 0.02), 1e-12);
  for (double a : {0.0, 0.01, 0.3, 2.0}) {
    const double d = 1e-6;
    EXPECT_NEAR(h.slope(a), (h.yield_stress(a + d) - h.yield_stress(a - d)) / (2 * d),
                1e-6 * std::abs(h.slope(a)) + 1e-9)
        << "alpha " << a;
  }
}

TEST(J2Hardening, NegativeKhSoftensToTheFloor) {
  const J2Hardening<double> h{HardeningLaw::nonlinear, 100, 0, -2, 0.5, 20};
  EXPECT_NEAR(h.yield_stress(0.2), 100 * std::sqrt(1 - 0.4), 1e-12);
  EXPECT_LT(h.slope(0.2), 0);
  // 100 sqrt(1 - 2 alpha) = 20 at alpha = 0.48; beyond, and past 1 + K_h alpha = 0, the floor holds.
  EXPECT_DOUBLE_EQ(h.yield_stress(0.49), 20);
  EXPECT_DOUBLE_EQ(h.yield_stress(0.7), 20);
  EXPECT_DOUBLE_EQ(h.slope(0.7), 0);
  const J2Hardening<double> linear{HardeningLaw::linear, 100, -1e3, 0, 0, 30};
  EXPECT_DOUBLE_EQ(linear.yield_stress(0.05), 50);
  EXPECT_DOUBLE_EQ(linear.yield_stress(0.2), 30);
}

TEST(J2Return, LinearHardeningHasClosedForm) {
  // f linear in dgamma: dgamma = (s - sqrt(2/3) sigma_y(alpha_n)) / (2 mu_bar + 2/3 E_p).
  const J2Hardening<double> h{HardeningLaw::linear, 100, 5e3, 0, 0, 0};
  const double alpha_n = 0.01, s = 900, mu_bar = 6e4;
  const J2ReturnSolution<double> r = solve_j2_return(h, alpha_n, s, mu_bar);
  EXPECT_NEAR(r.dgamma, (s - kSqrt23 * h.yield_stress(alpha_n)) / (2 * mu_bar + 2.0 / 3 * 5e3), 1e-15);
  EXPECT_LE(r.iterations, 4);
}

TEST(J2Return, SolvesEveryLawWithinTheBracket) {
  const J2Hardening<double> laws[] = {
      {HardeningLaw::nonlinear, 100, 0, 15, 0.02, 0},   // thesis shell
      {HardeningLaw::nonlinear, 100, 0, -5, 0.8, 10},   // softening onto the floor
      {HardeningLaw::nonlinear, 100, 0, -50, 0.0, 10},  // n = 0: a jump to the floor
      {HardeningLaw::linear, 100, -2e5, 0, 0, 5},       // softening faster than 2 mu_bar: f rises
      {HardeningLaw::nonlinear, 100, 0, 1e3, 1.0, 0},   // steep hardening
  };
  for (const auto& h : laws)
    for (double s : {82.0, 200.0, 1e4, 1e7}) {
      const double mu_bar = 5e4, alpha_n = 0;
      if (residual(h, alpha_n, s, mu_bar, 0) <= 0) continue;
      const J2ReturnSolution<double> r = solve_j2_return(h, alpha_n, s, mu_bar);
      EXPECT_GE(r.dgamma, 0);
      EXPECT_LE(r.dgamma, s / (2 * mu_bar));
      EXPECT_LT(r.iterations, 200);
      // A root, or (where f jumps) a point where f changes sign within rounding of dgamma.
      const double f = residual(h, alpha_n, s, mu_bar, r.dgamma);
      const double step = 4e-16 * std::max(r.dgamma, 1e-300);
      const bool root = std::abs(f) <= 1e-12 * s;
      const bool jump =
          residual(h, alpha_n, s, mu_bar, r.dgamma - step) * residual(h, alpha_n, s, mu_bar, r.dgamma + step) <= 0;
      EXPECT_TRUE(root || jump) << "law " << int(h.law) << " K_h " << h.K_h << " s " << s << " f " << f;
    }
}

TEST(J2Return, FloatConverges) {
  const J2Hardening<float> h{HardeningLaw::nonlinear, 100.f, 0.f, 15.f, 0.02f, 0.f};
  const float s = 500.f, mu_bar = 5.83e4f;
  const J2ReturnSolution<float> r = solve_j2_return(h, 0.f, s, mu_bar);
  const float f = s - 2 * mu_bar * r.dgamma - std::sqrt(2.f / 3.f) * h.yield_stress(std::sqrt(2.f / 3.f) * r.dgamma);
  EXPECT_LE(std::abs(f), 1e-5f * s);
  EXPECT_LT(r.iterations, 20);
}

}  // namespace
}  // namespace firn

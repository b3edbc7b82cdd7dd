// Mooney-Rivlin elasticity (thesis Eq. 4.1-4.4) and the hyperelastic-plastic return (Simo and Hughes
// Box 9.1 with the J-consistent b_e update): closed-form stresses, tau = (dW/dF) F^T by central
// differences, and the returned state on the yield surface with det F_E kept, at J from 0.3 to 1.5.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "kernels/constitutive/hyperelastic_plastic.hpp"
#include "kernels/constitutive/mooney_rivlin.hpp"
#include "kernels/svd3.hpp"
#include "tests/constitutive_checks.hpp"

namespace firn {
namespace {

constexpr double kK = 78e3, kG = 58.3e3;  // thesis Table 4.2, shell

Mat3<double> random_F(std::mt19937& rng, double spread) {
  std::uniform_real_distribution<double> d(-spread, spread);
  Mat3<double> F = Mat3<double>::identity();
  for (double& x : F.m) x += d(rng);
  return F;
}

Mat3<double> scaled_to_J(const Mat3<double>& F, double J) { return std::cbrt(J / determinant(F)) * F; }

double dev_norm(const Mat3<double>& a) {
  Mat3<double> d = a;
  for (int i = 0; i < 3; ++i) d(i, i) -= trace(a) / 3;
  return std::sqrt(ddot(d, d));
}

TEST(MooneyRivlin, UndeformedIsStressFree) {
  const MooneyRivlin<double> m{kK, 0.7 * kG, 0.3 * kG};
  for (double t : m.kirchhoff(Mat3<double>::identity()).m) EXPECT_EQ(t, 0);
  EXPECT_NEAR(m.energy_density(Mat3<double>::identity()), 0, 1e-12);
}

TEST(MooneyRivlin, DiagonalStretchClosedForm) {
  // Principal stretches l_i: b_i = l_i^2, I1 = sum b_i, tau_i = K/2 (J^2 - 1) + G1 J^(-2/3) (b_i - I1/3)
  // + G2 J^(-4/3) (a_i - sum a / 3) with a_i = I1 b_i - b_i^2.
  const double G1 = 2e4, G2 = 1e4;
  const MooneyRivlin<double> m{kK, G1, G2};
  const double l[3] = {1.3, 0.8, 0.9}, J = l[0] * l[1] * l[2];
  const double b[3] = {l[0] * l[0], l[1] * l[1], l[2] * l[2]}, I1 = b[0] + b[1] + b[2];
  double a[3], a_sum = 0;
  for (int i = 0; i < 3; ++i) a_sum += a[i] = I1 * b[i] - b[i] * b[i];
  const Mat3<double> tau = m.kirchhoff(Mat3<double>::diag(l[0], l[1], l[2]));
  for (int i = 0; i < 3; ++i) {
    const double exact = kK / 2 * (J * J - 1) + G1 * std::pow(J, -2.0 / 3) * (b[i] - I1 / 3) +
                         G2 * std::pow(J, -4.0 / 3) * (a[i] - a_sum / 3);
    EXPECT_NEAR(tau(i, i), exact, 1e-9 * kK);
  }
  EXPECT_EQ(tau(0, 1), 0);
}

TEST(MooneyRivlin, StressIsEnergyDerivative) {
  std::mt19937 rng(3);
  const MooneyRivlin<double> m{kK, 0.6 * kG, 0.4 * kG};
  for (int i = 0; i < 40; ++i) expect_stress_is_energy_derivative(m, random_F(rng, 0.3), kK + kG);
}

HyperelasticPlastic<double> shell(double G2 = 0) {
  return {{kK, kG - G2, G2}, {HardeningLaw::nonlinear, 100, 0, 15, 0.02, 0}};
}

TEST(HyperelasticPlastic, ElasticBranchIsMooneyRivlinAndEnergyDerivative) {
  std::mt19937 rng(5);
  const HyperelasticPlastic<double> m = shell(0.2 * kG);
  for (int i = 0; i < 20; ++i) expect_stress_is_energy_derivative(m, random_F(rng, 0.2), kK + kG);
  EXPECT_DOUBLE_EQ(m.p_wave_modulus({}), kK + 4 * kG / 3);
}

TEST(HyperelasticPlastic, ElasticStateIsLeftUntouched) {
  // Inside the yield surface project() must return F and alpha bit for bit (no SVD round trip).
  const HyperelasticPlastic<double> m = shell();
  Mat3<double> F = 0.5 * Mat3<double>::identity();
  F(0, 1) = 2e-4;  // small shear at J = 0.125
  const Mat3<double> before = F;
  PlasticState<double> s;
  s.alpha = 0.1;
  ASSERT_LT(m.yield_function(F, s), 0);
  m.project(F, s);
  for (int q = 0; q < 9; ++q) EXPECT_EQ(F.m[q], before.m[q]);
  EXPECT_EQ(s.alpha, 0.1);
}

// After a return from any trial state at any J: det F_E unchanged, ||dev tau|| = sqrt(2/3) sigma_y(alpha_new)
// from the stress recomputed by kirchhoff(F_new) (i.e. the b_e update is consistent with the returned
// stress), alpha grown by the plastic increment, and the rotation U V^T of F_E kept.
TEST(HyperelasticPlastic, ReturnLandsOnYieldSurfaceAtAnyJ) {
  std::mt19937 rng(17);
  const HyperelasticPlastic<double> m = shell();
  int returns = 0;
  for (double J : {0.3, 0.5, 1.0, 1.5})
    for (int i = 0; i < 25; ++i) {
      Mat3<double> F = scaled_to_J(random_F(rng, 0.25), J);
      PlasticState<double> s;
      s.alpha = 0.01 * (i % 5);
      ASSERT_GT(m.yield_function(F, s), 0);
      const double alpha_before = s.alpha;
      const Mat3<double> R_before = polar_rotation(F);
      m.project(F, s);
      ++returns;
      EXPECT_NEAR(determinant(F), J, 1e-14 * J);
      const double target = std::sqrt(2.0 / 3) * m.hardening.yield_stress(s.alpha);
      EXPECT_NEAR(dev_norm(m.kirchhoff(F, s)), target, 1e-10 * target) << "J " << J << " sample " << i;
      EXPECT_GT(s.alpha, alpha_before);
      const Mat3<double> R_after = polar_rotation(F);
      for (int q = 0; q < 9; ++q) EXPECT_NEAR(R_after.m[q], R_before.m[q], 1e-12);
      // A second projection finds the state on the surface: nothing left to return.
      const Mat3<double> F_again = F;
      const double alpha_again = s.alpha;
      m.project(F, s);
      for (int q = 0; q < 9; ++q) EXPECT_NEAR(F.m[q], F_again.m[q], 1e-12);
      EXPECT_NEAR(s.alpha, alpha_again, 1e-12);
    }
  EXPECT_EQ(returns, 100);
}

TEST(HyperelasticPlastic, DeviatoricStressOfReturnIsRadial) {
  // s_new = (1 - beta) s_trial: the returned deviatoric stress is parallel to the trial one.
  const HyperelasticPlastic<double> m = shell();
  Mat3<double> F = scaled_to_J(Mat3<double>{{1.1, 0.2, 0.05, -0.1, 0.9, 0.1, 0.0, 0.15, 1.05}}, 0.3);
  Mat3<double> dev_trial = m.kirchhoff(F, {});
  PlasticState<double> s;
  m.project(F, s);
  Mat3<double> dev_new = m.kirchhoff(F, s);
  const double p_trial = trace(dev_trial) / 3, p_new = trace(dev_new) / 3;
  for (int d = 0; d < 3; ++d) {
    dev_trial(d, d) -= p_trial;
    dev_new(d, d) -= p_new;
  }
  const double ratio = dev_norm(dev_new) / dev_norm(dev_trial);
  for (int q = 0; q < 9; ++q) EXPECT_NEAR(dev_new.m[q], ratio * dev_trial.m[q], 1e-10 * dev_norm(dev_new));
}

TEST(HyperelasticPlastic, WithG2TheG1PartLandsOnYieldSurface) {
  const HyperelasticPlastic<double> m = shell(0.3 * kG);
  Mat3<double> F = scaled_to_J(Mat3<double>{{1.2, 0.3, 0.0, 0.0, 0.9, 0.1, 0.05, 0.0, 1.0}}, 0.5);
  PlasticState<double> s;
  m.project(F, s);
  EXPECT_NEAR(m.yield_function(F, s), 0, 1e-10 * m.hardening.yield_stress(s.alpha));
  EXPECT_NEAR(determinant(F), 0.5, 1e-14);
}

TEST(HyperelasticPlastic, FloatReturnIsSane) {
  const HyperelasticPlastic<float> m{{float(kK), float(kG), 0.f},
                                     {HardeningLaw::nonlinear, 100.f, 0.f, 15.f, 0.02f, 0.f}};
  Mat3<float> F = Mat3<float>{{0.75f, 0.1f, 0.0f, 0.0f, 0.7f, 0.05f, 0.0f, 0.0f, 0.6f}};
  const float J = determinant(F);
  PlasticState<float> s;
  m.project(F, s);
  const Mat3<float> tau = m.kirchhoff(F, s);
  Mat3<float> dev = tau;
  for (int d = 0; d < 3; ++d) dev(d, d) -= trace(tau) / 3;
  const float target = std::sqrt(2.f / 3.f) * m.hardening.yield_stress(s.alpha);
  EXPECT_NEAR(std::sqrt(ddot(dev, dev)), target, 1e-3f * target);
  EXPECT_NEAR(determinant(F), J, 1e-5f * J);
  EXPECT_GT(s.alpha, 0.f);
}

}  // namespace
}  // namespace firn

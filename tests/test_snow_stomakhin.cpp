// Stomakhin snow (Stomakhin et al. 2013; thesis Eq. 4.6): hardened fixed-corotated stress, the
// singular-value clamp, J_P bookkeeping det(F_E) J_P = J, the optional J_P clamp, float precision.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "kernels/constitutive/fixed_corotated.hpp"
#include "kernels/constitutive/snow_stomakhin.hpp"
#include "tests/constitutive_checks.hpp"

namespace firn {
namespace {

// Table 4.1: E0 = 1.4e5 Pa, nu = 0.2 -> mu = E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - 2 nu)).
constexpr double kE = 1.4e5, kNu = 0.2;
constexpr double kMu = kE / (2 * (1 + kNu)), kLambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu));
const double kInf = std::numeric_limits<double>::infinity();

SnowStomakhin<double> table_4_1(double Jp_min = 0, double Jp_max = kInf) {
  return {kMu, kLambda, 10, 2.5e-2, 7.5e-3, Jp_min, Jp_max};
}

TEST(SnowStomakhin, StressIsHardenedFixedCorotated) {
  const SnowStomakhin<double> m = table_4_1();
  PlasticState<double> s;
  s.Jp = 0.95;
  const double h = std::exp(10 * (1 - 0.95));
  const Mat3<double> F = {{1.01, 0.002, 0, -0.003, 0.99, 0.001, 0, 0.002, 1.004}};
  const Mat3<double> expected = FixedCorotated<double>{h * kMu, h * kLambda}.kirchhoff(F);
  const Mat3<double> tau = m.kirchhoff(F, s);
  for (int q = 0; q < 9; ++q) EXPECT_NEAR(tau.m[q], expected.m[q], 1e-12 * h * kMu);
  EXPECT_NEAR(m.p_wave_modulus(s), (kLambda + 2 * kMu) * h, 1e-9);
  // Diagonal closed form: tau_ii = 2 mu h (s_i - 1) s_i + lambda h (J - 1) J.
  const double a = 0.98, J = a;
  EXPECT_NEAR(m.kirchhoff(Mat3<double>::diag(a, 1, 1), s)(0, 0), 2 * kMu * h * (a - 1) * a + kLambda * h * (J - 1) * J,
              1e-9);
}

TEST(SnowStomakhin, StressIsEnergyDerivative) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> d(-0.02, 0.02);
  const SnowStomakhin<double> m = table_4_1();
  PlasticState<double> s;
  s.Jp = 0.9;
  for (int i = 0; i < 20; ++i) {
    Mat3<double> F = Mat3<double>::identity();
    for (double& x : F.m) x += d(rng);
    expect_stress_is_energy_derivative(m, F, std::exp(1.0) * (kMu + kLambda), s, 1e-7);
  }
}

TEST(SnowStomakhin, ClampAndJpBookkeeping) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> d(-0.15, 0.15);
  const SnowStomakhin<double> m = table_4_1();
  PlasticState<double> s;
  s.Jp = 1.0;
  Mat3<double> F_total = Mat3<double>::identity();
  Mat3<double> F = F_total;
  int clamped = 0;
  for (int i = 0; i < 200; ++i) {
    // A random increment applied to F_E and to the total F, as the engine's G2P does.
    Mat3<double> inc = Mat3<double>::identity();
    for (double& x : inc.m) x += 0.1 * d(rng);
    F = inc * F;
    F_total = inc * F_total;
    const double Jp_before = s.Jp, J_trial = determinant(F);
    m.project(F, s);
    if (s.Jp != Jp_before) ++clamped;
    EXPECT_NEAR(determinant(F) * s.Jp / determinant(F_total), 1, 1e-12);
    EXPECT_NEAR(determinant(F) * s.Jp / Jp_before, J_trial, 1e-12 * J_trial);
    Mat3<double> U, V;
    Vec3<double> sig;
    svd3(F, U, sig, V);
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(sig[k], 1 - 2.5e-2 - 1e-14);
      EXPECT_LE(sig[k], 1 + 7.5e-3 + 1e-14);
    }
  }
  EXPECT_GT(clamped, 50);  // the walk left the elastic range most of the time
}

TEST(SnowStomakhin, InsideTheClampNothingChanges) {
  const SnowStomakhin<double> m = table_4_1();
  Mat3<double> F = {{1.005, 0.001, 0, 0, 0.99, 0, 0.002, 0, 0.98}};
  const Mat3<double> before = F;
  PlasticState<double> s;
  m.project(F, s);
  for (int q = 0; q < 9; ++q) EXPECT_EQ(F.m[q], before.m[q]);
  EXPECT_EQ(s.Jp, 1);
}

TEST(SnowStomakhin, UniaxialCompressionClampsTheSingularValue) {
  const SnowStomakhin<double> m = table_4_1();
  Mat3<double> F = Mat3<double>::diag(0.9, 1, 1);
  PlasticState<double> s;
  m.project(F, s);
  EXPECT_NEAR(F(0, 0), 1 - 2.5e-2, 1e-14);
  EXPECT_NEAR(F(1, 1), 1, 1e-14);
  EXPECT_NEAR(s.Jp, 0.9 / (1 - 2.5e-2), 1e-14);
}

TEST(SnowStomakhin, JpClampBoundsHardening) {
  const SnowStomakhin<double> m = table_4_1(0.95, 1.05);
  Mat3<double> F = Mat3<double>::diag(0.8, 1, 1);
  PlasticState<double> s;
  m.project(F, s);
  EXPECT_EQ(s.Jp, 0.95);
  F = Mat3<double>::diag(1.3, 1.3, 1.3);
  m.project(F, s);
  EXPECT_EQ(s.Jp, 1.05);
}

TEST(SnowStomakhin, FloatProjectIsSane) {
  const SnowStomakhin<float> m{float(kMu), float(kLambda), 10.f, 2.5e-2f, 7.5e-3f, 0.f, 1e30f};
  Mat3<float> F = {{0.9f, 0.05f, 0.f, 0.f, 1.05f, 0.02f, 0.f, 0.f, 0.97f}};
  const float J = determinant(F);
  PlasticState<float> s;
  m.project(F, s);
  EXPECT_NEAR(determinant(F) * s.Jp, J, 1e-5f);
  EXPECT_TRUE(std::isfinite(m.kirchhoff(F, s)(0, 0)));
}

}  // namespace
}  // namespace firn

// Constitutive models: closed-form values, and tau = P F^T with P = dW/dF checked by central
// differences of the energy, including inverted deformation for fixed-corotated, and the
// bimodular model's softer (or absent) response in compression.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "kernels/constitutive/bimodular.hpp"
#include "kernels/constitutive/fixed_corotated.hpp"
#include "kernels/constitutive/neo_hookean.hpp"
#include "tests/constitutive_checks.hpp"

namespace firn {
namespace {

constexpr double kMu = 3.0e4, kLambda = 5.0e4;

// tau compared with (dW/dF) F^T from central differences of energy_density.
TEST(NeoHookean, UndeformedIsStressFree) {
  const NeoHookean<double> m{kMu, kLambda};
  const Mat3<double> tau = m.kirchhoff(Mat3<double>::identity());
  for (double t : tau.m) EXPECT_NEAR(t, 0, 1e-9);
  EXPECT_NEAR(m.energy_density(Mat3<double>::identity()), 0, 1e-9);
}

TEST(NeoHookean, UniaxialStretch) {
  const NeoHookean<double> m{kMu, kLambda};
  const double a = 1.2;
  const Mat3<double> tau = m.kirchhoff(Mat3<double>::diag(a, 1, 1));
  EXPECT_NEAR(tau(0, 0), kMu * (a * a - 1) + kLambda * std::log(a), 1e-8);
  EXPECT_NEAR(tau(1, 1), kLambda * std::log(a), 1e-8);
  EXPECT_NEAR(tau(0, 1), 0, 1e-12);
}

TEST(NeoHookean, StressIsEnergyDerivative) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-0.3, 0.3);
  const NeoHookean<double> m{kMu, kLambda};
  for (int i = 0; i < 50; ++i) {
    Mat3<double> F = Mat3<double>::identity();
    for (double& x : F.m) x += d(rng);
    expect_stress_is_energy_derivative(m, F, kMu + kLambda);
  }
}

TEST(FixedCorotated, RotationIsStressFree) {
  const FixedCorotated<double> m{kMu, kLambda};
  const Mat3<double> tau = m.kirchhoff(axis_angle_rotation<double>({{1, 2, 3}}, 0.7));
  for (double t : tau.m) EXPECT_NEAR(t, 0, 1e-9);
}

TEST(FixedCorotated, DiagonalStretch) {
  const FixedCorotated<double> m{kMu, kLambda};
  const double a = 1.1, b = 0.9, c = 1.05, J = a * b * c;
  const Mat3<double> tau = m.kirchhoff(Mat3<double>::diag(a, b, c));
  EXPECT_NEAR(tau(0, 0), 2 * kMu * (a - 1) * a + kLambda * (J - 1) * J, 1e-8);
  EXPECT_NEAR(tau(1, 1), 2 * kMu * (b - 1) * b + kLambda * (J - 1) * J, 1e-8);
  EXPECT_NEAR(tau(2, 2), 2 * kMu * (c - 1) * c + kLambda * (J - 1) * J, 1e-8);
  EXPECT_NEAR(m.energy_density(Mat3<double>::diag(a, b, c)),
              kMu * ((a - 1) * (a - 1) + (b - 1) * (b - 1) + (c - 1) * (c - 1)) + 0.5 * kLambda * (J - 1) * (J - 1),
              1e-8);
}

// tau(R F) = R tau(F) R^T for a turn R about a skew axis.
template <class Model>
void expect_rotated_stretch_is_covariant(const Model& m, const Mat3<double>& F) {
  const Mat3<double> R = axis_angle_rotation<double>({{-1, 0.5, 2}}, 1.1);
  const Mat3<double> lhs = m.kirchhoff(R * F);
  const Mat3<double> rhs = mul_transposed(R * m.kirchhoff(F), R);
  for (int q = 0; q < 9; ++q) EXPECT_NEAR(lhs.m[q], rhs.m[q], 1e-8 * kMu);
}

TEST(FixedCorotated, RotatedStretchIsCovariant) {
  expect_rotated_stretch_is_covariant(FixedCorotated<double>{kMu, kLambda},
                                      {{1.1, 0.2, 0.0, -0.1, 0.9, 0.05, 0.0, 0.1, 1.2}});
}

TEST(FixedCorotated, StressIsEnergyDerivativeIncludingInverted) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> d(-0.3, 0.3);
  const FixedCorotated<double> m{kMu, kLambda};
  for (int i = 0; i < 50; ++i) {
    Mat3<double> F = Mat3<double>::identity();
    for (double& x : F.m) x += d(rng);
    if (i % 2) F = Mat3<double>::diag(-1, 1, 1) * F;  // inverted: det F < 0
    expect_stress_is_energy_derivative(m, F, kMu + kLambda);
  }
}

TEST(Bimodular, StretchIsHenckyAndCompressionIsSofter) {
  // Stretched along x, shortened along y and z, ln J > 0: Hencky's moduli on the stretch and the
  // volume change, c times them on the shortenings. With c = 0, tension only.
  for (const double c : {0.0, 0.05}) {
    const Bimodular<double> m{kMu, kLambda, c};
    const double a = 1.3, b = 0.95, d = 0.98, lnJ = std::log(a * b * d);
    const Mat3<double> tau = m.kirchhoff(Mat3<double>::diag(a, b, d));
    EXPECT_NEAR(tau(0, 0), 2 * kMu * std::log(a) + kLambda * lnJ, 1e-8);
    EXPECT_NEAR(tau(1, 1), 2 * kMu * c * std::log(b) + kLambda * lnJ, 1e-8);
    EXPECT_NEAR(tau(2, 2), 2 * kMu * c * std::log(d) + kLambda * lnJ, 1e-8);
    EXPECT_NEAR(tau(0, 1), 0, 1e-8);
    EXPECT_NEAR(m.energy_density(Mat3<double>::diag(a, b, d)),
                kMu * (std::log(a) * std::log(a) + c * std::log(b) * std::log(b) + c * std::log(d) * std::log(d)) +
                    0.5 * kLambda * lnJ * lnJ,
                1e-8);
    // Shortened along every axis: c times Hencky's stress, none at all for c = 0.
    const Mat3<double> squeezed = Mat3<double>::diag(0.9, 0.95, 0.99);
    const double lnJs = std::log(0.9 * 0.95 * 0.99);
    EXPECT_NEAR(m.kirchhoff(squeezed)(0, 0), c * (2 * kMu * std::log(0.9) + kLambda * lnJs), 1e-8);
  }
  // Tension only: compressed, collapsed or inverted, no stress and no NaN.
  const Bimodular<double> slack{kMu, kLambda, 0};
  for (const Mat3<double>& F :
       {Mat3<double>::diag(1, 0.8, 1), Mat3<double>::diag(1, 1, 0), Mat3<double>::diag(0.9, 0.9, -0.5)}) {
    for (double t : slack.kirchhoff(F).m) EXPECT_EQ(t, 0);
    EXPECT_EQ(slack.energy_density(F), 0);
  }
}

TEST(Bimodular, RotatedStretchIsCovariant) {
  expect_rotated_stretch_is_covariant(Bimodular<double>{kMu, kLambda, 0.05},
                                      {{1.2, 0.1, 0.0, -0.1, 0.9, 0.05, 0.0, 0.1, 1.1}});
}

TEST(Bimodular, StressIsEnergyDerivative) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> d(-0.3, 0.3);
  for (const double c : {0.0, 0.05, 1.0}) {
    const Bimodular<double> m{kMu, kLambda, c};
    for (int i = 0; i < 50; ++i) {
      Mat3<double> F = Mat3<double>::identity();
      for (double& x : F.m) x += d(rng);
      expect_stress_is_energy_derivative(m, F, kMu + kLambda);
    }
  }
}

}  // namespace
}  // namespace firn

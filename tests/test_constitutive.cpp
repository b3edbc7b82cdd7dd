// Constitutive models: closed-form values, and tau = P F^T with P = dW/dF checked by central
// differences of the energy, including inverted deformation for fixed-corotated.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "kernels/constitutive/fixed_corotated.hpp"
#include "kernels/constitutive/neo_hookean.hpp"

namespace firn {
namespace {

constexpr double kMu = 3.0e4, kLambda = 5.0e4;

Mat3<double> rotation(double angle, const Vec3<double>& axis_in) {
  const double n = norm(axis_in);
  const Vec3<double> a = {{axis_in[0] / n, axis_in[1] / n, axis_in[2] / n}};
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  return Mat3<double>{{t * a[0] * a[0] + c, t * a[0] * a[1] - s * a[2], t * a[0] * a[2] + s * a[1],
                       t * a[0] * a[1] + s * a[2], t * a[1] * a[1] + c, t * a[1] * a[2] - s * a[0],
                       t * a[0] * a[2] - s * a[1], t * a[1] * a[2] + s * a[0], t * a[2] * a[2] + c}};
}

// tau compared with (dW/dF) F^T from central differences of energy_density.
template <class Model>
void expect_stress_is_energy_derivative(const Model& model, const Mat3<double>& F) {
  const double h = 1e-6;
  Mat3<double> P;
  for (int q = 0; q < 9; ++q) {
    Mat3<double> Fp = F, Fm = F;
    Fp.m[q] += h;
    Fm.m[q] -= h;
    P.m[q] = (model.energy_density(Fp) - model.energy_density(Fm)) / (2 * h);
  }
  const Mat3<double> expected = mul_transposed(P, F);
  const Mat3<double> tau = model.kirchhoff(F);
  const double scale = kMu + kLambda;
  for (int q = 0; q < 9; ++q) EXPECT_NEAR(tau.m[q], expected.m[q], 1e-5 * scale) << "component " << q;
}

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
    expect_stress_is_energy_derivative(m, F);
  }
}

TEST(FixedCorotated, RotationIsStressFree) {
  const FixedCorotated<double> m{kMu, kLambda};
  const Mat3<double> tau = m.kirchhoff(rotation(0.7, {{1, 2, 3}}));
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

TEST(FixedCorotated, RotatedStretchIsCovariant) {
  // tau(R F) = R tau(F) R^T.
  const FixedCorotated<double> m{kMu, kLambda};
  const Mat3<double> F = {{1.1, 0.2, 0.0, -0.1, 0.9, 0.05, 0.0, 0.1, 1.2}};
  const Mat3<double> R = rotation(1.1, {{-1, 0.5, 2}});
  const Mat3<double> lhs = m.kirchhoff(R * F);
  const Mat3<double> rhs = mul_transposed(R * m.kirchhoff(F), R);
  for (int q = 0; q < 9; ++q) EXPECT_NEAR(lhs.m[q], rhs.m[q], 1e-8 * kMu);
}

TEST(FixedCorotated, StressIsEnergyDerivativeIncludingInverted) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> d(-0.3, 0.3);
  const FixedCorotated<double> m{kMu, kLambda};
  for (int i = 0; i < 50; ++i) {
    Mat3<double> F = Mat3<double>::identity();
    for (double& x : F.m) x += d(rng);
    if (i % 2) F = Mat3<double>::diag(-1, 1, 1) * F;  // inverted: det F < 0
    expect_stress_is_energy_derivative(m, F);
  }
}

}  // namespace
}  // namespace firn

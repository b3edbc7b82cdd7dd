// The SVD-free pieces of the plastic returns (kernels/constitutive/deviator_rescale.hpp): the
// eigenvalues of a symmetric 3x3 tensor, its square root on both sides of the near-identity series'
// radius (squared back to A, continuous across the switch, repeated and widely spread eigenvalues),
// and the rescale itself (det F = J_new, dev(bbar) = keep dev(bbar_tr), the trial rotation kept);
// the lane form's series in D against the scalar rescale up to its radius, where it hands lanes back.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "kernels/constitutive/deviator_rescale.hpp"
#include "kernels/svd3.hpp"

namespace firn {
namespace {

Mat3<double> random_rotation(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  Vec3<double> axis{{u(rng), u(rng), u(rng)}};
  const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  for (int d = 0; d < 3; ++d) axis[d] /= n;
  return axis_angle_rotation(axis, 3.0 * u(rng));
}

// Q diag(e) Q^T.
Mat3<double> with_eigenvalues(const Mat3<double>& Q, double e0, double e1, double e2) {
  Mat3<double> D{};
  D(0, 0) = e0;
  D(1, 1) = e1;
  D(2, 2) = e2;
  return mul_transposed(Q * D, Q);
}

double max_abs_diff(const Mat3<double>& a, const Mat3<double>& b) {
  double m = 0;
  for (int q = 0; q < 9; ++q) m = std::max(m, std::abs(a.m[q] - b.m[q]));
  return m;
}

TEST(SymmetricEigenvalues, MatchConstructedSpectrum) {
  std::mt19937 rng(3);
  for (const auto& e : {Vec3<double>{{3.0, 1.0, 0.5}}, Vec3<double>{{2.0, 2.0, 5.0}}, Vec3<double>{{1.0, 1.0, 1.0}},
                        Vec3<double>{{100.0, 1.0, 0.01}}}) {
    const Vec3<double> got = symmetric_eigenvalues(with_eigenvalues(random_rotation(rng), e[0], e[1], e[2]));
    double want[3] = {e[0], e[1], e[2]}, have[3] = {got[0], got[1], got[2]};
    std::sort(want, want + 3);
    std::sort(have, have + 3);
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(have[d], want[d], 1e-6 * want[2]) << d;
  }
}

// S S = A and S symmetric, for spectra near the identity (the series), just outside the series'
// radius, repeated and widely spread (the closed form).
TEST(SpdSqrt, SquaresBackToA) {
  std::mt19937 rng(11);
  const double r = std::sqrt(SqrtSeriesRadius<double>::kSquared);
  const Vec3<double> spectra[] = {{{1 + 0.3 * r, 1 - 0.2 * r, 1 + 0.1 * r}},
                                  {{1 + 2 * r, 1 - r, 1}},
                                  {{1.05, 0.97, 1.0}},
                                  {{2.0, 2.0, 5.0}},
                                  {{4.0, 4.0, 4.0}},
                                  {{100.0, 1.0, 0.01}}};
  for (const Vec3<double>& e : spectra) {
    const Mat3<double> A = with_eigenvalues(random_rotation(rng), e[0], e[1], e[2]);
    const Mat3<double> S = spd_sqrt(A);
    const double scale = std::max({e[0], e[1], e[2]});
    EXPECT_LT(max_abs_diff(S * S, A), 1e-13 * scale) << e[0] << " " << e[1] << " " << e[2];
    EXPECT_LT(max_abs_diff(S, transpose(S)), 1e-13 * std::sqrt(scale));
  }
}

// The series and the closed form meet: just inside and just outside the radius, in float, the root
// is the same to a few roundings, and each squares back to A to float precision.
TEST(SpdSqrt, SeriesAndClosedFormAgreeAtTheRadius) {
  std::mt19937 rng(5);
  const float r = std::sqrt(SqrtSeriesRadius<float>::kSquared);
  for (int i = 0; i < 20; ++i) {
    const Mat3<double> Q = random_rotation(rng);
    Mat3<float> inside, outside;
    // ||A - I||_F = r (1 -+ 1e-3) along the direction (1, -1, 0) / sqrt(2).
    const double a = 0.999 * r / std::sqrt(2.0), b = 1.001 * r / std::sqrt(2.0);
    const Mat3<double> Ai = with_eigenvalues(Q, 1 + a, 1 - a, 1), Ao = with_eigenvalues(Q, 1 + b, 1 - b, 1);
    for (int q = 0; q < 9; ++q) {
      inside.m[q] = float(Ai.m[q]);
      outside.m[q] = float(Ao.m[q]);
    }
    const Mat3<float> Si = spd_sqrt(inside), So = spd_sqrt(outside);
    for (int q = 0; q < 9; ++q) {
      // The two roots differ by about (b - a) / 2 = 1e-3 r / sqrt(2) in their eigenvalues, plus rounding.
      EXPECT_NEAR(Si.m[q], So.m[q], 1e-3f * r + 1e-6f) << q;
      EXPECT_NEAR((Si * Si).m[q], inside.m[q], 1e-6f) << q;
      EXPECT_NEAR((So * So).m[q], outside.m[q], 1e-6f) << q;
    }
  }
}

// The rescale keeps the trial rotation, sets det F to J_new and scales dev(bbar) by keep, for a
// small return (the series) and a large one (the closed form).
TEST(RescaleIsochoricDeviator, SetsVolumeAndDeviatorKeepsRotation) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for (const double keep : {0.9999, 0.5, 0.0})
    for (int i = 0; i < 10; ++i) {
      Mat3<double> F = Mat3<double>::identity();
      for (double& x : F.m) x += u(rng);
      const double J = determinant(F), Jm23 = std::pow(J, -2.0 / 3.0), J_new = 0.8 * J;
      const Mat3<double> b = mul_transposed(F, F);
      const double Ibar = Jm23 * trace(b) / 3;
      const Mat3<double> out = rescale_isochoric_deviator(F, Jm23, Ibar, keep, J_new, std::cbrt(0.8));
      EXPECT_NEAR(determinant(out), J_new, 1e-14);
      const Mat3<double> b_out = mul_transposed(out, out);
      const double Jm23_out = std::pow(J_new, -2.0 / 3.0);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
          const double dev_tr = Jm23 * b(r, c) - (r == c ? Ibar : 0);
          const double dev_out = Jm23_out * (b_out(r, c) - (r == c ? trace(b_out) / 3 : 0));
          EXPECT_NEAR(dev_out, keep * dev_tr, 1e-12) << keep << " " << r << c;
        }
      EXPECT_LT(max_abs_diff(polar_rotation(out), polar_rotation(F)), 1e-12);
    }
}

// A trial F = J^(1/3) sqrt(Ibar I + D) R with dev(bbar_tr) = D = `size` Ibar times a traceless unit
// direction, random or diag(e) rotated (Ibar from det(Ibar I + D) = 1), in double.
Mat3<double> trial_with_deviator(std::mt19937& rng, double size, double J, double& Ibar, const double* e = nullptr) {
  std::uniform_real_distribution<double> u(-1, 1);
  const double e0 = e ? e[0] : u(rng), e1 = e ? e[1] : u(rng), e2 = -e0 - e1;
  const double n = std::sqrt(e0 * e0 + e1 * e1 + e2 * e2);
  const double d[3] = {size * e0 / n, size * e1 / n, size * e2 / n};
  Ibar = 1 / std::cbrt((1 + d[0]) * (1 + d[1]) * (1 + d[2]));
  const Mat3<double> Q = random_rotation(rng);
  const Mat3<double> bbar = with_eigenvalues(Q, Ibar * (1 + d[0]), Ibar * (1 + d[1]), Ibar * (1 + d[2]));
  return (std::cbrt(J) * spd_sqrt(bbar)) * random_rotation(rng);
}

// Lane l of D = bbar - Ibar I in ParticleView::tau's order (as isochoric_invariants_lanes gives
// it), rounded to T.
template <class T, int W>
void set_deviator_lane(Lanes<T, W> (&D)[6], int l, const Mat3<double>& bbar, double Ibar) {
  const double d[6] = {bbar(0, 0) - Ibar, bbar(1, 1) - Ibar, bbar(2, 2) - Ibar, bbar(0, 1), bbar(1, 2), bbar(2, 0)};
  for (int c = 0; c < 6; ++c) D[c].v[l] = T(d[c]);
}

// The largest difference of the lane form in T from the scalar rescale in double, over deviators
// from 1e-4 to 0.99 `radius` (||D||_F / Ibar) along random directions and the two uniaxial ones
// (the eigenvalue sqrt(2/3) ||D||_F, of either sign), for returns from none (keep 1) to full (keep 0).
// With `inside`, every lane must be taken (not handed back).
template <class T>
double lane_rescale_error(double radius, bool inside) {
  constexpr int W = 4;
  using L = Lanes<T, W>;
  std::mt19937 rng(31);
  const double uniaxial[2][2] = {{2, -1}, {-2, 1}};
  double worst = 0;
  for (const double size : {1e-4, 0.1 * radius, 0.5 * radius, 0.99 * radius})
    for (const double keep : {1.0, 0.9999, 0.5, 0.0})
      for (int i = 0; i < 8; ++i) {
        Mat3<L> F;
        L D[6], Ibar, J;
        const L keep_l{T(keep)};
        Mat3<double> want[W];
        for (int l = 0; l < W; ++l) {
          const double J_l = 0.6 + 0.1 * l;
          double ibar;
          const Mat3<double> Fd = trial_with_deviator(rng, size * (1 + 1e-3 * l), J_l, ibar, i < 2 ? uniaxial[i] : nullptr);
          Mat3<T> Ft;  // the lanes' input, rounded to T, and the reference from that rounded input
          for (int q = 0; q < 9; ++q) F.m[q].v[l] = Ft.m[q] = T(Fd.m[q]);
          Mat3<double> Fr;
          for (int q = 0; q < 9; ++q) Fr.m[q] = double(Ft.m[q]);
          const double Jr = determinant(Fr), Jm23r = std::pow(Jr, -2.0 / 3.0);
          const double Ibar_r = Jm23r * trace(mul_transposed(Fr, Fr)) / 3;
          want[l] = rescale_isochoric_deviator(Fr, Jm23r, Ibar_r, keep, Jr, 1.0);
          set_deviator_lane(D, l, Jm23r * mul_transposed(Fr, Fr), Ibar_r);
          Ibar.v[l] = T(Ibar_r);
          J.v[l] = T(Jr);
        }
        LaneMask<W> ok = LaneMask<W>::all();
        const Mat3<L> got = rescale_isochoric_deviator_lanes(F, D, Ibar, keep_l, J, LaneMask<W>::all(), ok);
        for (int l = 0; l < W; ++l) {
          if (inside) {
            EXPECT_TRUE(ok.m[l]) << size << " " << keep << " lane " << l;
          }
          for (int q = 0; q < 9; ++q) worst = std::max(worst, std::abs(double(got.m[q].v[l]) - want[l].m[q]));
        }
      }
  return worst;
}

// Within its radius the lane form is the scalar rescale to a few roundings of T (F is of order 1;
// measured: 1.5 and 2 epsilon in float and double).
TEST(RescaleIsochoricDeviatorLanes, MatchesTheScalarRescaleWithinItsRadiusFloat) {
  const double radius = std::sqrt(double(CoaxialSqrtSeries<float>::kRadiusSquared));
  EXPECT_LT(lane_rescale_error<float>(radius, true), 8 * std::numeric_limits<float>::epsilon());
}
TEST(RescaleIsochoricDeviatorLanes, MatchesTheScalarRescaleWithinItsRadiusDouble) {
  const double radius = std::sqrt(double(CoaxialSqrtSeries<double>::kRadiusSquared));
  EXPECT_LT(lane_rescale_error<double>(radius, true), 8 * std::numeric_limits<double>::epsilon());
}

// The float radius's truncation, seen in double arithmetic (both precisions sum the same terms):
// below float's unit roundoff, as the bound rho^9 / (1 - rho) < 7.3e-9, rho = sqrt(2/3) 0.15, that
// the float radius rests on says (kernels/constitutive/deviator_rescale.hpp). Measured: 7.4e-10;
// with six terms instead of nine, 4.0e-7.
TEST(RescaleIsochoricDeviatorLanes, TruncationAtTheFloatRadiusIsBelowFloatRounding) {
  static_assert(CoaxialSqrtSeries<float>::kTerms == CoaxialSqrtSeries<double>::kTerms, "the same series");
  const double radius = std::sqrt(double(CoaxialSqrtSeries<float>::kRadiusSquared));
  EXPECT_LT(lane_rescale_error<double>(radius, false), 0.5 * std::numeric_limits<float>::epsilon());
}

// Just outside the radius an active lane is handed back (ok cleared), an inactive one is not.
template <class T>
void check_handed_back_outside_the_radius() {
  constexpr int W = 4;
  using L = Lanes<T, W>;
  std::mt19937 rng(37);
  const double radius = std::sqrt(double(CoaxialSqrtSeries<T>::kRadiusSquared));
  Mat3<L> F;
  L D[6], Ibar, J(T(1));
  const L keep{T(0.5)};
  for (int l = 0; l < W; ++l) {
    double ibar;
    const Mat3<double> Fd = trial_with_deviator(rng, 1.01 * radius, 1.0, ibar);
    for (int q = 0; q < 9; ++q) F.m[q].v[l] = T(Fd.m[q]);
    set_deviator_lane(D, l, mul_transposed(Fd, Fd), ibar);  // J = 1: bbar = F F^T
    Ibar.v[l] = T(ibar);
  }
  LaneMask<W> active = LaneMask<W>::all(), ok = LaneMask<W>::all();
  active.m[1] = active.m[3] = 0;
  rescale_isochoric_deviator_lanes(F, D, Ibar, keep, J, active, ok);
  for (int l = 0; l < W; ++l) EXPECT_EQ(ok.m[l], 1 - active.m[l]) << l;
}

TEST(RescaleIsochoricDeviatorLanes, HandsBackActiveLanesOutsideItsRadius) {
  check_handed_back_outside_the_radius<float>();
  check_handed_back_outside_the_radius<double>();
}

}  // namespace
}  // namespace firn

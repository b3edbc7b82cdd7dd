// The elastic deformation gradient after a return mapping that scales the deviator of the
// isochoric elastic left Cauchy-Green tensor and sets the elastic volume (DESIGN.md section 4):
// given the trial F_tr with b_tr = F_tr F_tr^T, J_tr = det F_tr, bbar_tr = J_tr^(-2/3) b_tr = Ibar I + D
// (Ibar = tr(bbar_tr) / 3, D = dev(bbar_tr)), it returns F with
//   dev(bbar) = keep D   and   det F = J_new.
// Only J and dev(bbar) enter the stress of an isochoric-volumetric split energy, so the trace part
// of bbar is free: it is the x with det(x I + keep D) = 1 (the volume-preserving variant of Simo and
// Hughes, Computational Inelasticity, Box 9.1 step 4; cf. Simo 1992, CMAME 99:61-112). Used by the
// J2 radial return (keep = 1 - beta, J_new = J_tr) and the Cam-clay return (keep = q / q_tr, J_new
// from the returned pressure). The caller passes stretch = (J_new / J_tr)^(1/3), which it has at hand
// (1 for a volume-preserving return, so the J2 return takes no cube root here).
//
// No SVD: b and bbar = x I + keep D are coaxial, so F = S F_tr with the symmetric stretch
//   S = (J_new / J_tr)^(1/3) sqrt(A),   A = (x I + keep D) (Ibar I + D)^-1,
// which keeps F_tr's rotation (S is symmetric positive definite and commutes with b_tr, so
// F F^T = S^2 b_tr = J_new^(2/3) bbar). The square root of the symmetric positive definite A comes
// from Hoger and Carlson (1984, Quart. Appl. Math. 42:113-117, Eq. 3.3):
//   sqrt(A) = (i1 i2 - i3)^-1 (-A^2 + (i1^2 - i2) A + i1 i3 I),
// with i1, i2, i3 the invariants of sqrt(A), i.e. the elementary symmetric functions of the square
// roots of A's eigenvalues (closed form for a symmetric 3x3: Smith 1961, Comm. ACM 4:168). The
// invariants are symmetric in the eigenvalues and i1 i2 - i3 = (l1 + l2)(l2 + l3)(l3 + l1) > 0,
// so nothing divides by a gap between eigenvalues: repeated eigenvalues, the common case near an
// isotropic state, are as accurate as distinct ones.
#pragma once

#include <cmath>

#include "kernels/float_limits.hpp"
#include "kernels/hd.hpp"
#include "kernels/lanes.hpp"
#include "kernels/mat3.hpp"

namespace firn {

// The eigenvalues of a symmetric 3x3 matrix (Smith 1961): A = m I + K, tr K = 0, the eigenvalues
// m + 2 sqrt(p) cos(phi + 2 pi k / 3) with p = K:K / 6 and cos(3 phi) = det(K) / (2 p^(3/2)).
template <class T>
FIRN_HD Vec3<T> symmetric_eigenvalues(const Mat3<T>& A) {
  const T m = trace(A) / T(3);
  Mat3<T> K = A;
  for (int d = 0; d < 3; ++d) K(d, d) -= m;
  const T p = ddot(K, K) / T(6);
  if (!(p > T(0))) return Vec3<T>{{m, m, m}};
  const T sp = std::sqrt(p);
  T c = determinant(K) / (T(2) * p * sp);
  c = c > T(1) ? T(1) : (c < T(-1) ? T(-1) : c);
  const T phi = std::acos(c) / T(3);
  const T cos_phi = std::cos(phi), sin_phi = std::sin(phi);
  const T half_sqrt3 = T(0.8660254037844386);
  const T e0 = m + T(2) * sp * cos_phi;
  const T e2 = m + T(2) * sp * (T(-0.5) * cos_phi - half_sqrt3 * sin_phi);  // phi + 2 pi / 3
  return Vec3<T>{{e0, T(3) * m - e0 - e2, e2}};
}

// ||A - I||_F^2 below which spd_sqrt takes the binomial series: its remainder after the cubic term,
// at most 5/128 e^4 / (1 - e) for e = ||A - I||_F, is then below the precision's epsilon
// (float: e < 0.04; double: e < 2.5e-4).
template <class T>
struct SqrtSeriesRadius;
template <>
struct SqrtSeriesRadius<float> {
  static constexpr float kSquared = 1.6e-3f;
};
template <>
struct SqrtSeriesRadius<double> {
  static constexpr double kSquared = 6.25e-8;
};

// The binomial series sqrt(I + E) = I + E/2 - E^2/8 + E^3/16 (two matrix products), within its
// radius SqrtSeriesRadius; V is T or Lanes of T (kernels/lanes.hpp).
template <class V>
FIRN_HD Mat3<V> sqrt_near_identity(const Mat3<V>& E) {
  Mat3<V> S = V(1) / V(16) * E;
  for (int d = 0; d < 3; ++d) S(d, d) -= V(1) / V(8);
  S = E * S;
  for (int d = 0; d < 3; ++d) S(d, d) += V(0.5);
  S = E * S;
  for (int d = 0; d < 3; ++d) S(d, d) += V(1);
  return S;
}

// sqrt(A) of a symmetric positive definite A. Near the identity, where a plastic step of snow
// almost always lands, the series above; elsewhere the closed form of Hoger and Carlson (1984).
template <class T>
FIRN_HD Mat3<T> spd_sqrt(const Mat3<T>& A) {
  Mat3<T> E = A;
  for (int d = 0; d < 3; ++d) E(d, d) -= T(1);
  if (ddot(E, E) < SqrtSeriesRadius<T>::kSquared) return sqrt_near_identity(E);
  const Vec3<T> e = symmetric_eigenvalues(A);
  T l[3];
  for (int d = 0; d < 3; ++d) l[d] = std::sqrt(e[d] > T(0) ? e[d] : T(0));
  const T i1 = l[0] + l[1] + l[2], i2 = l[0] * l[1] + l[1] * l[2] + l[2] * l[0], i3 = l[0] * l[1] * l[2];
  const T inv = T(1) / ((l[0] + l[1]) * (l[1] + l[2]) * (l[2] + l[0]));  // = 1 / (i1 i2 - i3)
  Mat3<T> S = (-inv) * (A * A) + (inv * (i1 * i1 - i2)) * A;
  for (int d = 0; d < 3; ++d) S(d, d) += inv * i1 * i3;
  return S;
}

template <class T>
FIRN_HD Mat3<T> rescale_isochoric_deviator(const Mat3<T>& F_tr, T Jm23, T Ibar, T keep, T J_new, T stretch) {
  const Mat3<T> b = mul_transposed(F_tr, F_tr);
  Mat3<T> D = Jm23 * b;
  for (int d = 0; d < 3; ++d) D(d, d) -= Ibar;
  // x solves h(x) = det(x I + keep D) - 1 = x^3 - x keep^2 D:D / 2 + keep^3 det D - 1 = 0 (tr D = 0).
  // h is increasing and convex where all factors x + keep d_i are positive, and h(Ibar) >= 0 for
  // keep <= 1 (for a fixed trace the product grows as the deviation shrinks), so Newton from
  // x = Ibar decreases monotonically to the root without leaving that region.
  const T k2j2 = keep * keep * ddot(D, D) / T(2), k3d = keep * keep * keep * determinant(D);
  T x = Ibar;
  for (int it = 0; it < 32; ++it) {
    const T h = x * x * x - x * k2j2 + k3d - T(1);
    const T step = h / (T(3) * x * x - k2j2);
    x -= step;
    if (!(step > T(4) * FloatLimits<T>::kEpsilon * x)) break;
  }
  // A = (x I + keep D) (Ibar I + D)^-1, symmetric since the factors commute.
  Mat3<T> P = keep * D, Q = D;
  for (int d = 0; d < 3; ++d) {
    P(d, d) += x;
    Q(d, d) += Ibar;
  }
  const Mat3<T> A = P * inverse(Q);
  Mat3<T> As;  // symmetrised against rounding
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) As(r, c) = T(0.5) * (A(r, c) + A(c, r));
  const Mat3<T> F = stretch * (spd_sqrt(As) * F_tr);
  // det F = J_new up to one rounding: det sqrt(A) = 1 and stretch^3 = J_new / J_tr up to a few
  // roundings e, which the factor cbrt(1 + e) = 1 + e / 3 + O(e^2) removes.
  return ((T(2) + J_new / determinant(F)) / T(3)) * F;
}

// rescale_isochoric_deviator on W lanes (kernels/lanes.hpp) for a volume-preserving return (J_new =
// J_tr, stretch 1), the J2 return's case: the same Newton iteration for x, run until every lane in
// `active` has converged, and sqrt(A) by the series only. Lanes outside the series' radius, or not
// converged in kMaxSteps, are cleared in `ok` for the caller's scalar path.
template <class T, int W>
FIRN_HD Mat3<Lanes<T, W>> rescale_isochoric_deviator_lanes(const Mat3<Lanes<T, W>>& F_tr, const Lanes<T, W>& Jm23,
                                                          const Lanes<T, W>& Ibar, const Lanes<T, W>& keep,
                                                          const Lanes<T, W>& J, const LaneMask<W>& active,
                                                          LaneMask<W>& ok) {
  using L = Lanes<T, W>;
  constexpr int kMaxSteps = 8;
  const Mat3<L> b = mul_transposed(F_tr, F_tr);
  Mat3<L> D = Jm23 * b;
  for (int d = 0; d < 3; ++d) D(d, d) -= Ibar;
  const L k2j2 = keep * keep * ddot(D, D) / L(T(2)), k3d = keep * keep * keep * determinant(D);
  L x = Ibar;
  LaneMask<W> done = !active || !ok;
  for (int it = 0; it < kMaxSteps && any(!done); ++it) {
    const L h = x * x * x - x * k2j2 + k3d - L(T(1));
    const L step = h / (L(T(3)) * x * x - k2j2);
    x = select(done, x, x - step);
    done = done || !(step > L(T(4) * FloatLimits<T>::kEpsilon) * x);
  }
  ok = ok && done;
  Mat3<L> P = keep * D, Q = D;
  for (int d = 0; d < 3; ++d) {
    P(d, d) += x;
    Q(d, d) += Ibar;
  }
  const Mat3<L> A = P * inverse(Q);
  Mat3<L> E;  // A - I, symmetrised against rounding
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) E(r, c) = L(T(0.5)) * (A(r, c) + A(c, r));
  for (int d = 0; d < 3; ++d) E(d, d) -= L(T(1));
  ok = ok && ddot(E, E) < L(SqrtSeriesRadius<T>::kSquared);
  const Mat3<L> F = sqrt_near_identity(E) * F_tr;
  return ((L(T(2)) + J / determinant(F)) / L(T(3))) * F;
}

}  // namespace firn

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
#include "kernels/lane_math.hpp"
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
// radius SqrtSeriesRadius; V is T or Lanes of T (kernels/lanes.hpp) (the lane return uses
// rescale_isochoric_deviator_lanes' series instead).
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

// The invariants a return mapping on W lanes starts from, one loop over the lanes in scalar code
// (FIRN_NOINLINE): J = det F, Ibar = tr(bbar) / 3, D = dev(bbar) (its six entries in
// ParticleView::tau's order: 00, 11, 22, 01, 12, 20) and ||D||_F of bbar = J^(-2/3) F F^T, with
// J^(-2/3) by inverse_root.
template <class T, int W>
FIRN_NOINLINE FIRN_HD void isochoric_invariants_lanes(const Mat3<Lanes<T, W>>& F, Lanes<T, W>& J, Lanes<T, W>& Ibar,
                                                      Lanes<T, W> (&D)[6], Lanes<T, W>& dev_norm) {
  FIRN_LANES
  for (int l = 0; l < W; ++l) {
    T f[9];  // F, row by row
    FIRN_UNROLL
    for (int q = 0; q < 9; ++q) f[q] = F.m[q].v[l];
    const T det = determinant_of_rows(f);
    const T y = inverse_root<3>(det), jm23 = y * y;
    const T b00 = rows_dot(f, 0, 0), b11 = rows_dot(f, 1, 1), b22 = rows_dot(f, 2, 2), b01 = rows_dot(f, 0, 1), b12 = rows_dot(f, 1, 2), b20 = rows_dot(f, 2, 0);
    const T third_trace = (b00 + b11 + b22) * T(1.0 / 3);
    const T e0 = b00 - third_trace, e1 = b11 - third_trace, e2 = b22 - third_trace;
    const T dd = e0 * e0 + e1 * e1 + e2 * e2 + T(2) * (b01 * b01 + b12 * b12 + b20 * b20);
    J.v[l] = det;
    Ibar.v[l] = jm23 * third_trace;
    D[0].v[l] = jm23 * e0;
    D[1].v[l] = jm23 * e1;
    D[2].v[l] = jm23 * e2;
    D[3].v[l] = jm23 * b01;
    D[4].v[l] = jm23 * b12;
    D[5].v[l] = jm23 * b20;
    dev_norm.v[l] = jm23 * (dd * inverse_root<2>(dd));  // sqrt(dd); 0 for dd = 0
  }
}

// The series of rescale_isochoric_deviator_lanes: its last power of D, and the radius on
// ||D||_F max(u, v) (see there) within which the remainder is below the precision's epsilon.
template <class T>
struct CoaxialSqrtSeries;
template <>
struct CoaxialSqrtSeries<float> {
  static constexpr int kTerms = 8;
  static constexpr float kRadiusSquared = 0.0225f;  // rho <= sqrt(2/3) 0.15 = 0.122: rho^9 / (1 - rho) < 7.3e-9
};
template <>
struct CoaxialSqrtSeries<double> {
  static constexpr int kTerms = 8;
  static constexpr double kRadiusSquared = 4e-4;  // rho <= sqrt(2/3) 0.02 = 0.0163: rho^9 / (1 - rho) < 8.6e-17
};

// rescale_isochoric_deviator on W lanes (kernels/lanes.hpp) for a volume-preserving return (J_new =
// J_tr, stretch 1), the J2 return's case, for the lanes in `active`, given D = dev(bbar_tr) as
// isochoric_invariants_lanes gives it (tau's order). One loop over the lanes holds
// a lane's whole computation in scalar code, which the compiler vectorises (FIRN_NOINLINE):
// - x by two Newton steps from its first-order value 1 + keep^2 (J2 - keep J3) / 3 (J2 = D:D / 2,
//   J3 = det D; det(x I + keep D) = x^3 - keep^2 J2 x + keep^3 J3 for tr D = 0).
// - sqrt(A) = g(D) for the scalar function
//     g(d) = sqrt((x + keep d) / (Ibar + d)) = sqrt(x / Ibar) h(d),  h(d) = (1 + u d)^(1/2) (1 + v d)^(-1/2),
//   u = keep / x, v = 1 / Ibar. h solves (1 + u d)(1 + v d) h' = (u - v) / 2 h, so its Taylor
//   coefficients follow h_0 = 1, h_1 = (u - v) / 2,
//     (j + 1) h_(j+1) = ((u - v) / 2 - (u + v) j) h_j - u v (j - 1) h_(j-1),
//   and the powers of D reduce by Cayley-Hamilton, D^3 = J2 D + J3 I, so the series is
//   c0 I + c1 D + c2 D^2 with scalar coefficients and one product D D.
// The remainder: |C(1/2, i)| <= |C(-1/2, i)| and the C(-1/2, i) (-1)^i are positive, so h's
// coefficients are bounded by those of (1 - r t)^(-1/2) (1 - r t)^(-1/2) = (1 - r t)^-1: |h_j| <= r^j,
// r = max(u, v). Every eigenvalue d of D has |d| <= sqrt(2/3) ||D||_F, so with rho = sqrt(2/3)
// ||D||_F r the terms j > kTerms sum to at most rho^(kTerms+1) / (1 - rho), which the radius of
// CoaxialSqrtSeries keeps below the precision's epsilon (u <= 1 and v <= 1, since x >= 1 and
// Ibar >= 1 by the means of eigenvalues whose product is 1). The radius bounds the deviator, not
// the return's step: the scalar form's series bounds ||A - I||, which is small for any deviator
// when keep is near 1; a material whose yield strain sqrt(2/3) sigma_y / G1 exceeds 0.15 (float)
// or 0.02 (double) takes the scalar return at every yielding step. An active lane outside the
// radius, or whose x has not converged, is cleared in `ok` for the caller's scalar path.
template <class T, int W>
FIRN_NOINLINE FIRN_HD Mat3<Lanes<T, W>> rescale_isochoric_deviator_lanes(
    const Mat3<Lanes<T, W>>& F_tr, const Lanes<T, W> (&D)[6], const Lanes<T, W>& Ibar, const Lanes<T, W>& keep,
    const Lanes<T, W>& J, const LaneMask<W>& active, LaneMask<W>& ok) {
  using Series = CoaxialSqrtSeries<T>;
  constexpr int kNewtonSteps = 2;
  Mat3<Lanes<T, W>> F_out;
  FIRN_LANES
  for (int l = 0; l < W; ++l) {
    T f[9];  // F_tr, row by row
    FIRN_UNROLL
    for (int q = 0; q < 9; ++q) f[q] = F_tr.m[q].v[l];
    const T ibar = Ibar.v[l], k = keep.v[l];
    const T d00 = D[0].v[l], d11 = D[1].v[l], d22 = D[2].v[l], d01 = D[3].v[l], d12 = D[4].v[l], d20 = D[5].v[l];
    const T DD = d00 * d00 + d11 * d11 + d22 * d22 + T(2) * (d01 * d01 + d12 * d12 + d20 * d20);
    const T J2 = T(0.5) * DD;
    const T J3 = d00 * (d11 * d22 - d12 * d12) - d01 * (d01 * d22 - d12 * d20) + d20 * (d01 * d12 - d11 * d20);
    const T a = k * k * J2, c = k * k * k * J3;
    T x = T(1) + (a - c) * T(1.0 / 3), step = T(0);
    FIRN_UNROLL
    for (int it = 0; it < kNewtonSteps; ++it) {
      step = (x * x * x - a * x + c - T(1)) / (T(3) * x * x - a);
      x = x - step;
    }
    const T inv = T(1) / (x * ibar), u = k * ibar * inv, v = x * inv;
    const T half_u_minus_v = T(0.5) * (u - v), u_plus_v = u + v, uv = u * v;
    T h_prev = T(0), h = T(1);          // h_(j-1), h_j
    T p0 = T(1), p1 = T(0), p2 = T(0);  // D^j = p0 I + p1 D + p2 D^2
    T c0 = T(0), c1 = T(0), c2 = T(0);
    FIRN_UNROLL
    for (int j = 0; j <= Series::kTerms; ++j) {
      c0 += h * p0;
      c1 += h * p1;
      c2 += h * p2;
      const T h_next = ((half_u_minus_v - u_plus_v * T(j)) * h - uv * T(j - 1) * h_prev) * T(1.0 / (j + 1));
      h_prev = h;
      h = h_next;
      const T next0 = p2 * J3, next1 = p0 + p2 * J2;  // D^(j+1) = D^j D
      p2 = p1;
      p1 = next1;
      p0 = next0;
    }
    const T xv = x * v, scale = xv * inverse_root<2>(xv);  // sqrt(x / Ibar)
    c0 *= scale;
    c1 *= scale;
    c2 *= scale;
    // S = c0 I + c1 D + c2 D^2 (symmetric), row by row; then S F_tr.
    const T s00 = c0 + c1 * d00 + c2 * (d00 * d00 + d01 * d01 + d20 * d20);
    const T s11 = c0 + c1 * d11 + c2 * (d01 * d01 + d11 * d11 + d12 * d12);
    const T s22 = c0 + c1 * d22 + c2 * (d20 * d20 + d12 * d12 + d22 * d22);
    const T s01 = c1 * d01 + c2 * (d00 * d01 + d01 * d11 + d20 * d12);
    const T s12 = c1 * d12 + c2 * (d01 * d20 + d11 * d12 + d12 * d22);
    const T s20 = c1 * d20 + c2 * (d20 * d00 + d12 * d01 + d22 * d20);
    const T s[9] = {s00, s01, s20, s01, s11, s12, s20, s12, s22};
    T g[9];
    FIRN_UNROLL
    for (int r = 0; r < 3; ++r) {
      FIRN_UNROLL
      for (int col = 0; col < 3; ++col)
        g[3 * r + col] = s[3 * r] * f[col] + s[3 * r + 1] * f[3 + col] + s[3 * r + 2] * f[6 + col];
    }
    // det = J up to one rounding, as in rescale_isochoric_deviator.
    const T det = determinant_of_rows(g);
    const T fix = (T(2) + J.v[l] / det) * T(1.0 / 3);
    FIRN_UNROLL
    for (int q = 0; q < 9; ++q) F_out.m[q].v[l] = fix * g[q];
    const int within = int(DD * u * u < Series::kRadiusSquared) & int(DD * v * v < Series::kRadiusSquared) &
                       int(std::fabs(step) <= T(4) * FloatLimits<T>::kEpsilon * x);
    ok.m[l] = ok.m[l] & (within | (active.m[l] ^ 1));
  }
  return F_out;
}

}  // namespace firn

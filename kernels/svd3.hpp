// Fast, robust 3x3 singular value decomposition for float and double, host and device.
//
//   svd3(A, U, sigma, V):  A = U diag(sigma) V^T with U, V proper rotations (det = +1),
//                          sigma[0] >= sigma[1] >= |sigma[2]|, sigma[2] < 0 exactly when the
//                          reconstruction has det < 0, i.e. when det(A) < 0 (for inputs whose
//                          smallest singular value is above rounding level; below it the sign of
//                          det(A) is itself rounding noise).
//   polar_rotation(A):     R = U V^T, the rotation of the polar decomposition A = R (V diag(sigma) V^T).
//
// This "signed" convention (Irving et al. 2004) keeps R a rotation even for inverted elements,
// as fixed-corotated elasticity needs.
//
// Algorithm after McAdams, Selle, Tamstorf, Teran, Sifakis, "Computing the Singular Value
// Decomposition of 3x3 matrices with minimal branching and elementary floating point
// operations", UW-Madison TR1690 (2011), referred to as [M11] below:
//   0. (not in [M11]) scale A so that max |a_ij| = 1: A^T A cannot overflow for any finite
//      input, nothing that matters underflows, and every threshold below can be absolute;
//   1. [M11 sec. 2] Jacobi eigenanalysis of S = A^T A: a fixed number of cyclic sweeps of
//      approximate Givens conjugations, the rotations accumulated in a quaternion, V = R(q);
//   2. [M11 sec. 3] B = A V; sort the columns of B (and V) by decreasing norm with
//      sign-preserving swaps, so det V stays +1;
//   3. [M11 sec. 4] QR of B by three Givens rotations: B = U R, sigma = diag(R);
//   4. (not in [M11]) one exact two-sided 2x2 Jacobi step on the trailing block of R. Forming
//      A^T A squares the condition number: the eigenvectors of S for sigma[1], sigma[2] are only
//      accurate to eps * sigma[0]^2 / sigma[1]^2, which leaves an R(1,2) of eps * sigma[0]^2 /
//      sigma[1] in step 3 (1e-5 relative in float for sigma[1] = 0.01 sigma[0]). Diagonalising
//      that block from its own, well-scaled entries brings the backward error back to a few eps.
//      R(0,1) and R(0,2) are O(eps * sigma[0]) by construction and are dropped.
#pragma once

#include <cmath>

#include "kernels/hd.hpp"
#include "kernels/mat3.hpp"

namespace firn {
namespace svd3_detail {

template <class T>
struct Traits;
// kSweeps: number of cyclic Jacobi sweeps (3 rotations each), the smallest that reaches the
// rounding floor of the whole decomposition (backward error about 7 eps at worst) on 2e6
// adversarial matrices: a pair of singular values clustered within 1e-16..0.3 relative and a
// third apart, the slowest structure found for the approximate rotations below. Measured worst
// backward error with one sweep fewer: float 5 sweeps 158 eps, double 7 sweeps 49 eps. (Matrices
// with uniform random entries converge sooner: float 5 sweeps 13 eps, double 6 sweeps 6 eps.)
// 4 sweeps, as in the float implementation of [M11], leave up to 1e4 eps here.
// kTiny = sqrt(smallest normal number): a guard below which 2-vectors are treated as zero; its
// square is still a normal number, so nothing derived from it underflows.
template <>
struct Traits<float> {
  static constexpr int kSweeps = 6;
  static constexpr float kTiny = 0x1p-63f;
};
template <>
struct Traits<double> {
  static constexpr int kSweeps = 8;
  static constexpr double kTiny = 0x1p-511;
};

// max and min as one instruction each (std::fmax, std::fmin are library calls on x86 because of
// their NaN rules, which do not matter here).
template <class T>
FIRN_HD T max2(T a, T b) {
  return a > b ? a : b;
}
template <class T>
FIRN_HD T min2(T a, T b) {
  return a < b ? a : b;
}

// One approximate Jacobi conjugation S <- G^T S G of the symmetric S on the pair (p, q), where
// (p, q, k) is a cyclic permutation of (0, 1, 2) and G rotates the (p, q) plane by theta, i.e.
// G is a rotation about axis k. The quaternion q accumulates V <- V G ([M11] sec. 2).
// |spq| <= negligible (kTiny trace S, some 1e12 times below rounding) counts as zero: once the
// iteration has converged, the squares of such entries would be subnormal numbers, which cost
// x86 CPUs about 10% of the float run time.
template <class T>
FIRN_HD void jacobi_conjugate(T& spp, T& sqq, T& spq, T& spk, T& sqk, T& qw, T& qp, T& qq, T& qk, T negligible) {
  // [M11] sec. 2, approximate Givens quaternion (ch, sh) ~ (cos, sin)(theta / 2), unnormalised:
  // the exact angle has tan(2 theta) = 2 spq / (spp - sqq); for small angles
  // tan(theta / 2) ~ spq / (2 (spp - sqq)). That first-order guess is used while
  // |theta / 2| < pi/8, i.e. while (3 + 2 sqrt 2) sh^2 < ch^2; otherwise theta = pi/4, which still
  // reduces |spq| by a constant factor. The fallback also runs when ch^2 <= kTiny: then
  // |spp - sqq| < 2e-10 (float) of max S >= 1, equal up to rounding, and pi/4 is the exact
  // Jacobi angle up to that rounding; this keeps n >= kTiny below, so 1/n^2 is finite.
  const T gamma = T(5.8284271247461901);  // 3 + 2 sqrt(2) = cot^2(pi/8)
  const T ch0 = T(2) * (spp - sqq);
  const T sh0 = std::fabs(spq) > negligible ? spq : T(0);
  const T ch0_sq = ch0 * ch0, sh0_sq = sh0 * sh0;
  const bool first_order = (gamma * sh0_sq < ch0_sq) & (ch0_sq > Traits<T>::kTiny);
  const T ch = first_order ? ch0 : T(0.92387953251128676);        // cos(pi/8)
  const T sh = first_order ? sh0 : T(0.38268343236508977);        // sin(pi/8)
  const T ch_sq = first_order ? ch0_sq : T(0.85355339059327376);  // cos^2(pi/8)
  const T sh_sq = first_order ? sh0_sq : T(0.14644660940672624);  // sin^2(pi/8)

  // With n = ch^2 + sh^2: n cos(theta) = ch^2 - sh^2 and n sin(theta) = 2 ch sh.
  // S is conjugated by the unnormalised n G and rescaled by 1/n^2 (1/n for the entries linear
  // in G), so that the one division runs in parallel with the products instead of before them.
  const T n = ch_sq + sh_sq;
  const T cu = ch_sq - sh_sq;
  const T su = T(2) * ch * sh;
  const T inv_n = T(1) / n;
  const T inv_n2 = inv_n * inv_n;
  const T cc = cu * cu, ss = su * su, cs = cu * su;
  const T spp_new = (cc * spp + T(2) * cs * spq + ss * sqq) * inv_n2;
  const T sqq_new = (ss * spp - T(2) * cs * spq + cc * sqq) * inv_n2;
  spq = (cs * (sqq - spp) + (cc - ss) * spq) * inv_n2;  // not zero: the angle is approximate
  spp = spp_new;
  sqq = sqq_new;
  const T spk_new = (cu * spk + su * sqk) * inv_n;
  sqk = (cu * sqk - su * spk) * inv_n;
  spk = spk_new;

  // q <- q * (ch, sh e_k) / sqrt(n): the quaternion of V G (its square root is off the chain
  // of dependencies through S).
  const T w = std::sqrt(inv_n);
  const T wch = w * ch, wsh = w * sh;
  const T w0 = qw, p0 = qp, q0 = qq, k0 = qk;
  qw = w0 * wch - k0 * wsh;
  qp = p0 * wch + q0 * wsh;
  qq = q0 * wch - p0 * wsh;
  qk = k0 * wch + w0 * wsh;
}

// If swap: (column i, column j) <- (column j, -column i), a quarter turn that keeps det M
// ([M11] sec. 3, conditional negative swap).
template <class T>
FIRN_HD void cond_neg_swap_cols(bool swap, Mat3<T>& M, int i, int j) {
  for (int r = 0; r < 3; ++r) {
    const T x = M(r, i), y = M(r, j);
    M(r, i) = swap ? y : x;
    M(r, j) = swap ? -x : y;
  }
}

// One compare-exchange of the column sort ([M11] sec. 3): if column j of B is longer than
// column i, conditionally negative-swap them in B and V, and swap their squared norms rho.
template <class T>
FIRN_HD void sort_pair(Mat3<T>& B, Mat3<T>& V, T* rho, int i, int j) {
  const bool swap = rho[i] < rho[j];
  cond_neg_swap_cols(swap, B, i, j);
  cond_neg_swap_cols(swap, V, i, j);
  const T ri = rho[i], rj = rho[j];
  rho[i] = swap ? rj : ri;
  rho[j] = swap ? ri : rj;
}

// Givens rotation (c, s) with [c s; -s c] (a1, a2)^T = (rho, 0), where rho = |(a1, a2)| is
// passed in because some callers know it already ([M11] sec. 4). Below kTiny the vector is
// treated as zero: the identity, or a half turn if a1 < 0 so that the entry it leaves behind is
// still >= 0.
template <class T>
FIRN_HD void givens(T a1, T a2, T rho, T& c, T& s) {
  const bool nonzero = rho > Traits<T>::kTiny;
  const T inv = T(1) / (nonzero ? rho : T(1));
  c = nonzero ? a1 * inv : (a1 < T(0) ? T(-1) : T(1));
  s = nonzero ? a2 * inv : T(0);
}

// M <- G^T M on rows (p, q), columns from j0 on (the ones before are already zero there).
template <class T>
FIRN_HD void rotate_rows(Mat3<T>& M, int p, int q, int j0, T c, T s) {
  for (int j = j0; j < 3; ++j) {
    const T x = M(p, j), y = M(q, j);
    M(p, j) = c * x + s * y;
    M(q, j) = c * y - s * x;
  }
}

// M <- M G on columns (p, q).
template <class T>
FIRN_HD void rotate_cols(Mat3<T>& M, int p, int q, T c, T s) {
  for (int r = 0; r < 3; ++r) {
    const T x = M(r, p), y = M(r, q);
    M(r, p) = c * x + s * y;
    M(r, q) = c * y - s * x;
  }
}

// The decomposition with an explicit sweep count (svd3 passes Traits<T>::kSweeps).
template <class T>
FIRN_HD void svd3_sweeps(const Mat3<T>& A_in, Mat3<T>& U, Vec3<T>& sigma, Mat3<T>& V, int sweeps) {
  const T tiny = Traits<T>::kTiny;
  const T min_normal = tiny * tiny;

  // 0. Scale by m = max |a_ij|, clamped to [min_normal, 1 / min_normal] so that 1/m is a normal
  //    number (the scaled entries are then at most 4 in magnitude, and S at most 48).
  T amax[9];
  for (int i = 0; i < 9; ++i) amax[i] = std::fabs(A_in.m[i]);
  for (int i = 0; i < 4; ++i) amax[i] = max2(amax[i], amax[i + 4]);  // a reduction tree,
  amax[0] = max2(max2(amax[0], amax[2]), max2(amax[1], amax[3]));    // not a chain
  const T m = min2(max2(max2(amax[0], amax[8]), min_normal), T(1) / min_normal);
  const Mat3<T> A = (T(1) / m) * A_in;

  // 1. S = A^T A (upper triangle) and its Jacobi eigenanalysis, q = (qw, qx, qy, qz) = identity.
  T s00 = A(0, 0) * A(0, 0) + A(1, 0) * A(1, 0) + A(2, 0) * A(2, 0);
  T s11 = A(0, 1) * A(0, 1) + A(1, 1) * A(1, 1) + A(2, 1) * A(2, 1);
  T s22 = A(0, 2) * A(0, 2) + A(1, 2) * A(1, 2) + A(2, 2) * A(2, 2);
  T s01 = A(0, 0) * A(0, 1) + A(1, 0) * A(1, 1) + A(2, 0) * A(2, 1);
  T s02 = A(0, 0) * A(0, 2) + A(1, 0) * A(1, 2) + A(2, 0) * A(2, 2);
  T s12 = A(0, 1) * A(0, 2) + A(1, 1) * A(1, 2) + A(2, 1) * A(2, 2);
  T qw = T(1), qx = T(0), qy = T(0), qz = T(0);
  const T negligible = tiny * (s00 + s11 + s22);
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    // Pairs (0,1), (1,2), (2,0): rotations about z, x, y. Arguments: S_pp, S_qq, S_pq, S_pk,
    // S_qk and the quaternion components w, p, q, k.
    jacobi_conjugate(s00, s11, s01, s02, s12, qw, qx, qy, qz, negligible);
    jacobi_conjugate(s11, s22, s12, s01, s02, qw, qy, qz, qx, negligible);
    jacobi_conjugate(s22, s00, s02, s12, s01, qw, qz, qx, qy, negligible);
  }
  // V = R(q / |q|) written with |q|^2 as a divisor, so that no square root is needed; it is
  // orthogonal to rounding whatever drift q accumulated.
  {
    const T ww = qw * qw, xx = qx * qx, yy = qy * qy, zz = qz * qz;
    const T xy = qx * qy, xz = qx * qz, yz = qy * qz, wx = qw * qx, wy = qw * qy, wz = qw * qz;
    const T inv = T(1) / (ww + xx + yy + zz);
    const T inv2 = T(2) * inv;
    V = Mat3<T>{{(ww + xx - yy - zz) * inv, (xy - wz) * inv2, (xz + wy) * inv2,  //
                 (xy + wz) * inv2, (ww - xx + yy - zz) * inv, (yz - wx) * inv2,  //
                 (xz - wy) * inv2, (yz + wx) * inv2, (ww - xx - yy + zz) * inv}};
  }

  // 2. B = A V, columns sorted by decreasing squared norm with the same swaps on V.
  Mat3<T> B = A * V;
  T rho[3];
  for (int j = 0; j < 3; ++j) rho[j] = B(0, j) * B(0, j) + B(1, j) * B(1, j) + B(2, j) * B(2, j);
  sort_pair(B, V, rho, 0, 1);  // sorting network for three: the largest ends in column 0,
  sort_pair(B, V, rho, 0, 2);
  sort_pair(B, V, rho, 1, 2);  // then the other two are ordered

  // 3. QR by Givens: zero B(1,0), B(2,0), then B(2,1); U = G1 G2 G3, B becomes R = U^T (A V).
  //    The second rotation's norm is |column 0| = sqrt(rho[0]), known before the first is done.
  T c, s;
  const T r0 = std::sqrt(rho[0]);
  givens(B(0, 0), B(1, 0), std::sqrt(B(0, 0) * B(0, 0) + B(1, 0) * B(1, 0)), c, s);
  rotate_rows(B, 0, 1, 0, c, s);
  U = Mat3<T>{{c, -s, T(0), s, c, T(0), T(0), T(0), T(1)}};
  givens(B(0, 0), B(2, 0), r0, c, s);
  rotate_rows(B, 0, 2, 1, c, s);  // B(0,0) = r0 and B(2,0) = 0 are not stored
  rotate_cols(U, 0, 2, c, s);
  givens(B(1, 1), B(2, 1), std::sqrt(B(1, 1) * B(1, 1) + B(2, 1) * B(2, 1)), c, s);
  rotate_rows(B, 1, 2, 1, c, s);
  rotate_cols(U, 1, 2, c, s);

  // 4. Trailing block [a b; 0 d] of R, scaled to max |entry| = 1. An exact Jacobi rotation
  //    (cr, sr) of its columns makes them orthogonal; it is computed from the block's own Gram
  //    matrix [a^2 ab; ab b^2+d^2], whose rounding errors are relative to the block, not to
  //    sigma[0]. A Givens rotation (cl, sl) of its rows then leaves diag(s1, s2). The scaling
  //    keeps the fourth powers in r below from underflowing, which would make the shortcut for
  //    s1 inconsistent with the rotation and U not orthogonal.
  const T k = max2(max2(std::fabs(B(1, 1)), std::fabs(B(1, 2))), max2(std::fabs(B(2, 2)), min_normal));
  const T k_inv = T(1) / k;
  const T a = k_inv * B(1, 1), b = k_inv * B(1, 2), d = k_inv * B(2, 2);
  const T g11 = a * a, g22 = b * b + d * d;
  const T f = g11 - g22;
  const T e = T(2) * a * b;
  const T r = std::sqrt(f * f + e * e);
  // The smaller root of tan(2 theta) = e / f: tan(theta) = e' / u with e' = sign(f) e,
  // u = |f| + r >= |e'|, so (cos, sin)(theta) = (u, e') / sqrt(u^2 + e'^2). It keeps the longer
  // column first. Step 2 sorted by norms that include R(0,1), R(0,2) (O(eps sigma[0])), so when
  // sigma[1] is that small the shorter one can come first here (f < 0): then a further quarter
  // turn (cr, sr) <- (-sr, cr) swaps them. u >= tiny keeps (1, 0) for a zero block.
  const T u = max2(std::fabs(f) + r, tiny);
  const T ep = f < T(0) ? -e : e;
  const T h = T(1) / std::sqrt(u * u + ep * ep);
  const T cr = f < T(0) ? -ep * h : u * h;
  const T sr = f < T(0) ? u * h : ep * h;
  const T x1 = cr * a + sr * b, y1 = sr * d;  // first column of the block times G_r
  const T x2 = cr * b - sr * a, y2 = cr * d;  // second column
  // |(x1, y1)| = s1 = sqrt of the larger eigenvalue of the Gram matrix, known from r already.
  const T s1 = std::sqrt(T(0.5) * (g11 + g22 + r));
  T cl, sl;
  givens(x1, y1, s1, cl, sl);
  const T s2 = cl * y2 - sl * x2;
  rotate_cols(V, 1, 2, cr, sr);
  rotate_cols(U, 1, 2, cl, sl);

  // Undo the scalings. The clamps only move values by rounding: the sort of step 2 orders the
  // singular values up to O(eps sigma[0]), and this makes the documented order exact.
  sigma[0] = m * r0;
  sigma[1] = min2(m * (k * s1), sigma[0]);
  sigma[2] = std::copysign(min2(m * (k * std::fabs(s2)), sigma[1]), s2);
}

}  // namespace svd3_detail

template <class T>
FIRN_HD void svd3(const Mat3<T>& A, Mat3<T>& U, Vec3<T>& sigma, Mat3<T>& V) {
  svd3_detail::svd3_sweeps(A, U, sigma, V, svd3_detail::Traits<T>::kSweeps);
}

// U diag(sigma) V^T: a matrix rebuilt from (possibly modified) singular values.
template <class T>
FIRN_HD Mat3<T> svd_compose(const Mat3<T>& U, const Vec3<T>& sigma, const Mat3<T>& V) {
  Mat3<T> US = U;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) US(r, k) *= sigma[k];
  return mul_transposed(US, V);
}

template <class T>
FIRN_HD Mat3<T> polar_rotation(const Mat3<T>& A) {
  Mat3<T> U, V;
  Vec3<T> sigma;
  svd3(A, U, sigma, V);
  return mul_transposed(U, V);
}

}  // namespace firn

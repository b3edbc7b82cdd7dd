// Compressible Mooney-Rivlin elasticity (thesis Eq. 4.1-4.4; DESIGN.md section 4):
//   W = U(J) + G1/2 (I1bar - 3) + G2/2 (I2bar - 3),   U(J) = K/2 (1/2 (J^2 - 1) - ln J)   (Eq. 4.1, 4.2)
//   I1bar = J^(-2/3) tr B,   I2bar = 1/2 (I1bar^2 - J^(-4/3) tr(B^2))                     (Eq. 4.3, 4.4)
// with B = F F^T. (The thesis prints J^(2/3) under tr(B^2) in Eq. 4.4; the isochoric invariant
// needs J^(4/3) = (J^(2/3))^2, which is what makes I2bar independent of J.) The Kirchhoff stress
// tau = 2 (dW/dB) B (isochoric invariants, e.g. Holzapfel, Nonlinear Solid Mechanics, ch. 6) is
//   tau = K/2 (J^2 - 1) I + G1 J^(-2/3) dev(B) + G2 J^(-4/3) dev(I1 B - B^2),   I1 = tr B.
// The small-strain shear modulus is G1 + G2.
#pragma once

#include <cmath>

#include "kernels/constitutive/plastic_state.hpp"
#include "kernels/hd.hpp"
#include "kernels/lane_math.hpp"
#include "kernels/lanes.hpp"
#include "kernels/mat3.hpp"

namespace firn {

template <class T>
struct MooneyRivlin {
  static constexpr const char* kName = "mooney_rivlin";
  static constexpr bool kPlastic = false, kUsesAlpha = false, kUsesJp = false;
  T K;   // bulk modulus
  T G1;  // I1bar coefficient
  T G2;  // I2bar coefficient

  FIRN_HD T p_wave_modulus(const PlasticState<T>& = {}) const { return K + T(4) / T(3) * (G1 + G2); }

  FIRN_HD Mat3<T> kirchhoff(const Mat3<T>& F, const PlasticState<T>& = {}) const { return kirchhoff_of(F); }

  FIRN_HD Mat3<T> kirchhoff_of(const Mat3<T>& F) const {
    const Mat3<T> B = mul_transposed(F, F);
    const T J = determinant(F);
    const T Jm23 = pow_minus_two_thirds(J);
    const T I1 = trace(B);
    Mat3<T> tau = (G1 * Jm23) * B;
    T diag = K / T(2) * (J * J - T(1)) - G1 * Jm23 * I1 / T(3);
    if (G2 != T(0)) {
      const Mat3<T> A = I1 * B - B * B;  // dev(A) with tr A = I1^2 - tr(B^2)
      tau = tau + (G2 * Jm23 * Jm23) * A;
      diag -= G2 * Jm23 * Jm23 * trace(A) / T(3);
    }
    for (int d = 0; d < 3; ++d) tau(d, d) += diag;
    return tau;
  }

  // The same stress on W particles at once (kernels/lanes.hpp), one loop over the lanes with a
  // lane's whole computation in scalar code (FIRN_NOINLINE; plain scalars, since GCC 12 does not
  // vectorise the loop around a Mat3 local), J^(-1/3) by inverse_root. Returns tau's six entries
  // in ParticleView::tau's order (00, 11, 22, 01, 12, 20).
  template <int W>
  FIRN_HD void kirchhoff_lanes(const Mat3<Lanes<T, W>>& F, Lanes<T, W> (&tau)[6]) const {
    if (G2 != T(0))
      kirchhoff_loop<true>(F, tau);
    else
      kirchhoff_loop<false>(F, tau);  // the thesis' snow
  }

  FIRN_HD T energy_density(const Mat3<T>& F, const PlasticState<T>& = {}) const {
    const Mat3<T> B = mul_transposed(F, F);
    const T J = determinant(F);
    const T Jm23 = T(1) / (std::cbrt(J) * std::cbrt(J));
    const T I1bar = Jm23 * trace(B);
    const T I2bar = T(0.5) * (I1bar * I1bar - Jm23 * Jm23 * ddot(B, B));  // tr(B^2) = B : B, B symmetric
    const T U = K / T(2) * (T(0.5) * (J * J - T(1)) - std::log(J));
    return U + G1 / T(2) * (I1bar - T(3)) + G2 / T(2) * (I2bar - T(3));
  }

 private:
  // kirchhoff_lanes' loop, with or without the G2 term (a branch inside would keep it scalar).
  template <bool kG2, int W>
  FIRN_NOINLINE FIRN_HD void kirchhoff_loop(const Mat3<Lanes<T, W>>& F, Lanes<T, W> (&tau)[6]) const {
    FIRN_LANES
    for (int l = 0; l < W; ++l) {
      T f[9];
      FIRN_UNROLL
      for (int q = 0; q < 9; ++q) f[q] = F.m[q].v[l];
      // B = F F^T, in tau's order.
      const T b[6] = {rows_dot(f, 0, 0), rows_dot(f, 1, 1), rows_dot(f, 2, 2),
                      rows_dot(f, 0, 1), rows_dot(f, 1, 2), rows_dot(f, 2, 0)};
      const T J = determinant_of_rows(f);
      const T y = inverse_root<3>(J), Jm23 = y * y;
      const T I1 = b[0] + b[1] + b[2];
      T t[6], diag = K / T(2) * (J * J - T(1)) - G1 * Jm23 * I1 / T(3);
      FIRN_UNROLL
      for (int c = 0; c < 6; ++c) t[c] = (G1 * Jm23) * b[c];
      if constexpr (kG2) {
        // A = I1 B - B^2, symmetric; B^2's entries from b in tau's order.
        const T bb[6] = {b[0] * b[0] + b[3] * b[3] + b[5] * b[5], b[3] * b[3] + b[1] * b[1] + b[4] * b[4],
                         b[5] * b[5] + b[4] * b[4] + b[2] * b[2], b[0] * b[3] + b[3] * b[1] + b[5] * b[4],
                         b[3] * b[5] + b[1] * b[4] + b[4] * b[2], b[5] * b[0] + b[4] * b[3] + b[2] * b[5]};
        T a[6];
        FIRN_UNROLL
        for (int c = 0; c < 6; ++c) a[c] = I1 * b[c] - bb[c];
        const T g = G2 * Jm23 * Jm23;
        FIRN_UNROLL
        for (int c = 0; c < 6; ++c) t[c] = t[c] + g * a[c];
        diag -= g * (a[0] + a[1] + a[2]) / T(3);
      }
      FIRN_UNROLL
      for (int c = 0; c < 6; ++c) tau[c].v[l] = c < 3 ? t[c] + diag : t[c];
    }
  }
};

}  // namespace firn

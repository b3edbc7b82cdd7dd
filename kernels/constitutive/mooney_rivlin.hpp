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

  // The stress of F, where V is T or Lanes of T (kernels/lanes.hpp): W particles at once.
  template <class V>
  FIRN_HD Mat3<V> kirchhoff_of(const Mat3<V>& F) const {
    const Mat3<V> B = mul_transposed(F, F);
    const V J = determinant(F);
    const V Jm23 = pow_minus_two_thirds(J);
    const V I1 = trace(B);
    Mat3<V> tau = (V(G1) * Jm23) * B;
    V diag = V(K / T(2)) * (J * J - V(T(1))) - V(G1) * Jm23 * I1 / V(T(3));
    if (G2 != T(0)) {
      const Mat3<V> A = I1 * B - B * B;  // dev(A) with tr A = I1^2 - tr(B^2)
      tau = tau + (V(G2) * Jm23 * Jm23) * A;
      diag -= V(G2) * Jm23 * Jm23 * trace(A) / V(T(3));
    }
    for (int d = 0; d < 3; ++d) tau(d, d) += diag;
    return tau;
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
};

}  // namespace firn

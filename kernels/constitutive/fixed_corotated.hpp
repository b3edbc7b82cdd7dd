// Fixed-corotated elasticity (Stomakhin et al. 2012, "Energetically consistent invertible
// elasticity", Eq. 2-3; DESIGN.md section 4):
//   W = mu sum (sigma_i - 1)^2 + lambda/2 (J - 1)^2,   tau = 2 mu (F - R) F^T + lambda (J - 1) J I,
// with F = R S the polar decomposition (R a rotation even for inverted F, from the signed SVD).
#pragma once

#include "kernels/constitutive/plastic_state.hpp"
#include "kernels/hd.hpp"
#include "kernels/mat3.hpp"
#include "kernels/svd3.hpp"

namespace firn {

template <class T>
struct FixedCorotated {
  static constexpr const char* kName = "fixed_corotated";
  static constexpr bool kPlastic = false, kUsesAlpha = false, kUsesJp = false;
  T mu;
  T lambda;

  FIRN_HD T p_wave_modulus(const PlasticState<T>& = {}) const { return lambda + T(2) * mu; }

  FIRN_HD Mat3<T> kirchhoff(const Mat3<T>& F, const PlasticState<T>& = {}) const {
    const Mat3<T> R = polar_rotation(F);
    const T J = determinant(F);
    Mat3<T> tau = (T(2) * mu) * mul_transposed(F - R, F);
    const T p = lambda * (J - T(1)) * J;
    for (int d = 0; d < 3; ++d) tau(d, d) += p;
    return tau;
  }

  FIRN_HD T energy_density(const Mat3<T>& F, const PlasticState<T>& = {}) const {
    Mat3<T> U, V;
    Vec3<T> s;
    svd3(F, U, s, V);
    const T J = s[0] * s[1] * s[2];
    T e = T(0);
    for (int d = 0; d < 3; ++d) e += (s[d] - T(1)) * (s[d] - T(1));
    return mu * e + T(0.5) * lambda * (J - T(1)) * (J - T(1));
  }
};

}  // namespace firn

// Compressible neo-Hookean elasticity (Bonet and Wood, Nonlinear Continuum Mechanics, Eq. 6.28):
//   W = mu/2 (tr B - 3) - mu ln J + lambda/2 (ln J)^2,   tau = mu (B - I) + lambda ln(J) I,
// with B = F F^T and J = det F (DESIGN.md section 4).
#pragma once

#include <cmath>

#include "kernels/constitutive/plastic_state.hpp"
#include "kernels/hd.hpp"
#include "kernels/mat3.hpp"

namespace firn {

template <class T>
struct NeoHookean {
  static constexpr const char* kName = "neo_hookean";
  static constexpr bool kPlastic = false, kUsesAlpha = false, kUsesJp = false;
  T mu;
  T lambda;

  FIRN_HD T p_wave_modulus(const PlasticState<T>& = {}) const { return lambda + T(2) * mu; }

  FIRN_HD Mat3<T> kirchhoff(const Mat3<T>& F, const PlasticState<T>& = {}) const {
    Mat3<T> tau = mu * mul_transposed(F, F);
    const T p = lambda * std::log(determinant(F)) - mu;
    for (int d = 0; d < 3; ++d) tau(d, d) += p;
    return tau;
  }

  FIRN_HD T energy_density(const Mat3<T>& F, const PlasticState<T>& = {}) const {
    const T lnJ = std::log(determinant(F));
    return T(0.5) * mu * (ddot(F, F) - T(3)) - mu * lnJ + T(0.5) * lambda * lnJ * lnJ;
  }
};

}  // namespace firn

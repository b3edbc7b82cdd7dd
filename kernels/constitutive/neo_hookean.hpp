// Compressible neo-Hookean elasticity (Bonet and Wood, Nonlinear Continuum Mechanics, Eq. 6.28):
//   W = mu/2 (tr B - 3) - mu ln J + lambda/2 (ln J)^2,   tau = mu (B - I) + lambda ln(J) I,
// with B = F F^T and J = det F (DESIGN.md section 4).
#pragma once

#include <cmath>

#include "kernels/constitutive/plastic_state.hpp"
#include "kernels/hd.hpp"
#include "kernels/lanes.hpp"
#include "kernels/mat3.hpp"

namespace firn {

template <class T>
struct NeoHookean {
  static constexpr const char* kName = "neo_hookean";
  static constexpr bool kPlastic = false, kUsesAlpha = false, kUsesJp = false;
  static constexpr bool kLanes = true;  // kirchhoff_lanes (kernels/step/constitutive_update.hpp)
  T mu;
  T lambda;

  FIRN_HD T p_wave_modulus(const PlasticState<T>& = {}) const { return lambda + T(2) * mu; }

  FIRN_HD Mat3<T> kirchhoff(const Mat3<T>& F, const PlasticState<T>& = {}) const {
    Mat3<T> tau = mu * mul_transposed(F, F);
    const T p = lambda * std::log(determinant(F)) - mu;
    for (int d = 0; d < 3; ++d) tau(d, d) += p;
    return tau;
  }

  // kirchhoff() on W particles at once (kernels/lanes.hpp; issue 15): B = F F^T and J in one loop
  // over the lanes (one lane's F as 9 scalars row by row, the form GCC 12 vectorises; MooneyRivlin
  // does the same), ln J from the C library lane by lane, as kirchhoff() takes it, then tau with
  // kirchhoff()'s operations: the same bits. tau's six entries in ParticleView::tau's order (00, 11,
  // 22, 01, 12, 20).
  template <int W>
  FIRN_NOINLINE FIRN_HD void kirchhoff_lanes(const Mat3<Lanes<T, W>>& F, Lanes<T, W> (&tau)[6]) const {
    Lanes<T, W> B[6], J;
    FIRN_LANES
    for (int l = 0; l < W; ++l) {
      T f[9];
      FIRN_UNROLL
      for (int q = 0; q < 9; ++q) f[q] = F.m[q].v[l];
      B[0].v[l] = rows_dot(f, 0, 0);
      B[1].v[l] = rows_dot(f, 1, 1);
      B[2].v[l] = rows_dot(f, 2, 2);
      B[3].v[l] = rows_dot(f, 0, 1);
      B[4].v[l] = rows_dot(f, 1, 2);
      B[5].v[l] = rows_dot(f, 2, 0);
      J.v[l] = determinant_of_rows(f);
    }
    Lanes<T, W> lnJ;
    for (int l = 0; l < W; ++l) lnJ.v[l] = std::log(J.v[l]);
    FIRN_LANES
    for (int l = 0; l < W; ++l) {
      const T p = lambda * lnJ.v[l] - mu;
      FIRN_UNROLL
      for (int c = 0; c < 6; ++c) tau[c].v[l] = c < 3 ? mu * B[c].v[l] + p : mu * B[c].v[l];
    }
  }

  FIRN_HD T energy_density(const Mat3<T>& F, const PlasticState<T>& = {}) const {
    const T lnJ = std::log(determinant(F));
    return T(0.5) * mu * (ddot(F, F) - T(3)) - mu * lnJ + T(0.5) * lambda * lnJ * lnJ;
  }
};

}  // namespace firn

// Bimodular Hencky elasticity: stiff in tension, soft in compression, as a sheet of cords in rubber
// (the bimodular model that Bert developed for cord-rubber tire composites, C. W. Bert, "Models for
// fibrous composites with different properties in tension and compression", J. Eng. Mater.
// Technol. 99, 1977; after Ambartsumyan's bimodular elasticity). With e_i = ln(lambda_i) the
// logarithmic principal stretches (F = U diag(lambda) V^T), Hencky's quadratic energy keeps its
// moduli where a strain is a stretch and takes `compression_ratio` c of them where it shortens:
//   W = mu sum_i s(e_i) e_i^2 + lambda/2 s(ln J) (ln J)^2,   s(x) = 1 for x > 0, c otherwise,
// so the Kirchhoff stress, coaxial with B = F F^T, is (Hencky: tau_i = dW/de_i)
//   tau = U diag(tau_i) U^T,   tau_i = 2 mu s(e_i) e_i + lambda s(ln J) ln J.
// W is continuously differentiable and convex in e. With c = 0 it carries tension only (a wrinkling
// membrane's tension field); a small c, the rubber between the cords, keeps particles from
// collapsing onto each other where the sheet is slack. A tire sidewall of it holds the rim up
// from the top and goes slack under the axle, as corded sidewalls do. An inverted F (a negative
// signed singular value) counts as a stretch of 1e-30.
#pragma once

#include <cmath>

#include "kernels/constitutive/plastic_state.hpp"
#include "kernels/hd.hpp"
#include "kernels/mat3.hpp"
#include "kernels/svd3.hpp"

namespace firn {

template <class T>
struct Bimodular {
  static constexpr const char* kName = "bimodular";
  static constexpr bool kPlastic = false, kUsesAlpha = false, kUsesJp = false;
  T mu;
  T lambda;
  T compression_ratio;  // c: the moduli in compression over those in tension, in [0, 1]

  // The stiffness in tension, the larger, sets the time step.
  FIRN_HD T p_wave_modulus(const PlasticState<T>& = {}) const { return lambda + T(2) * mu; }

  FIRN_HD Mat3<T> kirchhoff(const Mat3<T>& F, const PlasticState<T>& = {}) const {
    Mat3<T> U, V;
    Vec3<T> e;
    log_stretches(F, U, e, V);
    const T lnJ = e[0] + e[1] + e[2];
    const T volume = lambda * scaled(lnJ);
    const Mat3<T> tau_u = U * Mat3<T>::diag(T(2) * mu * scaled(e[0]) + volume, T(2) * mu * scaled(e[1]) + volume,
                                           T(2) * mu * scaled(e[2]) + volume);
    return mul_transposed(tau_u, U);
  }

  FIRN_HD T energy_density(const Mat3<T>& F, const PlasticState<T>& = {}) const {
    Mat3<T> U, V;
    Vec3<T> e;
    log_stretches(F, U, e, V);
    const T lnJ = e[0] + e[1] + e[2];
    T w = T(0.5) * lambda * scaled(lnJ) * lnJ;
    for (int d = 0; d < 3; ++d) w += mu * scaled(e[d]) * e[d];
    return w;
  }

 private:
  // s(x) x.
  FIRN_HD T scaled(T x) const { return x > T(0) ? x : compression_ratio * x; }

  FIRN_HD static void log_stretches(const Mat3<T>& F, Mat3<T>& U, Vec3<T>& e, Mat3<T>& V) {
    Vec3<T> s;
    svd3(F, U, s, V);
    constexpr T kTiny = T(1e-30);
    for (int d = 0; d < 3; ++d) e[d] = std::log(s[d] > kTiny ? s[d] : kTiny);
  }
};

}  // namespace firn

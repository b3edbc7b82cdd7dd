// Stomakhin snow (Stomakhin, Schroeder, Chai, Teran, Selle, "A material point method for snow
// simulation", SIGGRAPH 2013; thesis Eq. 4.6; NairnMPM "ClampedNeohookean"; DESIGN.md section 4).
// F = F_E F_P; the engine's F holds F_E and the plastic state keeps J_P = det F_P.
//   energy (Eq. 4.6): fixed-corotated in F_E with mu(J_P) = mu0 e^(xi (1 - J_P)), lambda(J_P) = lambda0 e^(xi (1 -
//   J_P)) (Stomakhin et al. 2013, "Constitutive model"), so tau = the fixed-corotated stress (fixed_corotated.hpp) with
//   those moduli; return (Stomakhin et al. 2013, "Update deformation gradient"): trial F_E = U diag(s) V^T, s_i clamped
//   to [1 - theta_c, 1 + theta_s], F_E = U diag(s_clamped) V^T, and the rest goes to F_P: J_P <- J_P det(s) /
//   det(s_clamped), which keeps det(F_E) J_P = J. An optional clamp of J_P to [Jp_min, Jp_max] bounds the hardening
//   factor; where it acts, the clamped-away plastic volume is forgotten and det(F_E) J_P no longer equals J. Inverted
//   F_E (det <= 0) is left unchanged: clamping it would flip the sign of J_P.
#pragma once

#include <cmath>

#include "kernels/constitutive/fixed_corotated.hpp"
#include "kernels/constitutive/plastic_state.hpp"
#include "kernels/hd.hpp"
#include "kernels/mat3.hpp"
#include "kernels/svd3.hpp"

namespace firn {

template <class T>
struct SnowStomakhin {
  static constexpr const char* kName = "snow_stomakhin";
  static constexpr bool kPlastic = true, kUsesAlpha = false, kUsesJp = true;
  T mu, lambda;        // mu0, lambda0 at J_P = 1
  T xi;                // hardening coefficient
  T theta_c, theta_s;  // critical compression and stretch
  T Jp_min, Jp_max;    // clamp of J_P

  // e^(xi (1 - J_P)), Stomakhin et al. 2013, "Constitutive model".
  FIRN_HD T hardening_factor(const PlasticState<T>& state) const { return std::exp(xi * (T(1) - state.Jp)); }

  FIRN_HD FixedCorotated<T> hardened(const PlasticState<T>& state) const {
    const T h = hardening_factor(state);
    return FixedCorotated<T>{h * mu, h * lambda};
  }

  FIRN_HD T p_wave_modulus(const PlasticState<T>& state) const {
    return (lambda + T(2) * mu) * hardening_factor(state);
  }
  FIRN_HD Mat3<T> kirchhoff(const Mat3<T>& F, const PlasticState<T>& state) const {
    return hardened(state).kirchhoff(F);
  }
  FIRN_HD T energy_density(const Mat3<T>& F, const PlasticState<T>& state) const {
    return hardened(state).energy_density(F);
  }

  // The elastic energy the clamp takes out, W(F_trial; Jp_n) - W(F_returned; Jp_n+1): to first
  // order in the step, the work of the stress on the plastic strain increment (the clamp has no
  // flow rule whose work could be integrated instead).
  FIRN_HD T plastic_work(const Mat3<T>& F_trial, const PlasticState<T>& before, const Mat3<T>& F_returned,
                         const PlasticState<T>& after) const {
    return energy_density(F_trial, before) - energy_density(F_returned, after);
  }

  FIRN_HD bool project(Mat3<T>& F, PlasticState<T>& state) const {
    Mat3<T> U, V;
    Vec3<T> s;
    svd3(F, U, s, V);
    if (!(s[2] > T(0))) return false;  // inverted or NaN: left for the stability guard to name
    const T lo = T(1) - theta_c, hi = T(1) + theta_s;
    bool clamped = false;
    T ratio = T(1);  // det(s) / det(s_clamped), formed factor by factor
    for (int d = 0; d < 3; ++d) {
      const T c = s[d] < lo ? lo : (s[d] > hi ? hi : s[d]);
      if (c != s[d]) {
        clamped = true;
        ratio *= s[d] / c;
        s[d] = c;
      }
    }
    if (!clamped) return false;
    const T Jp = state.Jp * ratio;
    state.Jp = Jp < Jp_min ? Jp_min : (Jp > Jp_max ? Jp_max : Jp);
    F = svd_compose(U, s, V);
    return true;
  }
};

}  // namespace firn

// Cam-clay snow: snow that compacts, has cohesion and softens (DESIGN.md section 4, snow_cam_clay;
// issue 16). The modified Cam-clay yield surface of Gaume et al. 2018 (Nature Communications
// 9:3047, "Dynamic anticrack propagation in snow") with the non-associative return mapping of
// Wolper et al. 2019 (CD-MPM, ACM TOG 38(4):119, "NACC"), written here in the principal
// space of the elastic left Cauchy-Green tensor.
//
// Storage: the engine's F holds F_E; the plastic state keeps J_P = det F_P, so J = det(F_E) J_P.
// Elasticity: Mooney-Rivlin with G2 = 0 (kernels/constitutive/mooney_rivlin.hpp),
//   tau = G J_E^(-2/3) dev(b_e) + K/2 (J_E^2 - 1) I,
// with p_tau = -tr(tau)/3 = K/2 (1 - J_E^2) (positive in compression) and q_tau = sqrt(3/2) ||dev tau||.
// The yield surface is one of the true (Cauchy) stress sigma = tau / J, J = J_E J_P the total
// volume ratio, since that is what a plate or a piston measures and what laboratory compaction
// data give: p = p_tau / J, q = q_tau / J. (A surface in tau, as in CD-MPM's code, would put the
// measured pressure of snow compacted to J_P = 0.4 at 2.5 times its yield pressure.) J is fixed
// during a return, so the surface in tau is the Cauchy one with p0 scaled by J.
// Yield (Gaume et al. 2018):  y(p, q) = (1 + 2 beta) q^2 + M^2 (p + beta p0)(p - p0) <= 0,
// an ellipse in (p, q) from the tensile tip p = -beta p0 to the compressive tip p = p0, with M the
// slope of the critical state line and beta p0 the cohesion; p0 hardens with compaction and
// softens with dilation (kernels/constitutive/cam_clay_hardening.hpp).
//
// Return mapping for a trial state with y > 0 (after Wolper et al. 2019, with implicit
// hardening at the tips):
//   p > p0 (beyond the compressive tip): project to the tip, q = 0 and p = p0(J_P,new), where
//     J_P,new = J / J_E(p_tau) and J_E(p_tau) = sqrt(1 - 2 p_tau / K): one scalar equation, solved by
//     safeguarded Newton; the plastic volume change is compaction, so p0 rises (hardening).
//   p < -beta p0 (beyond the tensile tip): q = 0 and p = -beta p0(J_P,new): dilation, p0 and the
//     cohesion with it fall (softening); once p0 = 0 the snow carries no stress until it is
//     compacted again.
//   otherwise: keep p (so J_E and J_P) and scale q onto the surface,
//     q = sqrt(-M^2 (p + beta p0)(p - p0) / (1 + 2 beta)): the non-associative flow of NACC, with
//     no plastic volume change inside the tips.
// The new F_E = U diag(sigma) V^T has dev(bbar_e) = (q / q_tr) dev(bbar_tr) and det = J_E(p)
// (kernels/constitutive/deviator_rescale.hpp). The elastic path (y <= 0) costs one F F^T and no SVD.
#pragma once

#include <cmath>

#include "kernels/constitutive/cam_clay_hardening.hpp"
#include "kernels/constitutive/deviator_rescale.hpp"
#include "kernels/constitutive/mooney_rivlin.hpp"
#include "kernels/constitutive/plastic_state.hpp"
#include "kernels/float_limits.hpp"
#include "kernels/hd.hpp"
#include "kernels/mat3.hpp"
#include "kernels/svd3.hpp"

namespace firn {

template <class T>
struct SnowCamClay {
  static constexpr const char* kName = "snow_cam_clay";
  static constexpr bool kPlastic = true, kUsesAlpha = false, kUsesJp = true;
  MooneyRivlin<T> elastic;  // G2 = 0
  T M;                      // slope of the critical state line
  T beta;                   // cohesion: the tensile tip is at -beta p0
  CamClayHardening<T> hardening;

  FIRN_HD T p_wave_modulus(const PlasticState<T>& = {}) const { return elastic.p_wave_modulus(); }
  FIRN_HD Mat3<T> kirchhoff(const Mat3<T>& F, const PlasticState<T>& = {}) const { return elastic.kirchhoff(F); }
  FIRN_HD T energy_density(const Mat3<T>& F, const PlasticState<T>& = {}) const { return elastic.energy_density(F); }

  FIRN_HD T consolidation_pressure(const PlasticState<T>& state) const {
    return hardening.pressure(-std::log(state.Jp));
  }

  // y(p, q) above, in Cauchy stress, for the elastic F and the state; <= 0 is admissible. Units Pa^2.
  FIRN_HD T yield_function(const Mat3<T>& F, const PlasticState<T>& state) const {
    T J, Jm23, Ibar, q;
    invariants(F, J, Jm23, Ibar, q);
    const T Jt = J * state.Jp;
    const T p = elastic.K / T(2) * (T(1) - J * J) / Jt, qc = q / Jt;
    const T p0 = consolidation_pressure(state);
    return (T(1) + T(2) * beta) * qc * qc + M * M * (p + beta * p0) * (p - p0);
  }

  // First order in the step, as for Stomakhin's clamp: the elastic energy the return takes out,
  // W(F_trial) - W(F_returned), at fixed moduli.
  FIRN_HD T plastic_work(const Mat3<T>& F_trial, const PlasticState<T>&, const Mat3<T>& F_returned,
                         const PlasticState<T>&) const {
    return elastic.energy_density(F_trial) - elastic.energy_density(F_returned);
  }

  FIRN_HD bool project(Mat3<T>& F, PlasticState<T>& state) const {
    T J, Jm23, Ibar, q;
    invariants(F, J, Jm23, Ibar, q);
    if (!(J > T(0))) return false;  // inverted or NaN: left for the stability guard to name
    // In Kirchhoff terms throughout: the Cauchy surface with p0 scaled by the total J (above).
    const T K = elastic.K;
    const T Jt = J * state.Jp;
    const T p = K / T(2) * (T(1) - J * J);
    const T eps = -std::log(state.Jp);
    const T p0 = Jt * hardening.pressure(eps);
    const T ellipse = M * M * (p + beta * p0) * (p - p0);
    if ((T(1) + T(2) * beta) * q * q + ellipse <= T(0)) return false;  // elastic

    T p_new = p, keep = T(0);
    if (p > p0)
      p_new = tip_pressure(Jt, p, J, eps);
    else if (p < -beta * p0)
      p_new = tip_pressure(-beta * Jt, p, J, eps);
    else
      keep = std::sqrt(-ellipse / (T(1) + T(2) * beta)) / q;  // q > 0: y > 0 with ellipse <= 0
    const T J_new = std::sqrt(T(1) - T(2) * p_new / K);
    state.Jp *= J / J_new;
    Mat3<T> U, V;
    Vec3<T> sig;
    svd3(F, U, sig, V);
    F = rescale_isochoric_deviator(U, sig, V, Jm23, Ibar, keep, J_new);
    return true;
  }

 private:
  // J = det F, J^(-2/3), tr(bbar_e)/3 and q = sqrt(3/2) G ||dev(bbar_e)||.
  FIRN_HD void invariants(const Mat3<T>& F, T& J, T& Jm23, T& Ibar, T& q) const {
    const Mat3<T> b = mul_transposed(F, F);
    J = determinant(F);
    Jm23 = T(1) / (std::cbrt(J) * std::cbrt(J));
    const T mean = trace(b) / T(3);
    Ibar = Jm23 * mean;
    Mat3<T> dev = b;
    for (int d = 0; d < 3; ++d) dev(d, d) -= mean;
    q = std::sqrt(T(1.5) * ddot(dev, dev)) * elastic.G1 * Jm23;
  }

  // The Kirchhoff pressure of a tip projection: the root of g(p) = p - a p0(eps(p)) with a = J_t
  // (compressive tip) or a = -beta J_t (tensile tip), J_t the total J, where eps(p) = -ln J_P,new
  // = eps_n + ln(J_E(p) / J) is the plastic compaction after the return. g(p_tr) has the sign of p_tr - a p0(eps_n) and g(0) =
  // -a p0 the other one, so [min(0, p_tr), max(0, p_tr)] brackets the root; safeguarded Newton
  // (Press et al., Numerical Recipes 3rd ed., sec. 9.4 "rtsafe"), as in solve_j2_return.
  FIRN_HD T tip_pressure(T a, T p_tr, T J, T eps_n) const {
    constexpr T kEps = FloatLimits<T>::kEpsilon;
    const T K = elastic.K;
    T lo = p_tr < T(0) ? p_tr : T(0), hi = p_tr < T(0) ? T(0) : p_tr;
    T x = a * hardening.pressure(eps_n);
    if (!(x > lo && x < hi)) x = T(0.5) * (lo + hi);
    for (int it = 0; it < 200; ++it) {
      const T JE2 = T(1) - T(2) * x / K;
      T p0, slope;
      hardening.evaluate(eps_n + T(0.5) * std::log(JE2 / (J * J)), p0, slope);
      const T g = x - a * p0;
      if (std::fabs(g) <= T(4) * kEps * std::fabs(p_tr)) break;
      if (g < T(0))
        lo = x;
      else
        hi = x;
      if (hi - lo <= T(2) * kEps * std::fabs(p_tr)) break;
      const T dg = T(1) + a * slope / (K * JE2);  // d eps / d p = -1 / (K J_E^2)
      const T newton = dg > T(0) ? x - g / dg : hi;
      x = (newton > lo && newton < hi) ? newton : T(0.5) * (lo + hi);
    }
    return x;
  }
};

}  // namespace firn

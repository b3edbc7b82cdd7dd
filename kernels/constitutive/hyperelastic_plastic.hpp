// Isotropic hyperelastic-plastic material (thesis Eq. 4.1-4.5; NairnMPM "HEIsotropic"; DESIGN.md
// section 4): Mooney-Rivlin elasticity of the elastic left Cauchy-Green tensor b_e = F_E F_E^T
// (kernels/constitutive/mooney_rivlin.hpp, G1 = G - G2), J2 plasticity with isotropic hardening
// (kernels/constitutive/j2_hardening.hpp) integrated by the radial return of Simo and Hughes,
// Computational Inelasticity, Box 9.1.
//
// Storage: the engine's F holds F_E. Plastic flow is isochoric, so J = det F_E is the total J.
//
// Return mapping (Box 9.1), with bbar = J^(-2/3) b_e and s = G1 dev(bbar_e) the deviatoric
// Kirchhoff stress of the G1 part:
//   1. trial: s_tr = G1 dev(bbar_tr), f_tr = ||s_tr|| - sqrt(2/3) sigma_y(alpha_n); f_tr <= 0: elastic.
//   2. mu_bar = G1 tr(bbar_tr) / 3, n = s_tr / ||s_tr||, dgamma from the consistency equation
//      (solve_j2_return), s = s_tr - 2 mu_bar dgamma n = (1 - beta) s_tr, beta = 2 mu_bar dgamma / ||s_tr||,
//      alpha_{n+1} = alpha_n + sqrt(2/3) dgamma.
//   3. elastic update consistent with s at any J. Box 9.1 step 4 reads bbar_e = s / G1 + (tr(bbar_tr)/3) I.
//      Multiplying by J^(2/3): dev(b_e) = J^(2/3) s / G1 = (1 - beta) dev(b_tr). A code that keeps the
//      Cauchy stress sigma = tau / J must write dev(b_e) = J^(5/3) dev(sigma) / G1; dropping that factor
//      J^(5/3) (issue 4 reports this of NairnMPM's HEIsotropic) leaves dev(b_e) too large by J^(-5/3),
//      7.4x at J = 0.3, so the next stress lands far outside the yield surface and compacted snow
//      diverges. Here the update acts on b_e itself, where the factor never appears.
//      Box 9.1's trace keeps tr(bbar_e) but not det(bbar_e) = 1, i.e. it would change J. The stress
//      depends on b_e only through J and dev(b_e), so the trace part is free: it is set to the x with
//      det(x I + (1 - beta) dev(bbar_tr)) = 1 (the volume-preserving variant of step 4, cf. Simo 1992,
//      CMAME 99:61-112), which keeps J and s exactly. Since b_e and b_tr share eigenvectors, F_E is
//      F_tr stretched by a symmetric tensor coaxial with b_tr (kernels/constitutive/deviator_rescale.hpp).
// Neither path takes an SVD: the elastic one costs one F F^T, the plastic one the square root of a
// symmetric 3x3 tensor (a series near the identity, a closed form elsewhere; on lanes, a series in
// dev(bbar_tr)).
//
// G2 != 0: the elastic response is the full Mooney-Rivlin one, but the yield function and the
// return above use only the G1 part s = G1 dev(bbar_e): after a return the G1 part of the
// deviatoric stress lies on the yield surface and the G2 part, G2 J^(-4/3) dev(I1 b_e - b_e^2), is
// whatever the returned b_e gives. With G2 = 0 (the thesis' snow) the return is exact.
#pragma once

#include <cmath>

#include "kernels/constitutive/deviator_rescale.hpp"
#include "kernels/constitutive/j2_hardening.hpp"
#include "kernels/constitutive/mooney_rivlin.hpp"
#include "kernels/constitutive/plastic_state.hpp"
#include "kernels/hd.hpp"
#include "kernels/lanes.hpp"
#include "kernels/mat3.hpp"

namespace firn {

template <class T>
struct HyperelasticPlastic {
  static constexpr const char* kName = "hyperelastic_plastic";
  static constexpr bool kPlastic = true, kUsesAlpha = true, kUsesJp = false;
  static constexpr bool kLanes = true;  // project_lanes
  MooneyRivlin<T> elastic;
  J2Hardening<T> hardening;

  FIRN_HD T p_wave_modulus(const PlasticState<T>& = {}) const { return elastic.p_wave_modulus(); }
  FIRN_HD Mat3<T> kirchhoff(const Mat3<T>& F, const PlasticState<T>& = {}) const { return elastic.kirchhoff(F); }
  FIRN_HD T energy_density(const Mat3<T>& F, const PlasticState<T>& = {}) const { return elastic.energy_density(F); }

  // ||s_tr|| - sqrt(2/3) sigma_y(alpha) for the G1 part of the stress (step 1 above); <= 0 is admissible.
  FIRN_HD T yield_function(const Mat3<T>& F, const PlasticState<T>& state) const {
    const Mat3<T> b = mul_transposed(F, F);
    const T J = determinant(F);
    const T Jm23 = T(1) / (std::cbrt(J) * std::cbrt(J));
    Mat3<T> dev = b;
    const T mean = trace(b) / T(3);
    for (int d = 0; d < 3; ++d) dev(d, d) -= mean;
    return elastic.G1 * Jm23 * std::sqrt(ddot(dev, dev)) - std::sqrt(T(2) / T(3)) * hardening.yield_stress(state.alpha);
  }

  // The work of the stress on the return's plastic strain increment per unit reference volume,
  // s : dgamma n = sqrt(2/3) sigma_y dgamma = sigma_y d(alpha) on the yield surface, with sigma_y by
  // the trapezoid rule over the step: exact on a linear-hardening path, second order otherwise
  // (Simo and Hughes, Computational Inelasticity, sec. 2.3 and Box 9.1). The elastic energy drop
  // W(F_trial) - W(F_returned) would exceed it by about G dgamma^2 per step.
  FIRN_HD T plastic_work(const Mat3<T>&, const PlasticState<T>& before, const Mat3<T>&,
                         const PlasticState<T>& after) const {
    return T(0.5) * (hardening.yield_stress(before.alpha) + hardening.yield_stress(after.alpha)) *
           (after.alpha - before.alpha);
  }

  FIRN_HD bool project(Mat3<T>& F, PlasticState<T>& state) const {
    const T J = determinant(F);
    if (!(J > T(0))) return false;  // inverted or NaN: left for the stability guard to name
    const Mat3<T> b = mul_transposed(F, F);
    const T Jm23 = T(1) / (std::cbrt(J) * std::cbrt(J));
    const T Ibar = Jm23 * trace(b) / T(3);
    Mat3<T> dev = b;
    for (int d = 0; d < 3; ++d) dev(d, d) -= trace(b) / T(3);
    const T s_norm = elastic.G1 * Jm23 * std::sqrt(ddot(dev, dev));
    const T sqrt23 = std::sqrt(T(2) / T(3));
    if (s_norm - sqrt23 * hardening.yield_stress(state.alpha) <= T(0)) return false;  // step 1: elastic

    // Step 2: radial return.
    const T mu_bar = elastic.G1 * Ibar;
    const T dgamma = solve_j2_return(hardening, state.alpha, s_norm, mu_bar).dgamma;
    const T keep = T(1) - T(2) * mu_bar * dgamma / s_norm;  // 1 - beta
    state.alpha += sqrt23 * dgamma;

    // Step 3: dev(bbar_e) = (1 - beta) dev(bbar_tr) at the same J (kernels/constitutive/deviator_rescale.hpp).
    F = rescale_isochoric_deviator(F, Jm23, Ibar, keep, J, T(1));
    return true;
  }

  // project() and plastic_work() on W particles at once (kernels/lanes.hpp), the lane form of the
  // same return: Newton without bisection for dgamma (solve_j2_return_lanes), the stretch sqrt(A) as
  // a series in dev(bbar_tr) (rescale_isochoric_deviator_lanes), J^(-1/3) and the power law by lane
  // arithmetic (kernels/lane_math.hpp) instead of the C library. Returns the lanes that yielded;
  // their F, alpha and plastic work density are updated, and every lane's Kirchhoff stress (in
  // ParticleView::tau's order) is that of the F it leaves (lane_stress). A lane outside that common
  // case (J <= 0, a softening law that leaves Newton's bracket, a deviator beyond the series'
  // radius) is cleared in `ok` with its values undefined, and the caller projects it with project().
  template <int W>
  FIRN_HD LaneMask<W> project_lanes(Mat3<Lanes<T, W>>& F, Lanes<T, W>& alpha, Lanes<T, W>& work, LaneMask<W>& ok,
                                    Lanes<T, W> (&tau)[6]) const {
    using L = Lanes<T, W>;
    L J, Ibar, D[6], dev_norm;
    isochoric_invariants_lanes(F, J, Ibar, D, dev_norm);
    ok = ok && J > L(T(0));
    const L s_norm = L(elastic.G1) * dev_norm;
    const L sqrt23(std::sqrt(T(2) / T(3)));
    L sigma_n, slope;
    hardening.evaluate(alpha, sigma_n, slope, ok);
    const LaneMask<W> yields = ok && s_norm - sqrt23 * sigma_n > L(T(0));  // step 1
    if (!any(yields)) {
      lane_stress(F, J, D, L(T(1)), tau);
      return yields;
    }

    const L mu_bar = L(elastic.G1) * Ibar;  // step 2
    L sigma_end;
    const L dgamma = solve_j2_return_lanes(hardening, alpha, s_norm, mu_bar, sigma_n, slope, yields, ok, sigma_end);
    const L keep = L(T(1)) - L(T(2)) * mu_bar * dgamma / s_norm;
    const L alpha_end = alpha + sqrt23 * dgamma;
    const Mat3<L> F_end = rescale_isochoric_deviator_lanes(F, D, Ibar, keep, J, yields, ok);  // step 3
    const LaneMask<W> plastic = yields && ok;
    work = select(plastic, L(T(0.5)) * (sigma_n + sigma_end) * (alpha_end - alpha), L(T(0)));
    alpha = select(plastic, alpha_end, alpha);
    for (int q = 0; q < 9; ++q) F.m[q] = select(plastic, F_end.m[q], F.m[q]);
    lane_stress(F, J, D, select(plastic, keep, L(T(1))), tau);
    return plastic;
  }

 private:
  // The Kirchhoff stress of the F project_lanes leaves, whose isochoric deviator is keep D at the
  // trial's J (keep = 1 where nothing was returned). With G2 = 0 (the thesis' snow) that is
  // MooneyRivlin's tau = G1 J^(-2/3) dev(b_e) + K/2 (J^2 - 1) I = G1 keep D + K/2 (J^2 - 1) I, from
  // what the return already holds, rather than from F F^T again (issue 15); with G2 != 0 it is
  // MooneyRivlin::kirchhoff_lanes of F.
  template <int W>
  FIRN_HD void lane_stress(const Mat3<Lanes<T, W>>& F, const Lanes<T, W>& J, const Lanes<T, W> (&D)[6],
                           const Lanes<T, W>& keep, Lanes<T, W> (&tau)[6]) const {
    using L = Lanes<T, W>;
    if (elastic.G2 != T(0)) {
      elastic.kirchhoff_lanes(F, tau);
      return;
    }
    const L shear = L(elastic.G1) * keep, pressure = L(elastic.K / T(2)) * (J * J - L(T(1)));
    for (int c = 0; c < 6; ++c) tau[c] = c < 3 ? shear * D[c] + pressure : shear * D[c];
  }
};

}  // namespace firn

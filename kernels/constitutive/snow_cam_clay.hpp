// Cam-clay snow: snow that compacts, has cohesion and breaks (DESIGN.md section 4, snow_cam_clay;
// issue 16). The modified Cam-clay yield surface of Gaume et al. 2018 (Nature Communications
// 9:3047, "Dynamic anticrack propagation in snow"), as used for snow and sand in MPM (Wolper et
// al. 2019, CD-MPM, ACM TOG 38(4):119), written here in the principal space of the elastic left
// Cauchy-Green tensor.
//
// Storage: the engine's F holds F_E; the plastic state keeps J_P = det F_P, so J = det(F_E) J_P.
// Elasticity: Mooney-Rivlin with G2 = 0 (kernels/constitutive/mooney_rivlin.hpp),
//   tau = G J_E^(-2/3) dev(b_e) + K/2 (J_E^2 - 1) I,
// with p_tau = -tr(tau)/3 = K/2 (1 - J_E^2) (positive in compression) and q_tau = sqrt(3/2) ||dev tau||.
// The yield surface is one of the true (Cauchy) stress sigma = tau / J, J = J_E J_P the total
// volume ratio, since that is what a plate or a piston measures and what laboratory compaction
// data give: p = p_tau / J, q = q_tau / J. (A surface in tau, as in CD-MPM's code, would put the
// measured pressure of snow compacted to J_P = 0.4 at 2.5 times its yield pressure.) J is fixed
// during a return.
// Yield (Gaume et al. 2018):  y(p, q) = (1 + 2 beta) q^2 + M^2 (p + beta p0)(p - p0) <= 0,
// an ellipse in (p, q) from the tensile tip p = -beta p0 to the compressive tip p = p0, centred at
// p_c = (1 - beta) p0 / 2 with semi-axes a = (1 + beta) p0 / 2 along p and b = M a / sqrt(1 + 2 beta)
// along q; M is the slope of the critical state line and beta p0 the cohesion; p0 hardens with
// compaction and softens with dilation (kernels/constitutive/cam_clay_hardening.hpp).
//
// Return mapping for a trial state (p_t, q_t) with y > 0: radially toward the ellipse's centre,
//   (p, q) = (p_c, 0) + ((p_t - p_c), q_t) / r,   r = sqrt(((p_t - p_c) / a)^2 + (q_t / b)^2),
// with the ellipse of the hardened p0 (implicit): p0 = h(-ln J_P,new), J_P,new = J / J_E(p) and
// J_E(p) = sqrt(1 - 2 J p / K), one scalar equation in p0 solved on a bracket (below). On the
// wet side (p_t > p_c) the return lowers p: the snow compacts and hardens, in shear as under a
// wheel, not only under pure pressure; on the dry side (p_t < p_c, tension) it raises p: the snow
// dilates and softens, so a pulled bar breaks. On the p axis (q_t = 0) it ends at the tips p0 and
// -beta p0.
// Under net tension (p_t < 0) where the centre lies in tension too (beta > 1, p_c < 0), the
// return goes radially toward the origin instead, (p, q) = t (p_t, q_t) with t < 1 putting it on
// the ellipse. Such a beta belongs to light snow, whose tensile strength is large against its
// compaction strength (fresh_snow's beta is 2.175), and a return toward its centre would compact
// snow that is pulled apart: a uniaxial tension path meets the ellipse between p_c and 0 once beta
// > 1.74, and fresh_snow pulled that way hardened instead of breaking (measured: 2.93 N held to 3%
// strain). From the origin the return raises p under any net tension, so pulled snow dilates and
// softens at every density; under net compression, and for beta <= 1, nothing changes. The start
// jumps at p_t = 0 (from the origin below, the centre above), so a trial sheared at a mean stress
// near zero returns without volume change on one side and with some compaction on the other; a
// start moving continuously toward the centre would change compressive returns, and with them the
// confined-compression calibration (data/snow/fit_cam_clay.py).
// This is the critical-state picture of loose and dense granular matter (Roscoe and
// Burland 1968; Schofield and Wroth, Critical State Soil Mechanics, 1968). It departs from CD-MPM's
// NACC return, which keeps p between the tips, changes no volume there, so it never softens in
// uniaxial tension or compacts in shear (measured: a pulled fresh_snow bar lost only 17% of its
// force by 3% strain and stayed in one piece; a wheel sank through 0.21 m of fresh snow).
// The new F_E, the trial one stretched by a symmetric tensor coaxial with b_tr, has
// dev(bbar_e) = (q / q_t) dev(bbar_tr) and det = J_E(p) (kernels/constitutive/deviator_rescale.hpp).
// Neither path takes an SVD: the elastic one (y <= 0) costs one F F^T.
// The lane form (project_lanes; kernels/lanes.hpp) checks W particles at once and
// hands the ones that yield to project(), so the common elastic case runs in vector lanes.
#pragma once

#include <cmath>

#include "kernels/constitutive/cam_clay_hardening.hpp"
#include "kernels/constitutive/deviator_rescale.hpp"
#include "kernels/constitutive/mooney_rivlin.hpp"
#include "kernels/constitutive/plastic_state.hpp"
#include "kernels/float_limits.hpp"
#include "kernels/hd.hpp"
#include "kernels/lane_math.hpp"
#include "kernels/lanes.hpp"
#include "kernels/mat3.hpp"

namespace firn {

template <class T>
struct SnowCamClay {
  static constexpr const char* kName = "snow_cam_clay";
  static constexpr bool kPlastic = true, kUsesAlpha = false, kUsesJp = true;
  static constexpr bool kLanes = true;  // project_lanes
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
    return yield(elastic.K / T(2) * (T(1) - J * J) / Jt, q / Jt, consolidation_pressure(state));
  }

  // First order in the step, as for Stomakhin's clamp: the elastic energy the return takes out,
  // W(F_trial) - W(F_returned), at fixed moduli.
  FIRN_HD T plastic_work(const Mat3<T>& F_trial, const PlasticState<T>&, const Mat3<T>& F_returned,
                         const PlasticState<T>&) const {
    return elastic.energy_density(F_trial) - elastic.energy_density(F_returned);
  }

  FIRN_HD bool project(Mat3<T>& F, PlasticState<T>& state) const {
    T J, Jm23, Ibar, q_tau;
    invariants(F, J, Jm23, Ibar, q_tau);
    if (!(J > T(0))) return false;  // inverted or NaN: left for the stability guard to name
    const T Jt = J * state.Jp;
    const T p = elastic.K / T(2) * (T(1) - J * J) / Jt, q = q_tau / Jt;  // Cauchy
    const T eps = -std::log(state.Jp);
    const T p0 = hardening.pressure(eps);
    if (yield(p, q, p0) <= T(0)) return false;  // elastic

    const Return r = radial_return(p, q, J, Jt, eps, p0);
    const T J_new = std::sqrt(T(1) - T(2) * Jt * r.p / elastic.K);
    state.Jp = Jt / J_new;
    F = rescale_isochoric_deviator(F, Jm23, Ibar, q > T(0) ? r.q / q : T(0), J_new, std::cbrt(J_new / J));
    return true;
  }

  // project() on W particles at once for the elastic case: the yield check of project() in lane
  // arithmetic (J^(-2/3) by kernels/lane_math.hpp; p0 per lane, as project() has it). A lane that
  // yields, or whose J is not positive, is cleared in `ok` and left unchanged for the caller to
  // project with project(); no lane is returned here, so the mask of lanes returned is empty,
  // `work` is zero and tau is the stress of F as it is (MooneyRivlin::kirchhoff_lanes, in
  // ParticleView::tau's order).
  template <int W>
  FIRN_HD LaneMask<W> project_lanes(const Mat3<Lanes<T, W>>& F, const Lanes<T, W>& Jp, Lanes<T, W>& work,
                                    LaneMask<W>& ok, Lanes<T, W> (&tau)[6]) const {
    using L = Lanes<T, W>;
    const L J = determinant(F);
    const Mat3<L> b = mul_transposed(F, F);
    const L mean = trace(b) / L(T(3));
    Mat3<L> dev = b;
    for (int d = 0; d < 3; ++d) dev(d, d) -= mean;
    const L Jt = J * Jp;
    const L p = L(elastic.K / T(2)) * (L(T(1)) - J * J) / Jt;
    const L q = sqrt(L(T(1.5)) * ddot(dev, dev)) * L(elastic.G1) * pow_minus_two_thirds(J) / Jt;
    L p0;
    for (int l = 0; l < W; ++l) p0.v[l] = consolidation_pressure(PlasticState<T>{T(0), Jp.v[l]});
    ok = ok && J > L(T(0)) && yield(p, q, p0) <= L(T(0));  // a NaN yield value is handed back too, as project() does
    work = L(T(0));
    elastic.kirchhoff_lanes(F, tau);
    return LaneMask<W>::none();
  }

 private:
  struct Return {
    T p, q;  // the returned Cauchy stress invariants
  };

  // y(p, q) for one particle (V = T) or W of them (V = Lanes<T, W>).
  template <class V>
  FIRN_HD V yield(const V& p, const V& q, const V& p0) const {
    return V(T(1) + T(2) * beta) * q * q + V(M * M) * (p + V(beta) * p0) * (p - p0);
  }

  // The point where the ray through (p, q) from the centre of the ellipse of size s, or from the
  // origin (`from_origin`; inside the ellipse, since -beta s < 0 < s), meets it. From the origin:
  // t (p, q) on the ellipse, ((t p - c) / a)^2 + (t q / b)^2 = 1, a quadratic in t with one positive
  // root.
  FIRN_HD Return on_ellipse(T p, T q, T s, bool from_origin) const {
    const T a = (T(1) + beta) * s / T(2), c = (T(1) - beta) * s / T(2);
    if (!(a > T(0))) return {T(0), T(0)};  // no strength: the ellipse is the origin
    const T b = M * a / std::sqrt(T(1) + T(2) * beta);
    if (from_origin) {
      const T u = p / a, v = q / b, w = c / a;
      const T A = u * u + v * v, B = u * w;  // A t^2 - 2 B t + w^2 - 1 = 0, w^2 < 1
      if (!(A > T(0))) return {p, q};  // at the origin: inside, nothing to return
      const T t = (B + std::sqrt(B * B + A * (T(1) - w * w))) / A;
      return {t * p, t * q};
    }
    const T u = (p - c) / a, v = q / b;
    const T r = std::sqrt(u * u + v * v);
    if (!(r > T(0))) return {p, q};  // at the centre: inside, nothing to return
    return {c + (p - c) / r, q / r};
  }

  // The implicit return: the size s = p0 with G(s) = s - h(eps(s)) = 0, where eps(s) = eps_n +
  // ln(J_E(p(s)) / J) is the plastic compaction after returning to the ellipse of size s. G(0) =
  // -h <= 0. Where the trial is outside the ellipse of p0_n, the larger root s_hi of y(p_t, q_t; s)
  // = 0 (a quadratic in s; the trial lies on that ellipse, so eps(s_hi) = eps_n) gives G(s_hi) =
  // s_hi - p0_n > 0; without a root (beta = 0 in tension) the bracket doubles until G > 0. Regula
  // falsi with the Illinois modification (Dowell and Jarratt, BIT 11:168, 1971) on [0, s_hi].
  FIRN_HD Return radial_return(T p, T q, T J, T Jt, T eps_n, T p0_n) const {
    constexpr T kEps = FloatLimits<T>::kEpsilon;
    const T K = elastic.K;
    // Under net tension the return starts from the origin where the centre lies in tension (beta >
    // 1), so that pulled snow dilates (see the top of this file).
    const bool from_origin = p < T(0) && beta > T(1);
    const auto residual = [&](T s, Return& ret) {
      ret = on_ellipse(p, q, s, from_origin);
      const T JE2 = T(1) - T(2) * Jt * ret.p / K;
      return s - hardening.pressure(eps_n + T(0.5) * std::log(JE2 / (J * J)));
    };
    // y(s) = -M^2 beta s^2 + M^2 (beta - 1) p s + (1 + 2 beta) q^2 + M^2 p^2.
    const T A = M * M * beta, B = M * M * (beta - T(1)) * p, C = (T(1) + T(2) * beta) * q * q + M * M * p * p;
    T hi;
    if (A > T(0))
      hi = (B + std::sqrt(B * B + T(4) * A * C)) / (T(2) * A);
    else if (B < T(0))
      hi = -C / B;
    else
      hi = T(0);
    Return ret;
    T g_hi = residual(hi, ret);
    for (int it = 0; it < 200 && !(g_hi > T(0)); ++it) {
      hi = hi > T(0) ? T(2) * hi : (p0_n > T(0) ? T(2) * p0_n : T(1));
      g_hi = residual(hi, ret);
    }
    T lo = T(0);
    T g_lo = residual(lo, ret);
    if (!(g_lo < T(0))) return ret;  // h = 0 at s = 0: no strength, the stress is zero
    int side = 0;
    for (int it = 0; it < 200; ++it) {
      const T s = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
      const T g = residual(s, ret);
      if (std::fabs(g) <= T(4) * kEps * hi || hi - lo <= T(4) * kEps * hi) break;
      if (g < T(0)) {
        lo = s, g_lo = g;
        if (side == -1) g_hi *= T(0.5);
        side = -1;
      } else {
        hi = s, g_hi = g;
        if (side == 1) g_lo *= T(0.5);
        side = 1;
      }
    }
    return ret;
  }

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
};

}  // namespace firn

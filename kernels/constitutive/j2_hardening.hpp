// Isotropic hardening laws for J2 plasticity and the scalar consistency equation of the radial
// return (Simo and Hughes, Computational Inelasticity, Box 9.1 step 3; DESIGN.md section 4):
//   f(dgamma) = ||s_trial|| - 2 mu_bar dgamma - sqrt(2/3) sigma_y(alpha_n + sqrt(2/3) dgamma) = 0,
// with alpha the equivalent plastic strain. Laws, each floored at sigma_y_min >= 0:
//   linear:    sigma_y = sigma_y0 + E_p alpha                (Simo and Hughes sec. 2.3, isotropic part)
//   nonlinear: sigma_y = sigma_y0 (1 + K_h alpha)^n          (thesis Eq. 4.5; NairnMPM NonlinearHardening)
// A negative E_p or K_h softens the material down to the floor; where 1 + K_h alpha <= 0 the
// nonlinear law is the floor itself.
#pragma once

#include <cmath>

#include "kernels/float_limits.hpp"
#include "kernels/hd.hpp"
#include "kernels/lane_math.hpp"
#include "kernels/lanes.hpp"

namespace firn {

enum class HardeningLaw : int { linear = 0, nonlinear = 1 };  // index into the catalog's choices

template <class T>
struct J2Hardening {
  HardeningLaw law;
  T sigma_y0;     // initial yield stress
  T E_p;          // linear: plastic modulus d sigma_y / d alpha
  T K_h, n;       // nonlinear: thesis Eq. 4.5 coefficients
  T sigma_y_min;  // floor of the yield stress under softening

  // The unfloored law and its slope d sigma_y / d alpha.
  FIRN_HD void raw(T alpha, T& sigma, T& slope) const {
    if (law == HardeningLaw::linear) {
      sigma = sigma_y0 + E_p * alpha;
      slope = E_p;
      return;
    }
    const T base = T(1) + K_h * alpha;
    if (base <= T(0)) {
      sigma = T(0);
      slope = T(0);
      return;
    }
    const T p = std::pow(base, n);
    sigma = sigma_y0 * p;
    slope = sigma_y0 * n * K_h * p / base;
  }

  // The floored law and its slope, in one evaluation of the power law.
  FIRN_HD void evaluate(T alpha, T& sigma, T& slope) const {
    raw(alpha, sigma, slope);
    if (!(sigma > sigma_y_min)) {
      sigma = sigma_y_min;
      slope = T(0);
    }
  }

  // evaluate() on W lanes (kernels/lanes.hpp), the power law by pow_lanes; `ok` is cleared where
  // pow_lanes cannot take the base.
  template <int W>
  FIRN_HD void evaluate(const Lanes<T, W>& alpha, Lanes<T, W>& sigma, Lanes<T, W>& slope, LaneMask<W>& ok) const {
    using L = Lanes<T, W>;
    if (law == HardeningLaw::linear) {
      sigma = L(sigma_y0) + L(E_p) * alpha;
      slope = L(E_p);
    } else {
      const L base = L(T(1)) + L(K_h) * alpha;
      const LaneMask<W> positive = base > L(T(0));
      const L safe = select(positive, base, L(T(1)));
      // pow_lanes(1, n) is 1 exactly and keeps `ok` for a finite n (ln 1 = 0, exp 0 = 1): a batch
      // whose bases are all 1 (alpha = 0: particles that have not yielded yet) skips it.
      const L one(T(1));
      const L p = any(safe < one || safe > one) ? pow_lanes(safe, n, ok) : one;
      sigma = select(positive, L(sigma_y0) * p, L(T(0)));
      slope = select(positive, L(sigma_y0 * n * K_h) * p / safe, L(T(0)));
    }
    const LaneMask<W> floored = !(sigma > L(sigma_y_min));
    sigma = select(floored, L(sigma_y_min), sigma);
    slope = select(floored, L(T(0)), slope);
  }

  FIRN_HD T yield_stress(T alpha) const {
    T sigma, slope;
    evaluate(alpha, sigma, slope);
    return sigma;
  }

  FIRN_HD T slope(T alpha) const {
    T sigma, slope;
    evaluate(alpha, sigma, slope);
    return slope;
  }
};

template <class T>
struct J2ReturnSolution {
  T dgamma;        // plastic multiplier; alpha_{n+1} = alpha_n + sqrt(2/3) dgamma
  int iterations;  // residual evaluations
};

// Solves f(dgamma) = 0 (see the top of this file) for a yielding trial state, f(0) > 0. Because
// sigma_y >= sigma_y_min >= 0, f(s_norm / (2 mu_bar)) <= 0, so [0, s_norm / (2 mu_bar)] brackets
// the root; f is continuous but may rise where the law softens. Newton steps are taken when they
// land strictly inside the current bracket and bisection otherwise (safeguarded Newton, Press et
// al., Numerical Recipes 3rd ed., sec. 9.4 "rtsafe"), until |f| or the bracket reaches rounding.
template <class T>
FIRN_HD J2ReturnSolution<T> solve_j2_return(const J2Hardening<T>& h, T alpha_n, T s_norm, T mu_bar) {
  constexpr T kEps = FloatLimits<T>::kEpsilon;
  constexpr int kMaxIterations = 200;  // bisection alone needs < 2 x (mantissa bits) halvings
  const T sqrt23 = std::sqrt(T(2) / T(3));
  T lo = T(0), hi = s_norm / (T(2) * mu_bar);
  T x = T(0);
  for (int it = 1; it <= kMaxIterations; ++it) {
    T sigma_y, slope;
    h.evaluate(alpha_n + sqrt23 * x, sigma_y, slope);
    const T f = s_norm - T(2) * mu_bar * x - sqrt23 * sigma_y;
    if (std::fabs(f) <= T(4) * kEps * s_norm) return {x, it};
    if (f > T(0))
      lo = x;
    else
      hi = x;
    if (hi - lo <= T(2) * kEps * hi) return {x, it};
    const T df = -T(2) * mu_bar - (T(2) / T(3)) * slope;
    const T newton = df < T(0) ? x - f / df : hi;  // df >= 0 only under strong softening
    x = (newton > lo && newton < hi) ? newton : T(0.5) * (lo + hi);
  }
  return {x, kMaxIterations};
}

// solve_j2_return on W lanes at once, for the lanes in `active`: plain Newton steps from dgamma = 0
// until every active lane's |f| or step is at rounding. It takes no bisection, so a lane whose
// iterate leaves the bracket [0, s_norm / (2 mu_bar)] (a softening law) or that has not converged
// in kMaxSteps is cleared in `ok`, for the caller to return by the scalar solver. sigma_n and
// slope_n are the law at alpha_n (the caller's yield check has them: the first step reuses them
// rather than evaluate the power law again). sigma_end is sigma_y at the returned dgamma (for the
// plastic work).
template <class T, int W>
FIRN_HD Lanes<T, W> solve_j2_return_lanes(const J2Hardening<T>& h, const Lanes<T, W>& alpha_n,
                                          const Lanes<T, W>& s_norm, const Lanes<T, W>& mu_bar,
                                          const Lanes<T, W>& sigma_n, const Lanes<T, W>& slope_n,
                                          const LaneMask<W>& active, LaneMask<W>& ok, Lanes<T, W>& sigma_end) {
  using L = Lanes<T, W>;
  constexpr T kEps = FloatLimits<T>::kEpsilon;
  constexpr int kMaxSteps = 8;
  const L sqrt23(std::sqrt(T(2) / T(3))), two_mu = L(T(2)) * mu_bar;
  L x(T(0)), slope = slope_n;
  sigma_end = sigma_n;
  LaneMask<W> done = !active;  // and, below, lanes the hardening law cannot evaluate
  for (int it = 0; it < kMaxSteps; ++it) {
    if (it > 0) h.evaluate(alpha_n + sqrt23 * x, sigma_end, slope, ok);
    const L f = s_norm - two_mu * x - sqrt23 * sigma_end;
    const L step = f / (-two_mu - L(T(2) / T(3)) * slope);
    done = done || !ok || abs(f) <= L(T(4) * kEps) * s_norm || abs(step) <= L(T(2) * kEps) * x;
    if (!any(!done)) break;
    x = select(done, x, x - step);
  }
  ok = ok && done && !(x < L(T(0))) && !(two_mu * x > s_norm);
  return x;
}

}  // namespace firn

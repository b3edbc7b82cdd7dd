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

}  // namespace firn

// What the stability guard (DESIGN.md section 3) learns from G2P: per block, then over blocks, the
// largest speed, the smallest J and the first offender (lowest particle index) with its reason and
// values. Every merge is a min or max, so the summary is the same in any order of combination:
// for every thread count and on every backend.
#pragma once

#include <cmath>
#include <cstddef>

#include "kernels/float_limits.hpp"
#include "kernels/hd.hpp"

namespace firn {

enum class GuardReason { none, not_finite, inverted, too_fast, left_grid };

template <class T>
struct GuardSummary {
  T max_speed = T(0);
  T min_J = FloatLimits<T>::kMax;
  std::size_t offender = kNoParticle;  // physical particle index
  GuardReason reason = GuardReason::none;
  T J = T(0), speed = T(0), moved = T(0);  // the offender's values

  // Adds one particle's check; cell = dx.
  FIRN_HD void add(std::size_t p, T speed_p, T J_p, T moved_p, T cell) {
    if (speed_p > max_speed) max_speed = speed_p;
    if (J_p < min_J) min_J = J_p;
    // The common case first, in a few instructions (issue 15): a finite sum means all three are
    // finite (an infinity or a NaN among them makes it infinite or NaN), so with J > 0 and the move
    // under a cell there is nothing to report. Anything else, an overflowing sum included, is
    // classified below.
    const T sum = speed_p + J_p + moved_p;
    if (sum - sum == T(0) && J_p > T(0) && moved_p <= cell) return;
    GuardReason r = GuardReason::none;
    if (!std::isfinite(speed_p) || !std::isfinite(J_p) || !std::isfinite(moved_p))
      r = GuardReason::not_finite;
    else if (J_p <= T(0))
      r = GuardReason::inverted;
    else if (moved_p > cell)
      r = GuardReason::too_fast;
    if (r != GuardReason::none && p < offender) {
      offender = p;
      reason = r;
      J = J_p;
      speed = speed_p;
      moved = moved_p;
    }
  }
  FIRN_HD void merge(const GuardSummary& o) {
    if (o.max_speed > max_speed) max_speed = o.max_speed;
    if (o.min_J < min_J) min_J = o.min_J;
    if (o.offender < offender) {
      offender = o.offender;
      reason = o.reason;
      J = o.J;
      speed = o.speed;
      moved = o.moved;
    }
  }
};

// The combine of a reduction over guard summaries.
struct MergeGuard {
  template <class T>
  FIRN_HD void operator()(GuardSummary<T>& a, const GuardSummary<T>& b) const {
    a.merge(b);
  }
};

}  // namespace firn

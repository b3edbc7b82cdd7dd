// The stability guard (DESIGN.md section 3): after every G2P, a NaN/Inf, J <= 0 or a particle that
// moved more than one cell stops the run with an error naming step, time, particle, material and
// the offending values. The first offender (lowest particle index) is reported, so the message is
// the same for every thread count.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace firn {

class StabilityError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class GuardReason { none, not_finite, inverted, too_fast, left_grid };

// Per-block (then global) summary of the particles' checks.
template <class T>
struct GuardSummary {
  T max_speed = T(0);
  T min_J = std::numeric_limits<T>::max();
  std::size_t offender = std::numeric_limits<std::size_t>::max();  // physical particle index
  GuardReason reason = GuardReason::none;
  T J = T(0), speed = T(0), moved = T(0);  // the offender's values

  // Adds one particle's check; cell = dx.
  void add(std::size_t p, T speed_p, T J_p, T moved_p, T cell) {
    if (speed_p > max_speed) max_speed = speed_p;
    if (J_p < min_J) min_J = J_p;
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
  void merge(const GuardSummary& o) {
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

inline const char* guard_reason_text(GuardReason r) {
  switch (r) {
    case GuardReason::not_finite: return "non-finite velocity or deformation (NaN/Inf)";
    case GuardReason::inverted: return "inverted or collapsed element (J <= 0)";
    case GuardReason::too_fast: return "moved more than one cell in one step (time step too large)";
    case GuardReason::left_grid: return "left the grid (or its position is not finite)";
    case GuardReason::none: break;
  }
  return "no error";
}

}  // namespace firn

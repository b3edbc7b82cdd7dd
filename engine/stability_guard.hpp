// The stability guard (DESIGN.md section 3): after every G2P, a NaN/Inf, J <= 0 or a particle that
// moved more than one cell stops the run with an error naming step, time, particle, material and
// the offending values. The first offender (lowest particle index) is reported, so the message is
// the same for every thread count (kernels/guard_summary.hpp).
#pragma once

#include <stdexcept>
#include <string>

#include "kernels/guard_summary.hpp"

namespace firn {

class StabilityError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
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

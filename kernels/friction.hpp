// Friction laws for walls and colliders (DESIGN.md section 4, "Friction").
//   coulomb:            mu constant;
//   velocity_dependent: the thesis' Eq. 4.9, after Wriggers and Reinelt (2009) Eq. 4.8 with
//                       v_max = 110 mm/s and c = 0.17, scaled so that mu(1 mm/s) = mu0:
//                         mu(v) = mu0 (12101 v / (v^2 + 12100))^0.17,  v the slip speed in mm/s.
//                       It rises from 0 at rest to mu0 at 1 mm/s and 1.977 mu0 at 110 mm/s, then falls
//                       (0.296 at 10 mph for mu0 = 0.25).
#pragma once

#include <cmath>
#include <cstdint>

#include "kernels/hd.hpp"

namespace firn {

enum class FrictionLaw : std::uint8_t { coulomb, velocity_dependent };

template <class T>
struct Friction {
  FrictionLaw law = FrictionLaw::coulomb;
  T mu = T(0);  // coulomb: the coefficient; velocity_dependent: mu0, the value at 1 mm/s

  // The coefficient at tangential slip speed `slip` (m/s).
  FIRN_HD T coefficient(T slip) const {
    if (law == FrictionLaw::coulomb) return mu;
    const T v = T(1000) * slip;  // mm/s
    return mu * std::pow(T(12101) * v / (v * v + T(12100)), T(0.17));
  }

  // The share of a tangential slip speed `slip` that friction leaves after a normal speed change
  // `normal_change` >= 0, Coulomb on the impulse (|dv_t| <= mu |dv_n|, never reversing the slip):
  // max(0, 1 - mu(slip) normal_change / slip), 0 for no slip.
  FIRN_HD T slip_kept(T slip, T normal_change) const {
    const T scale = slip > T(0) ? T(1) - coefficient(slip) * normal_change / slip : T(0);
    return scale > T(0) ? scale : T(0);
  }
};

}  // namespace firn

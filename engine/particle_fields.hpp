// Per-particle derived fields shared by the .vtp writer and the renderer's colour-by.
#pragma once

#include <cmath>
#include <cstddef>

#include "kernels/mat3.hpp"
#include "kernels/particle_attributes.hpp"
#include "kernels/particle_state.hpp"

namespace firn {

// von Mises stress sqrt(3/2 s:s) of the Cauchy stress sigma = tau / J_E (tau from the last step).
template <class T>
T particle_von_mises(const ParticleView<T>& pv, std::size_t p) {
  const T inv_J = T(1) / determinant(particle_F(pv, p));
  const T t[6] = {pv.tau[0][p], pv.tau[1][p], pv.tau[2][p], pv.tau[3][p], pv.tau[4][p], pv.tau[5][p]};
  const T mean = (t[0] + t[1] + t[2]) / T(3);
  const T s2 = (t[0] - mean) * (t[0] - mean) + (t[1] - mean) * (t[1] - mean) + (t[2] - mean) * (t[2] - mean) +
               T(2) * (t[3] * t[3] + t[4] * t[4] + t[5] * t[5]);
  return std::sqrt(T(1.5) * s2) * inv_J;
}

}  // namespace firn

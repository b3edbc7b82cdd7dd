// Writes each particle's body acceleration from the table of its load's current acceleration:
// body_accel_p = table[3 load_p .. 3 load_p + 2] (entry 0, for particles without a load, is zero).
#pragma once

#include <cstddef>

#include "kernels/hd.hpp"
#include "kernels/particle_attributes.hpp"

namespace firn {

template <class T>
struct LoadRamp {
  ParticleView<T> pv;
  const T* table;

  FIRN_HD void operator()(std::size_t p) const {
    for (int d = 0; d < 3; ++d) pv.body_accel[d][p] = table[3 * pv.load[p] + d];
  }
};

}  // namespace firn

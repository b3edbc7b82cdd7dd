// Writes each particle's body acceleration a_p, which P2G adds to its velocity as dt a_p before it
// scatters (kernels/p2g.hpp):
//   - its load's current acceleration, table[3 load_p .. 3 load_p + 2] (entry 0, for particles
//     without a load, is zero; no table when the simulation has no loads);
//   - where the particle carries a rest area vector A0 (the on_demand attribute area0: a piece N dA
//     of a surface that a pressure acts on, N pointing into the body), the follower pressure's force
//     per unit mass, pressure cof(F) A0 / m. cof(F) = J F^-T carries the rest area element to the
//     deformed one, n da = J F^-T N dA (Nanson's formula; e.g. Holzapfel, Nonlinear Solid Mechanics,
//     2000, chapter 2), so the pressure follows the surface as it stretches and turns (a tire's
//     inflation, issue 17). F is the particle's deformation gradient: its whole deformation for the elastic
//     materials such a surface belongs to.
#pragma once

#include <cstddef>

#include "kernels/hd.hpp"
#include "kernels/particle_attributes.hpp"

namespace firn {

template <class T>
struct BodyAcceleration {
  ParticleView<T> pv;
  const T* table;  // [3 (loads + 1)], or null: no loads
  T pressure;      // Pa, on the particles' area0 (unused without it)

  FIRN_HD void operator()(std::size_t p) const {
    T a[3] = {T(0), T(0), T(0)};
    if (table)
      for (int d = 0; d < 3; ++d) a[d] = table[3 * pv.load[p] + d];
    if (pv.area0[0]) {
      T f[9];
      for (int q = 0; q < 9; ++q) f[q] = pv.F[q][p];
      const T A[3] = {pv.area0[0][p], pv.area0[1][p], pv.area0[2][p]};
      const T s = pressure / pv.mass[p];
      for (int i = 0; i < 3; ++i) {
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        T c = T(0);  // (cof F A)_i, cof(F)_ij = F_i1,j1 F_i2,j2 - F_i1,j2 F_i2,j1 (cyclic indices)
        for (int j = 0; j < 3; ++j) {
          const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
          c += (f[3 * i1 + j1] * f[3 * i2 + j2] - f[3 * i1 + j2] * f[3 * i2 + j1]) * A[j];
        }
        a[i] += s * c;
      }
    }
    for (int d = 0; d < 3; ++d) pv.body_accel[d][p] = a[d];
  }
};

}  // namespace firn

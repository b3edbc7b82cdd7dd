// Particle to grid (P2G): mass, momentum, the APIC/MLS affine term and the MLS stress impulse
// (Hu et al. 2018, "A moving least squares material point method", Eq. 29):
//   m_i  += w_ip m_p
//   mv_i += w_ip (m_p v_p + A_p (x_i - x_p)),  A_p = m_p C_p - dt V0_p D^-1 tau_p
// with tau the Kirchhoff stress (V0 tau = V P F^T). PIC and FLIP drop the m_p C_p term; FLIP also
// scatters the momentum without the stress impulse, from which the grid update recovers the old
// grid velocity. An optional body acceleration b adds m b dt to the momentum. The kernel computes contributions; where they go is the scatter target's business
// (a block-local scratch on the CPU, atomics on a GPU): Target::add(i, j, k, values[kCount]).
#pragma once

#include <cstddef>

#include "kernels/grid_geometry.hpp"
#include "kernels/hd.hpp"
#include "kernels/particle_attributes.hpp"
#include "kernels/transfer.hpp"

namespace firn {

template <class T, class ShapeT, Transfer kTransfer, class Target>
FIRN_HD void p2g_particle(const ParticleView<T>& pv, std::size_t p, const GridGeometry<T>& g, T dt, Target& out) {
  constexpr int S = ShapeT::kSupport;
  using Ch = GridChannels<kTransfer>;
  int base[3];
  T f[3], w[3][S];
  for (int d = 0; d < 3; ++d) {
    const T X = (pv.x[d][p] - g.origin[d]) * g.inv_dx;
    base[d] = ShapeT::base(X);
    f[d] = X - T(base[d]);
    ShapeT::weights(f[d], w[d]);
  }
  const T m = pv.mass[p];
  const T v[3] = {pv.v[0][p], pv.v[1][p], pv.v[2][p]};
  T vb[3] = {v[0], v[1], v[2]};  // velocity after the body force impulse
  if (pv.body_accel[0] != nullptr)
    for (int r = 0; r < 3; ++r) vb[r] += dt * pv.body_accel[r][p];

  // A = -dt V0 D^-1 tau (+ m C for APIC), D^-1 = kDinv / dx^2.
  const T s = -dt * pv.vol0[p] * ShapeT::kDinv * g.inv_dx * g.inv_dx;
  T A[9] = {s * pv.tau[0][p], s * pv.tau[3][p], s * pv.tau[5][p],   //
            s * pv.tau[3][p], s * pv.tau[1][p], s * pv.tau[4][p],   //
            s * pv.tau[5][p], s * pv.tau[4][p], s * pv.tau[2][p]};
  if (kTransfer == Transfer::apic)
    for (int q = 0; q < 9; ++q) A[q] += m * pv.C[q][p];

  // With node offset o = (a, b, c) from base, x_i - x_p = (o - f) dx, so the momentum
  // contribution is w (q + Ad o) with Ad = A dx and q = m vb - Ad f: three adds per node.
  T Ad[9];
  for (int q = 0; q < 9; ++q) Ad[q] = A[q] * g.dx;
  T q0[3];
  for (int r = 0; r < 3; ++r) q0[r] = m * vb[r] - (Ad[3 * r] * f[0] + Ad[3 * r + 1] * f[1] + Ad[3 * r + 2] * f[2]);

  for (int a = 0; a < S; ++a) {
    T qa[3];
    for (int r = 0; r < 3; ++r) qa[r] = q0[r] + T(a) * Ad[3 * r];
    for (int b = 0; b < S; ++b) {
      T qab[3];
      for (int r = 0; r < 3; ++r) qab[r] = qa[r] + T(b) * Ad[3 * r + 1];
      const T wab = w[0][a] * w[1][b];
      for (int c = 0; c < S; ++c) {
        const T wt = wab * w[2][c];
        T val[Ch::kCount];
        val[Ch::kMass] = wt * m;
        for (int r = 0; r < 3; ++r) val[Ch::kVelocity + r] = wt * (qab[r] + T(c) * Ad[3 * r + 2]);
        if (kTransfer == Transfer::flip)
          for (int r = 0; r < 3; ++r) val[Ch::kOldVelocity + r] = wt * m * v[r];
        out.add(base[0] + a, base[1] + b, base[2] + c, val);
      }
    }
  }
}

}  // namespace firn

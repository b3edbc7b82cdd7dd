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
#include "kernels/stencil.hpp"
#include "kernels/transfer.hpp"

namespace firn {

template <class T, class ShapeT, Transfer kTransfer, class Target>
FIRN_HD void p2g_particle(const ParticleView<T>& pv, std::size_t p, const GridGeometry<T>& g, T dt, Target& out) {
  constexpr int S = ShapeT::kSupport;
  using Ch = GridChannels<kTransfer>;
  const Stencil<T, ShapeT> st = particle_stencil<T, ShapeT>(pv, p, g);
  const int* base = st.base;
  const T* f = st.f;
  const auto& w = st.w;
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

  // With node offset o = (a, b, c) from base, x_i - x_p = (o - f) dx, so the node receives
  // w (m, q + Ad o) with Ad = A dx and q = m vb - Ad f. Four lanes (mass, momentum) per node:
  // u = (m, q) + a col0 + b col1 + c col2, with col_k = (0, Ad column k).
  T Ad[9];
  for (int q = 0; q < 9; ++q) Ad[q] = A[q] * g.dx;
  T u0[4] = {m, T(0), T(0), T(0)}, col[3][4];
  for (int r = 0; r < 3; ++r)
    u0[1 + r] = m * vb[r] - (Ad[3 * r] * f[0] + Ad[3 * r + 1] * f[1] + Ad[3 * r + 2] * f[2]);
  for (int k = 0; k < 3; ++k) {
    col[k][0] = T(0);
    for (int r = 0; r < 3; ++r) col[k][1 + r] = Ad[3 * r + k];
  }
  const T mv[4] = {T(0), m * v[0], m * v[1], m * v[2]};  // FLIP: momentum without the impulse

  for (int a = 0; a < S; ++a) {
    T ua[4];
    for (int r = 0; r < 4; ++r) ua[r] = u0[r] + T(a) * col[0][r];
    for (int b = 0; b < S; ++b) {
      T uab[4];
      for (int r = 0; r < 4; ++r) uab[r] = ua[r] + T(b) * col[1][r];
      const T wab = w[0][a] * w[1][b];
      for (int c = 0; c < S; ++c) {
        const T wt = wab * w[2][c];
        T val[Ch::kCount];
        for (int r = 0; r < 4; ++r) val[r] = wt * (uab[r] + T(c) * col[2][r]);
        if (kTransfer == Transfer::flip)
          for (int r = 0; r < 4; ++r) val[4 + r] = wt * mv[r];
        out.add(base[0] + a, base[1] + b, base[2] + c, val);
      }
    }
  }
}

}  // namespace firn

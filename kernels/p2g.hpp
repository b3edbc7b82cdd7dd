// Particle to grid (P2G): mass, momentum, the APIC/MLS affine term and the MLS stress impulse
// (Hu et al. 2018, "A moving least squares material point method", Eq. 29):
//   m_i  += w_ip m_p
//   mv_i += w_ip (m_p v_p + A_p (x_i - x_p)),  A_p = m_p C_p - dt V0_p D^-1 tau_p
// with tau the Kirchhoff stress (V0 tau = V P F^T). PIC and FLIP drop the m_p C_p term; FLIP also
// scatters the momentum without the stress impulse, from which the grid update recovers the old
// grid velocity. An optional body acceleration b adds m b dt to the momentum. The kernel computes
// contributions; where they go is the scatter target's business (a block-local scratch on the CPU,
// shared memory on a GPU): Target::add_row<S>(i, j, k, values[S kCount]) adds nodes
// (i, j, k .. k + S - 1), kCount values each.
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
  // w (m, q + Ad o) with Ad = A dx and q = m vb - Ad f: (m, q) + a col0 + b col1 + c col2, with
  // col_k = (0, Ad column k). A row of the stencil (fixed a, b; c = 0 .. S-1) is S consecutive
  // nodes, so its S x kCount values are computed and added as one short vector (lane l = c kCount
  // + r, 12 lanes for quadratic APIC): val = (w_b Wz) (w_a (P + a L0) + b w_a L1), where Wz, P, L0
  // and L1 are the per-lane weight along z, (m, q) + c col2, col0 and col1 (FLIP's lanes 4-7 hold
  // the momentum without the impulse, m v, in P only). The products by w_b Wz are made once per
  // particle, those by w_a once per a, and the terms a L0 at a = 0 and b L1 at b = 0 are left out
  // (issue 15: 24 instructions per particle fewer than (w_a w_b Wz) (P + a L0 + b L1) row by row).
  T Ad[9];
  for (int q = 0; q < 9; ++q) Ad[q] = A[q] * g.dx;
  T col[3][4];
  for (int k = 0; k < 3; ++k) {
    col[k][0] = T(0);
    for (int r = 0; r < 3; ++r) col[k][1 + r] = Ad[3 * r + k];
  }
  constexpr int K = Ch::kCount, L = S * K;
  const T u[4] = {m, m * vb[0], m * vb[1], m * vb[2]}, mv[4] = {T(0), m * v[0], m * v[1], m * v[2]};
  T Wz[L], P[L], L0[L], L1[L], L2[L];
  // Wz: w_c at lanes c K .. c K + K - 1, by selects, which GCC keeps in registers (issue 15: written
  // to the stack element by element and read back as one vector, it stalled P2G; docs/performance.md).
  FIRN_LANES
  for (int l = 0; l < L; ++l) {
    T wz = w[0][2];
    for (int c = 1; c < S; ++c) wz = l >= c * K ? w[c][2] : wz;
    Wz[l] = wz;
  }
  for (int c = 0; c < S; ++c)
    for (int r = 0; r < K; ++r) {
      const int l = c * K + r;
      const bool impulse = r < 4;  // FLIP's lanes 4-7: pad and m v
      L0[l] = impulse ? col[0][r] : T(0);
      L1[l] = impulse ? col[1][r] : T(0);
      L2[l] = impulse ? col[2][r] : T(0);
      P[l] = impulse ? u[r] : mv[r & 3];
    }
  // P = (m, m vb) - Ad f + c col2 = (m, m vb) - f_0 L0 - f_1 L1 + (c - f_2) L2.
  FIRN_LANES
  for (int l = 0; l < L; ++l) P[l] += (T(l / K) - f[2]) * L2[l] - f[0] * L0[l] - f[1] * L1[l];
  T Wyz[S][L];  // w_b Wz, row b's weights
  for (int b = 0; b < S; ++b) {
    FIRN_LANES
    for (int l = 0; l < L; ++l) Wyz[b][l] = w[b][1] * Wz[l];
  }
  for (int a = 0; a < S; ++a) {
    T Ha[L], Ka[L];  // w_a (P + a L0), w_a L1
    FIRN_LANES
    for (int l = 0; l < L; ++l) {
      Ha[l] = w[a][0] * (a > 0 ? P[l] + T(a) * L0[l] : P[l]);
      Ka[l] = w[a][0] * L1[l];
    }
    for (int b = 0; b < S; ++b) {
      T val[L];
      FIRN_LANES
      for (int l = 0; l < L; ++l) val[l] = Wyz[b][l] * (b > 0 ? Ha[l] + T(b) * Ka[l] : Ha[l]);
      out.template add_row<S>(base[0] + a, base[1] + b, base[2], val);
    }
  }
}

}  // namespace firn

// Grid to particle (G2P): velocity, affine velocity C, deformation gradient and position.
//   v_pic = sum w_ip v_i,  C = D^-1 sum w_ip v_i (x_i - x_p)^T   (Jiang et al. 2015, Eq. 8; MLS)
//   F <- (I + dt C) F,     x <- x + dt v_pic                     (Hu et al. 2018, Eq. 17)
//   v_p = v_pic (APIC, PIC) or alpha (v_p + v_pic - v_old) + (1 - alpha) v_pic (FLIP),
// where v_old = sum w_ip v_i_old. Reads grid velocities from Source::row(i, j, k): the nodes
// (i, j, k .. k + S - 1) one after another, GridChannels::kGatherCount values each (velocity and a
// zero pad, then for FLIP the old velocity and a pad).
// Returns what the stability guard needs: the new speed, J = det F and the distance moved.
#pragma once

#include <cmath>
#include <cstddef>

#include "kernels/grid_geometry.hpp"
#include "kernels/hd.hpp"
#include "kernels/mat3.hpp"
#include "kernels/particle_attributes.hpp"
#include "kernels/stencil.hpp"
#include "kernels/transfer.hpp"

namespace firn {

template <class T>
struct ParticleCheck {
  T speed;  // |v_p| after the update
  T J;      // det F after the update
  T moved;  // distance moved this step, dt |v_pic|
};

template <class T, class ShapeT, Transfer kTransfer, class Source>
FIRN_HD ParticleCheck<T> g2p_particle(const ParticleView<T>& pv, std::size_t p, const GridGeometry<T>& g, T dt,
                                      T flip_alpha, const Source& grid) {
  constexpr int S = ShapeT::kSupport;
  const Stencil<T, ShapeT> st = particle_stencil<T, ShapeT>(pv, p, g);
  const int* base = st.base;
  const T* f = st.f;
  const auto& w = st.w;

  // Accumulate sum w v_i and its first moments sum w v_i o_k (o the node offset). A row of the
  // stencil (fixed a, b; c = 0 .. S-1) is S consecutive nodes of K values (velocity and a zero pad,
  // then for FLIP the old velocity and a pad), read as one short vector of lanes l = c K + r. Sums
  // over b first (weights w_b and b w_b), then over a; the lanes are folded over c at the end, where
  // they take their weight along z, w_c, and the z moment its factor c. The loop over a is unrolled
  // (GCC kept it a loop, its weights spilled and reloaded each time: about 50 instructions per particle
  // more; issue 15); P2G's, unrolled likewise, ran no faster and is not.
  constexpr int K = GridChannels<kTransfer>::kGatherCount, L = S * K;
  T s0[L] = {}, sa[L] = {}, sb[L] = {};
  FIRN_UNROLL
  for (int a = 0; a < S; ++a) {
    T t0[L] = {}, tb[L] = {};
    for (int b = 0; b < S; ++b) {
      const T* row = grid.row(base[0] + a, base[1] + b, base[2]);
      const T wb = w[b][1], wbb = w[b][1] * T(b);
      FIRN_LANES
      for (int l = 0; l < L; ++l) t0[l] += wb * row[l];
      if (b > 0) {  // a moment's weight, b w_b here, is 0 at b = 0: those terms are skipped
        FIRN_LANES
        for (int l = 0; l < L; ++l) tb[l] += wbb * row[l];
      }
    }
    const T wa = w[a][0], waa = w[a][0] * T(a);
    FIRN_LANES
    for (int l = 0; l < L; ++l) {
      s0[l] += wa * t0[l];
      sb[l] += wa * tb[l];
    }
    if (a > 0) {  // likewise a w_a
      FIRN_LANES
      for (int l = 0; l < L; ++l) sa[l] += waa * t0[l];
    }
  }
  // Fold the lanes over c, a node's channel r at a time (lane c K + r), into vectors over r (the
  // velocity component; r = 3 is the pad): v_pic, the moments mo[k] = sum w v o_k and, for FLIP,
  // the old velocity. In that form the rest is column arithmetic on 4-lane vectors: column k of C
  // is cs (mo[k] - v_pic f_k), and column j of F_new = (I + dt C) F is sum_k (I + dt C)_k F(k, j).
  T vp[4], mo[3][4], vold[4];
  FIRN_LANES
  for (int r = 0; r < 4; ++r) {
    T v = T(0), m0 = T(0), m1 = T(0), m2 = T(0), vo = T(0);
    for (int c = 0; c < S; ++c) {
      const int l = c * K + r;
      v += w[c][2] * s0[l];
      m0 += w[c][2] * sa[l];
      m1 += w[c][2] * sb[l];
      if (c > 0) m2 += (w[c][2] * T(c)) * s0[l];  // and c w_c
      if constexpr (kTransfer == Transfer::flip) vo += w[c][2] * s0[l + 4];
    }
    vp[r] = v;
    mo[0][r] = m0;
    mo[1][r] = m1;
    mo[2][r] = m2;
    vold[r] = vo;
  }

  // x_i - x_p = (o - f) dx, so C = D^-1 dx (mo - v f^T) = kDinv / dx (mo - v f^T).
  const T cs = ShapeT::kDinv * g.inv_dx;
  T Ccol[3][4], Gcol[3][4], Fcol[3][4];
  for (int k = 0; k < 3; ++k) {
    FIRN_LANES
    for (int r = 0; r < 4; ++r) {
      Ccol[k][r] = cs * (mo[k][r] - vp[r] * f[k]);
      Gcol[k][r] = dt * Ccol[k][r] + (r == k ? T(1) : T(0));
    }
  }
  for (int j = 0; j < 3; ++j) {
    const T F0 = pv.F[j][p], F1 = pv.F[3 + j][p], F2 = pv.F[6 + j][p];
    FIRN_LANES
    for (int r = 0; r < 4; ++r) Fcol[j][r] = Gcol[0][r] * F0 + Gcol[1][r] * F1 + Gcol[2][r] * F2;
  }
  Mat3<T> Fn;
  for (int r = 0; r < 3; ++r)
    for (int j = 0; j < 3; ++j) Fn(r, j) = Fcol[j][r];

  T vn[3];
  for (int r = 0; r < 3; ++r)
    vn[r] = kTransfer == Transfer::flip ? flip_alpha * (pv.v[r][p] + vp[r] - vold[r]) + (T(1) - flip_alpha) * vp[r]
                                        : vp[r];
  for (int r = 0; r < 3; ++r) {
    pv.x[r][p] += dt * vp[r];
    pv.v[r][p] = vn[r];
  }
  for (int q = 0; q < 9; ++q) pv.F[q][p] = Fn.m[q];
  if constexpr (kTransfer == Transfer::apic)  // PIC and FLIP need C for F only: not stored
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) pv.C[3 * r + k][p] = Ccol[k][r];
  return ParticleCheck<T>{std::sqrt(vn[0] * vn[0] + vn[1] * vn[1] + vn[2] * vn[2]), determinant(Fn),
                          dt * std::sqrt(vp[0] * vp[0] + vp[1] * vp[1] + vp[2] * vp[2])};
}

}  // namespace firn

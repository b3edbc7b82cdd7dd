// Grid to particle (G2P): velocity, affine velocity C, deformation gradient and position.
//   v_pic = sum w_ip v_i,  C = D^-1 sum w_ip v_i (x_i - x_p)^T   (Jiang et al. 2015, Eq. 8; MLS)
//   F <- (I + dt C) F,     x <- x + dt v_pic                     (Hu et al. 2018, Eq. 17)
//   v_p = v_pic (APIC, PIC) or alpha (v_p + v_pic - v_old) + (1 - alpha) v_pic (FLIP),
// where v_old = sum w_ip v_i_old. Reads grid velocities from Source::node(i, j, k), which returns
// GridChannels::kGatherCount values: velocity and a zero pad, then for FLIP the old velocity and a pad.
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

  // Accumulate sum w v_i and its first moments sum w v_i o_k (o the node offset), four lanes per
  // node (velocity and a zero pad) so that every update is one short vector operation; the sums
  // over the innermost axis are taken first. FLIP also accumulates v_old = sum w v_i_old.
  T vp[4] = {T(0), T(0), T(0), T(0)}, mo[3][4] = {}, vold[4] = {T(0), T(0), T(0), T(0)};
  for (int a = 0; a < S; ++a)
    for (int b = 0; b < S; ++b) {
      T sv[4] = {T(0), T(0), T(0), T(0)}, sc[4] = {T(0), T(0), T(0), T(0)}, so[4] = {T(0), T(0), T(0), T(0)};
      for (int c = 0; c < S; ++c) {
        const T* node = grid.node(base[0] + a, base[1] + b, base[2] + c);
        const T wc = w[2][c], wcc = w[2][c] * T(c);
        for (int r = 0; r < 4; ++r) {
          sv[r] += wc * node[r];
          sc[r] += wcc * node[r];
        }
        if (kTransfer == Transfer::flip)
          for (int r = 0; r < 4; ++r) so[r] += wc * node[4 + r];
      }
      const T wab = w[0][a] * w[1][b], wa = wab * T(a), wb = wab * T(b);
      for (int r = 0; r < 4; ++r) {
        vp[r] += wab * sv[r];
        mo[0][r] += wa * sv[r];
        mo[1][r] += wb * sv[r];
        mo[2][r] += wab * sc[r];
      }
      if (kTransfer == Transfer::flip)
        for (int r = 0; r < 4; ++r) vold[r] += wab * so[r];
    }
  T Bo[9];
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) Bo[3 * r + k] = mo[k][r];

  // x_i - x_p = (o - f) dx, so C = D^-1 dx (Bo - v f^T) = kDinv / dx (Bo - v f^T).
  const T cs = ShapeT::kDinv * g.inv_dx;
  Mat3<T> C;
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) C(r, k) = cs * (Bo[3 * r + k] - vp[r] * f[k]);

  Mat3<T> F;
  for (int q = 0; q < 9; ++q) F.m[q] = pv.F[q][p];
  Mat3<T> G = dt * C;
  for (int d = 0; d < 3; ++d) G(d, d) += T(1);
  const Mat3<T> Fn = G * F;

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
    for (int q = 0; q < 9; ++q) pv.C[q][p] = C.m[q];
  return ParticleCheck<T>{std::sqrt(vn[0] * vn[0] + vn[1] * vn[1] + vn[2] * vn[2]), determinant(Fn),
                          dt * std::sqrt(vp[0] * vp[0] + vp[1] * vp[1] + vp[2] * vp[2])};
}

}  // namespace firn

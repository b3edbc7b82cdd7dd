// Grid update: momentum to velocity, gravity, colliders and the domain walls, for one 4x4x4 block.
//   v_i = (m v)_i / m_i + dt g, then each collider containing the node at the end of the step,
//   then each wall whose band contains the node (DESIGN.md section 3).
// Nodes with (almost) no mass get zero velocity: below `min_mass` the reciprocal 1/m could overflow
// (a corner node reached only through three tiny B-spline weights has a denormal mass in float),
// and a zero weight must never multiply a NaN in G2P.
#pragma once

#include "kernels/boundary_conditions.hpp"
#include "kernels/colliders.hpp"
#include "kernels/grid_geometry.hpp"
#include "kernels/hd.hpp"
#include "kernels/transfer.hpp"

namespace firn {

constexpr int kMaxColliders = 16;

template <class T>
struct GridUpdateParams {
  T dt;
  T time;  // at the end of the step: colliders act where they will be
  T gravity[3];
  Wall<T> walls[6];  // faces -x, +x, -y, +y, -z, +z
  int nodes[3];
  T origin[3];
  T dx;
  T min_mass;  // nodes lighter than this are treated as empty
  int collider_count;
  Collider<T> colliders[kMaxColliders];
};

template <class T, Transfer kTransfer>
FIRN_HD void grid_update_block(T* data, const int block[3], const GridUpdateParams<T>& p) {
  using Ch = GridChannels<kTransfer>;
  for (int l = 0; l < kBlockNodes; ++l) {
    T* mass = data + Ch::kMass * kBlockNodes + l;
    T* vel[3] = {data + (Ch::kVelocity + 0) * kBlockNodes + l, data + (Ch::kVelocity + 1) * kBlockNodes + l,
                 data + (Ch::kVelocity + 2) * kBlockNodes + l};
    if (!(*mass > p.min_mass)) {
      for (int d = 0; d < 3; ++d) *vel[d] = T(0);
      if (kTransfer == Transfer::flip)
        for (int d = 0; d < 3; ++d) data[(Ch::kOldVelocity + d) * kBlockNodes + l] = T(0);
      continue;
    }
    const T inv_m = T(1) / *mass;
    T v[3];
    for (int d = 0; d < 3; ++d) v[d] = *vel[d] * inv_m + p.dt * p.gravity[d];
    if (kTransfer == Transfer::flip)
      for (int d = 0; d < 3; ++d) data[(Ch::kOldVelocity + d) * kBlockNodes + l] *= inv_m;

    const int node[3] = {block[0] * kBlockSize + l / (kBlockSize * kBlockSize),
                         block[1] * kBlockSize + (l / kBlockSize) % kBlockSize, block[2] * kBlockSize + l % kBlockSize};
    if (p.collider_count > 0) {
      const T x[3] = {p.origin[0] + T(node[0]) * p.dx, p.origin[1] + T(node[1]) * p.dx, p.origin[2] + T(node[2]) * p.dx};
      for (int c = 0; c < p.collider_count; ++c) p.colliders[c].apply(v, x, p.time);
    }
    for (int d = 0; d < 3; ++d) {
      const Wall<T>& lo = p.walls[2 * d];
      const Wall<T>& hi = p.walls[2 * d + 1];
      T n[3] = {T(0), T(0), T(0)};
      if (node[d] < lo.width) {
        n[d] = T(1);
        apply_wall(v, n, lo.type, lo.friction);
      }
      if (node[d] > p.nodes[d] - 1 - hi.width) {
        n[d] = T(-1);
        apply_wall(v, n, hi.type, hi.friction);
      }
    }
    for (int d = 0; d < 3; ++d) *vel[d] = v[d];
  }
}

}  // namespace firn

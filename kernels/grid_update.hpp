// Grid update: momentum to velocity, gravity, and the domain walls, for one 4x4x4 block.
//   v_i = (m v)_i / m_i + dt g, then each wall whose band contains the node (DESIGN.md section 3).
// Nodes without mass get zero velocity so that a zero weight never multiplies a NaN in G2P.
#pragma once

#include "kernels/boundary_conditions.hpp"
#include "kernels/grid_geometry.hpp"
#include "kernels/hd.hpp"
#include "kernels/transfer.hpp"

namespace firn {

template <class T>
struct GridUpdateParams {
  T dt;
  T gravity[3];
  Wall<T> walls[6];  // faces -x, +x, -y, +y, -z, +z
  int nodes[3];
};

template <class T, Transfer kTransfer>
FIRN_HD void grid_update_block(T* data, const int block[3], const GridUpdateParams<T>& p) {
  using Ch = GridChannels<kTransfer>;
  for (int l = 0; l < kBlockNodes; ++l) {
    T* mass = data + Ch::kMass * kBlockNodes + l;
    T* vel[3] = {data + (Ch::kVelocity + 0) * kBlockNodes + l, data + (Ch::kVelocity + 1) * kBlockNodes + l,
                 data + (Ch::kVelocity + 2) * kBlockNodes + l};
    if (*mass <= T(0)) {
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

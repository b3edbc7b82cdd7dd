// Grid update: momentum to velocity, gravity, colliders and the domain walls, for one 4x4x4 block.
//   v_i = (m v)_i / m_i + dt g, then each collider containing the node at the end of the step,
//   then each wall whose band contains the node (DESIGN.md section 3). With a damping rate c > 0
//   (SimulationConfig::damping), v_i is first divided by 1 + c dt: mass-proportional damping,
//   implicit in the drag so that any c dt is stable, for quasi-static states (dynamic relaxation).
// Collider reactions: the impulse a collider gives a node is m_i (v_after - v_before); the force on
// the collider is its opposite over dt, summed over the block into `reactions` (per block slot and
// collider: force xyz, then torque xyz about the collider's origin). When `footprint` is set, the
// vertical force on collider `footprint_collider` is also summed per 4x4 column of the block
// (x-major), the contact pressure map's raw material.
// Work on the material (issue 19, the energy budget): when `work` is set, the block's sums go to
// work[slot][kind]: the gravity kick's, 1/2 m (|v|^2 - |v - dt g|^2) = m dt g . (v - dt g / 2), and
// the colliders', the impulse m (v_after - v_before) times the collider's velocity v_c at the node
// (force times the velocity of the boundary it acts through). Both are linear in the node's
// momentum, so nodes of tiny mass, whose velocities are large and meaningless, weigh nothing. The
// domain walls do not move and do no work; the kinetic energy a wall or a collider takes out of
// the motion it stops (relative to v_c) is dissipated, and the budget counts it in its residual.
// Nodes with (almost) no mass get zero velocity: below `min_mass` the reciprocal 1/m could overflow
// (a corner node reached only through three tiny B-spline weights has a denormal mass in float),
// and a zero weight must never multiply a NaN in G2P.
#pragma once

#include <cstddef>
#include <cstdint>

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
  T gravity[3];
  Wall<T> walls[6];  // faces -x, +x, -y, +y, -z, +z
  int nodes[3];
  T origin[3];
  T dx;
  T min_mass;  // nodes lighter than this are treated as empty
  T damping_factor;  // 1 / (1 + c dt) for a damping rate c: v after gravity is multiplied by it
  int collider_count;
  Collider<T> colliders[kMaxColliders];  // posed at the end of the step
  T* reactions;                           // [slot][collider][6], written when collider_count > 0
  int footprint_collider;                 // -1: no footprint
  T* footprint;                           // [slot][16]
  T* work;                                // [slot][kWorkKinds], or null: no energy budget
};

enum WorkKind : int { kGravityWork, kColliderWork, kWorkKinds };

constexpr int kReactionComponents = 6;

// The colliders that may hold a node of the block, as bits: a collider whose bounding box
// (Collider::bounds) lies farther than the skin from the box of the block's nodes cannot hold any
// of them (a node it holds is inside the solid by more than the skin), so the block skips its
// signed distance. The same nodes take the same conditions; on a tire over a snow bed, most
// blocks are far from the tire.
template <class T>
FIRN_HD std::uint32_t colliders_near_block(const int block[3], const GridUpdateParams<T>& p) {
  static_assert(kMaxColliders <= 32, "one bit per collider");
  const T skin = T(kColliderSkin) * p.dx;
  T first[3], last[3];  // the block's first and last nodes
  for (int d = 0; d < 3; ++d) {
    first[d] = p.origin[d] + T(block[d] * kBlockSize) * p.dx;
    last[d] = p.origin[d] + T(block[d] * kBlockSize + kBlockSize - 1) * p.dx;
  }
  std::uint32_t near = 0;
  for (int c = 0; c < p.collider_count; ++c) {
    T lo[3], hi[3];
    p.colliders[c].bounds(lo, hi);
    bool overlaps = true;
    for (int d = 0; d < 3; ++d) overlaps = overlaps && last[d] >= lo[d] - skin && first[d] <= hi[d] + skin;
    if (overlaps) near |= 1u << c;
  }
  return near;
}

template <class T, Transfer kTransfer>
FIRN_HD void grid_update_block(T* data, const int block[3], std::size_t slot, const GridUpdateParams<T>& p) {
  using Ch = GridChannels<kTransfer>;
  T reaction[kMaxColliders][kReactionComponents] = {};
  T column_force[kBlockSize * kBlockSize] = {};
  T work[kWorkKinds] = {};
  const std::uint32_t near = colliders_near_block(block, p);
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
    if (p.work)
      for (int d = 0; d < 3; ++d) work[kGravityWork] += *mass * p.dt * p.gravity[d] * (v[d] - T(0.5) * p.dt * p.gravity[d]);
    if (kTransfer == Transfer::flip)
      for (int d = 0; d < 3; ++d) data[(Ch::kOldVelocity + d) * kBlockNodes + l] *= inv_m;
    if (p.damping_factor != T(1))
      for (int d = 0; d < 3; ++d) v[d] *= p.damping_factor;

    int node[3];
    block_node(block, l, node);
    if (near != 0) {
      const T skin = T(kColliderSkin) * p.dx;
      const T x[3] = {p.origin[0] + T(node[0]) * p.dx, p.origin[1] + T(node[1]) * p.dx, p.origin[2] + T(node[2]) * p.dx};
      for (int c = 0; c < p.collider_count; ++c) {
        if (!(near >> c & 1u)) continue;
        const Collider<T>& k = p.colliders[c];
        const T before[3] = {v[0], v[1], v[2]};
        if (!k.apply(v, x, skin)) continue;
        if (p.work) {
          T vc[3];
          k.velocity_at(x, vc);
          for (int d = 0; d < 3; ++d) work[kColliderWork] += *mass * (v[d] - before[d]) * vc[d];
        }
        T f[3];  // on the collider: -m (v_after - v_before) / dt
        for (int d = 0; d < 3; ++d) f[d] = *mass * (before[d] - v[d]) / p.dt;
        const T r[3] = {x[0] - k.center[0], x[1] - k.center[1], x[2] - k.center[2]};
        T* out = reaction[c];
        for (int d = 0; d < 3; ++d) out[d] += f[d];
        out[3] += r[1] * f[2] - r[2] * f[1];
        out[4] += r[2] * f[0] - r[0] * f[2];
        out[5] += r[0] * f[1] - r[1] * f[0];
        if (c == p.footprint_collider) column_force[(l / (kBlockSize * kBlockSize)) * kBlockSize + l % kBlockSize] += f[1];
      }
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
  for (int c = 0; c < p.collider_count; ++c)
    for (int i = 0; i < kReactionComponents; ++i)
      p.reactions[(slot * std::size_t(p.collider_count) + std::size_t(c)) * kReactionComponents + i] = reaction[c][i];
  if (p.footprint)
    for (int i = 0; i < kBlockSize * kBlockSize; ++i) p.footprint[slot * kBlockSize * kBlockSize + i] = column_force[i];
  if (p.work)
    for (int k = 0; k < kWorkKinds; ++k) p.work[slot * kWorkKinds + k] = work[k];
}

}  // namespace firn

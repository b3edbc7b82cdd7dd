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
// A pooled collider (kernels/pooled_contact.hpp; at most one per scene, with its lambda and keep
// solved beforehand): a block within its reach takes the walls first, so that its friction acts on
// the velocity the walls allow, then the pooled collider, then the other colliders, then the walls
// again, so that a wall keeps its condition where a collider reaches into its band. Every other
// block keeps the order above.
// Nodes with (almost) no mass get zero velocity: below `min_mass` the reciprocal 1/m could overflow
// (a corner node reached only through three tiny B-spline weights has a denormal mass in float),
// and a zero weight must never multiply a NaN in G2P.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kernels/boundary_conditions.hpp"
#include "kernels/colliders.hpp"
#include "kernels/grid_geometry.hpp"
#include "kernels/grid_slots.hpp"
#include "kernels/hd.hpp"
#include "kernels/pooled_contact.hpp"
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
  GridSlotsView<T> moments;               // pooled colliders: the nodes' mass moments (pool_node)
  T pool_lambda[kMaxColliders];           // pooled colliders: the pool's normal velocity change
  T pool_keep[kMaxColliders];             // pooled colliders: the share of its slip the surface row keeps
};

enum WorkKind : int { kGravityWork, kColliderWork, kWorkKinds };

constexpr int kReactionComponents = 6;

// The colliders that may hold a node of the block, as bits: a collider whose bounding box
// (Collider::bounds) lies farther than the skin from the box of the block's nodes cannot hold any
// of them (a node it holds is inside the solid by more than the skin), so the block skips its
// signed distance; a plane, whose box is unbounded, is skipped by the distance of the block's
// corners. The same nodes take the same conditions; on a tire over a snow bed, most
// blocks are far from the tire. With `margin` > 0 the box is widened by that many cells on every
// side; the test is monotone in the box, so a wider box keeps every collider a narrower one keeps.
// A penalty collider holds no node.
template <class T>
FIRN_HD std::uint32_t colliders_near_block(const int block[3], const GridUpdateParams<T>& p, int margin = 0) {
  static_assert(kMaxColliders <= 32, "one bit per collider");
  const T skin = T(kColliderSkin) * p.dx;
  T first[3], last[3];  // the box's first and last nodes
  for (int d = 0; d < 3; ++d) {
    first[d] = p.origin[d] + T(block[d] * kBlockSize - margin) * p.dx;
    last[d] = p.origin[d] + T(block[d] * kBlockSize + kBlockSize - 1 + margin) * p.dx;
  }
  std::uint32_t near = 0;
  for (int c = 0; c < p.collider_count; ++c) {
    const Collider<T>& k = p.colliders[c];
    if (k.contact == ColliderContact::penalty) continue;  // it acts on particles, not nodes
    // A pooled collider also acts on the row outside it, up to half a cell (pooled_contact.hpp).
    const T reach = k.contact == ColliderContact::pooled ? T(0.5) * p.dx + skin : skin;
    T lo[3], hi[3];
    k.bounds(lo, hi);
    bool overlaps = true;
    for (int d = 0; d < 3; ++d) overlaps = overlaps && last[d] >= lo[d] - reach && first[d] <= hi[d] + reach;
    if (overlaps && k.shape == ColliderShape::plane) {
      // A plane's box is unbounded, but its signed distance is affine: no node is nearer than the
      // nearest of the box's corners (by a cell, against rounding).
      T nearest = T(INFINITY);
      for (int corner = 0; corner < 8; ++corner) {
        const T x[3] = {corner & 1 ? last[0] : first[0], corner & 2 ? last[1] : first[1], corner & 4 ? last[2] : first[2]};
        T n[3];
        nearest = std::fmin(nearest, k.distance(x, n));
      }
      overlaps = nearest < reach + p.dx;
    }
    if (overlaps) near |= 1u << c;
  }
  return near;
}

// The node's position.
template <class T>
FIRN_HD void node_position(const int block[3], int l, const GridUpdateParams<T>& p, T x[3]) {
  int node[3];
  block_node(block, l, node);
  for (int d = 0; d < 3; ++d) x[d] = p.origin[d] + T(node[d]) * p.dx;
}

// The node's velocity after gravity, before damping: v_i = (m v)_i / m_i + dt g.
template <class T, Transfer kTransfer>
FIRN_HD void node_velocity(const T* data, int l, T inv_m, const GridUpdateParams<T>& p, T v[3]) {
  using Ch = GridChannels<kTransfer>;
  for (int d = 0; d < 3; ++d) v[d] = data[(Ch::kVelocity + d) * kBlockNodes + l] * inv_m + p.dt * p.gravity[d];
}

// Mass-proportional damping (SimulationConfig::damping), when set.
template <class T>
FIRN_HD void apply_damping(const GridUpdateParams<T>& p, T v[3]) {
  if (p.damping_factor != T(1))
    for (int d = 0; d < 3; ++d) v[d] *= p.damping_factor;
}

// The domain walls whose bands hold the node.
template <class T>
FIRN_HD void apply_walls(const int block[3], int l, const GridUpdateParams<T>& p, T v[3]) {
  int node[3];
  block_node(block, l, node);
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
}

// The node's velocity where a pooled collider acts (gravity, damping, walls: see the header), without
// touching the block; false for an empty node. The pool's sums (kernels/step/contact_pool_sums.hpp)
// see the same velocities as grid_update_block.
template <class T, Transfer kTransfer>
FIRN_HD bool pooled_node_velocity(const T* data, const int block[3], int l, const GridUpdateParams<T>& p, T v[3]) {
  const T mass = data[GridChannels<kTransfer>::kMass * kBlockNodes + l];
  if (!(mass > p.min_mass)) return false;
  node_velocity<T, kTransfer>(data, l, T(1) / mass, p, v);
  apply_damping(p, v);
  apply_walls(block, l, p, v);
  return true;
}

// The gravity kick's work on a node of velocity v after the kick, m dt g . (v - dt g / 2), added to
// `sum` an axis at a time. An axis without gravity adds a zero, which leaves the sum as it is (for a
// finite velocity), so it is skipped: a scene without gravity sums nothing (issue 15).
template <class T>
FIRN_HD void add_gravity_work(const GridUpdateParams<T>& p, T mass, const T v[3], T& sum) {
  for (int d = 0; d < 3; ++d)
    if (p.gravity[d] != T(0)) sum += mass * p.dt * p.gravity[d] * (v[d] - T(0.5) * p.dt * p.gravity[d]);
}

// The node's velocity at the start of the grid update (gravity, then damping), with the side
// effects on the block: an empty node's velocity channels zeroed (returns false), FLIP's old
// velocity divided by the mass, gravity's work added to `gravity_work`.
template <class T, Transfer kTransfer>
FIRN_HD bool start_node(T* data, int l, const GridUpdateParams<T>& p, T v[3], T& gravity_work) {
  using Ch = GridChannels<kTransfer>;
  const T mass = data[Ch::kMass * kBlockNodes + l];
  if (!(mass > p.min_mass)) {
    for (int d = 0; d < 3; ++d) data[(Ch::kVelocity + d) * kBlockNodes + l] = T(0);
    if (kTransfer == Transfer::flip)
      for (int d = 0; d < 3; ++d) data[(Ch::kOldVelocity + d) * kBlockNodes + l] = T(0);
    return false;
  }
  const T inv_m = T(1) / mass;
  node_velocity<T, kTransfer>(data, l, inv_m, p, v);
  if (p.work) add_gravity_work(p, mass, v, gravity_work);
  if (kTransfer == Transfer::flip)
    for (int d = 0; d < 3; ++d) data[(Ch::kOldVelocity + d) * kBlockNodes + l] *= inv_m;
  apply_damping(p, v);
  return true;
}

// The block's sums of what one collider does to one node: the force on the collider,
// -m (v_after - v_before) / dt, and its torque about the collider's origin; the footprint column's
// vertical force; the collider's work on the material.
template <class T>
struct BlockReactions {
  T reaction[kMaxColliders][kReactionComponents] = {};
  T column_force[kBlockSize * kBlockSize] = {};
  T work[kWorkKinds] = {};

  FIRN_HD void add(const GridUpdateParams<T>& p, int c, int l, const T x[3], T mass, const T before[3],
                   const T after[3]) {
    const Collider<T>& k = p.colliders[c];
    if (p.work) {
      T vc[3];
      k.velocity_at(x, vc);
      for (int d = 0; d < 3; ++d) work[kColliderWork] += mass * (after[d] - before[d]) * vc[d];
    }
    T f[3];
    for (int d = 0; d < 3; ++d) f[d] = mass * (before[d] - after[d]) / p.dt;
    const T r[3] = {x[0] - k.center[0], x[1] - k.center[1], x[2] - k.center[2]};
    T* out = reaction[c];
    for (int d = 0; d < 3; ++d) out[d] += f[d];
    out[3] += r[1] * f[2] - r[2] * f[1];
    out[4] += r[2] * f[0] - r[0] * f[2];
    out[5] += r[0] * f[1] - r[1] * f[0];
    if (c == p.footprint_collider) column_force[(l / (kBlockSize * kBlockSize)) * kBlockSize + l % kBlockSize] += f[1];
  }

  FIRN_HD void write(std::size_t slot, const GridUpdateParams<T>& p) const {
    for (int c = 0; c < p.collider_count; ++c)
      for (int i = 0; i < kReactionComponents; ++i)
        p.reactions[(slot * std::size_t(p.collider_count) + std::size_t(c)) * kReactionComponents + i] = reaction[c][i];
    if (p.footprint)
      for (int i = 0; i < kBlockSize * kBlockSize; ++i) p.footprint[slot * kBlockSize * kBlockSize + i] = column_force[i];
    if (p.work)
      for (int k = 0; k < kWorkKinds; ++k) p.work[slot * kWorkKinds + k] = work[k];
  }
};

// Whether any collider in `near` is pooled.
template <class T>
FIRN_HD bool any_pooled(std::uint32_t near, const GridUpdateParams<T>& p) {
  for (int c = 0; c < p.collider_count; ++c)
    if ((near >> c & 1u) && p.colliders[c].contact == ColliderContact::pooled) return true;
  return false;
}

// Whether a node of the block lies in a domain wall's band (apply_walls' test over the block's nodes).
template <class T>
FIRN_HD bool block_in_wall_band(const int block[3], const GridUpdateParams<T>& p) {
  for (int d = 0; d < 3; ++d) {
    const int first = block[d] * kBlockSize, last = first + kBlockSize - 1;
    if (first < p.walls[2 * d].width || last > p.nodes[d] - 1 - p.walls[2 * d + 1].width) return true;
  }
  return false;
}

// A block no collider or wall reaches, with APIC or PIC channels: start_node and apply_damping's
// operations node by node, in one loop over the block's nodes that vectorises (issue 15: the
// node-by-node path took 84 instructions per node on cube_drop, where most blocks are free).
// It spells node_velocity and apply_damping out: called here, their local v[3] and the damping's
// branch kept GCC 12 from vectorising the loop ("no vectype", "control flow in loop"), and
// tests/test_grid_update.cpp holds the two paths to the same bits. With an energy budget, the
// gravity kick's work is summed first, node by node in start_node's order; the block's sums are
// returned.
template <class T, Transfer kTransfer>
FIRN_HD BlockReactions<T> free_block_update(T* data, const GridUpdateParams<T>& p) {
  using Ch = GridChannels<kTransfer>;
  const T* mass = data + Ch::kMass * kBlockNodes;
  T* vel = data + Ch::kVelocity * kBlockNodes;
  const T kick[3] = {p.dt * p.gravity[0], p.dt * p.gravity[1], p.dt * p.gravity[2]};
  BlockReactions<T> sums;
  if (p.work && (p.gravity[0] != T(0) || p.gravity[1] != T(0) || p.gravity[2] != T(0)))
    for (int l = 0; l < kBlockNodes; ++l) {
      if (!(mass[l] > p.min_mass)) continue;
      T v[3];
      node_velocity<T, kTransfer>(data, l, T(1) / mass[l], p, v);
      add_gravity_work(p, mass[l], v, sums.work[kGravityWork]);
    }
  const bool damped = p.damping_factor != T(1);
  FIRN_LANES
  for (int l = 0; l < kBlockNodes; ++l) {
    const bool filled = mass[l] > p.min_mass;
    const T inv_m = T(1) / mass[l];  // not finite for an empty node, whose velocity is set to 0
    for (int d = 0; d < 3; ++d) {
      T v = vel[d * kBlockNodes + l] * inv_m + kick[d];
      if (damped) v *= p.damping_factor;
      vel[d * kBlockNodes + l] = filled ? v : T(0);
    }
  }
  return sums;
}

// The block node by node, every condition in the header's order; the block's sums are returned.
template <class T, Transfer kTransfer>
FIRN_HD BlockReactions<T> node_block_update(T* data, const int block[3], std::uint32_t near, std::size_t slot,
                                            const GridUpdateParams<T>& p) {
  using Ch = GridChannels<kTransfer>;
  const bool pooled = near != 0 && any_pooled(near, p);  // walls first, and last (see the header)
  const T* moments = pooled ? p.moments.slot_data(slot) : nullptr;
  BlockReactions<T> sums;
  for (int l = 0; l < kBlockNodes; ++l) {
    T v[3];
    if (!start_node<T, kTransfer>(data, l, p, v, sums.work[kGravityWork])) continue;
    if (pooled) apply_walls(block, l, p, v);
    if (near != 0) {
      const T skin = T(kColliderSkin) * p.dx;
      T x[3];
      node_position(block, l, p, x);
      const T mass = data[Ch::kMass * kBlockNodes + l];
      for (int c = 0; c < p.collider_count && pooled; ++c) {
        const Collider<T>& k = p.colliders[c];
        if (!(near >> c & 1u) || k.contact != ColliderContact::pooled) continue;
        const PoolNode<T> q = pool_node(k, x, v, mass, moments + l, p.dx, skin, p.dt);
        if (q.role == kPoolNone) continue;
        const T before[3] = {v[0], v[1], v[2]};
        apply_pool(q, p.pool_lambda[c], p.pool_keep[c], v);
        sums.add(p, c, l, x, mass, before, v);
      }
      for (int c = 0; c < p.collider_count; ++c) {
        if (!(near >> c & 1u) || p.colliders[c].contact != ColliderContact::nodes) continue;
        const T before[3] = {v[0], v[1], v[2]};
        if (p.colliders[c].apply(v, x, skin)) sums.add(p, c, l, x, mass, before, v);
      }
    }
    apply_walls(block, l, p, v);
    for (int d = 0; d < 3; ++d) data[(Ch::kVelocity + d) * kBlockNodes + l] = v[d];
  }
  return sums;
}

template <class T, Transfer kTransfer>
FIRN_HD void grid_update_block(T* data, const int block[3], std::size_t slot, const GridUpdateParams<T>& p) {
  const std::uint32_t near = colliders_near_block(block, p);
  const bool is_free = near == 0 && kTransfer != Transfer::flip && !block_in_wall_band(block, p);
  (is_free ? free_block_update<T, kTransfer>(data, p) : node_block_update<T, kTransfer>(data, block, near, slot, p))
      .write(slot, p);
}

}  // namespace firn

// The sums over the grid that one pooled collider's lambda and friction are solved from
// (kernels/pooled_contact.hpp; engine: Simulation::solve_contact_pool), as a parallel_reduce over the
// block slots, for a trial lambda. Over the collider's inside nodes:
//   v[0] = sum m,  v[1] = sum m v_n,
//   v[2] = S(lambda) = sum m (v_n + max(lambda, least)),  v[3] = S'(lambda) = sum m [least < lambda],
//   v[4] = the pool's normal impulse, sum m max(lambda, least);
// over its surface row, v[5] = the friction's demand, sum m |v_t|, and v[6] = sum m (the friction's
// coefficient is taken at the row's mean slip, v[5] / v[6]: the slip it opposes).
// The velocities are those the grid update's pooled collider acts on (pooled_node_velocity), and the
// order of the sums depends only on the slot count, never on the threads.
#pragma once

#include <cstddef>

#include "kernels/grid_slots.hpp"
#include "kernels/grid_update.hpp"
#include "kernels/hd.hpp"
#include "kernels/pooled_contact.hpp"
#include "kernels/step/collider_sums.hpp"

namespace firn {

constexpr int kPoolSums = 7;

template <class T, Transfer kTransfer>
struct ContactPoolSums {
  GridSlotsView<T> slots;
  const GridUpdateParams<T>* params;
  int collider;
  T lambda;

  FIRN_HD void operator()(std::size_t s, DoubleSums<kPoolSums>& acc) const {
    const GridUpdateParams<T>& p = *params;
    const int* block = slots.slot_coords(s);
    if (!(colliders_near_block(block, p) >> collider & 1u)) return;
    const T* data = slots.slot_data(s);
    const T* moments = p.moments.slot_data(s);
    const T skin = T(kColliderSkin) * p.dx;
    for (int l = 0; l < kBlockNodes; ++l) {
      T v[3], x[3];
      if (!pooled_node_velocity<T, kTransfer>(data, block, l, p, v)) continue;
      node_position(block, l, p, x);
      const T m = data[GridChannels<kTransfer>::kMass * kBlockNodes + l];
      const PoolNode<T> q = pool_node(p.colliders[collider], x, v, m, moments + l, p.dx, skin, p.dt);
      if (q.role == kPoolNone) continue;
      if (q.role == kPoolSurface) {
        T t[3];
        const T slip = pool_tangential(q, v, t);
        acc.v[5] += double(m) * double(slip);
        acc.v[6] += double(m);
        continue;
      }
      const T dvn = pool_normal_change(q, lambda);
      acc.v[0] += double(m);
      acc.v[1] += double(m) * double(q.vn);
      acc.v[2] += double(m) * (double(q.vn) + double(dvn));
      if (q.least < lambda) acc.v[3] += double(m);
      acc.v[4] += double(m) * double(dvn);
    }
  }
};

}  // namespace firn

// Multi-velocity-field contact between two groups of bodies (Bardenhagen, Brackbill and Sulsky
// 2000, "The material-point method for granular materials", CMAME 187, section 4; Bardenhagen et
// al. 2001, CMES 2(4)): each group has its own grid (its own P2G, grid update and G2P), so bodies
// of different groups can separate and slide instead of moving as one continuum. At a node both
// groups reach, after the grid update, with masses m_A, m_B, velocities v_A, v_B and the normal n
// from B into A (kernels/step/contact_normals.hpp), the centre-of-mass velocity
//   v_cm = (m_A v_A + m_B v_B) / (m_A + m_B)
// is the "wall" A meets: A's velocity relative to it, v_A - v_cm, gets the domain walls' separate
// condition with friction (kernels/boundary_conditions.hpp: its normal part removed when A
// approaches B, its tangential part reduced by mu |v_n|, with mu from kernels/friction.hpp), and
// B takes the opposite impulse, so momentum is conserved:
//   v_A' = v_cm + r,  v_B' = v_cm - (m_A / m_B) r,  r = the corrected relative velocity.
// Contact acts only where the two bodies fill the node's neighbourhood (kContactVolumeFraction):
// otherwise a node shared across a gap, or at a body's open corner, would push or drag the bodies
// from a cell away. Parallel over the grid's block slots; both grids hold the same blocks in the
// same slots.
#pragma once

#include <cmath>
#include <cstddef>

#include "kernels/boundary_conditions.hpp"
#include "kernels/friction.hpp"
#include "kernels/grid_slots.hpp"
#include "kernels/hd.hpp"
#include "kernels/transfer.hpp"

namespace firn {

// Contact needs the bodies to fill the node's neighbourhood: sum_p w_ip V0_p, the rest volume of
// the particles the node sees, at least this fraction of a cell's volume. By the weights'
// partition of unity a node inside a body filled at the lattice's density holds one cell's
// volume, more where the material has compacted (particles closer together), less beside a gap
// or at a body's open corner (Bardenhagen et al. 2001, section 3.3, with the rest volume so that
// compacting snow still touches). Measured on the block sliding on a slab
// (tests/test_contact_groups.cpp, dx 1 cm, without friction, over 0.19 s): without the criterion
// the nodes at the block's front and back faces drag it at 12 m/s^2 (first 30 ms) and lift it by
// 2 cm; at 0.9 they drag it at 0.73 m/s^2; at 1.0 at 0.008 m/s^2, with the block resting 0.6 mm
// (0.06 dx) into the slab.
constexpr double kContactVolumeFraction = 1.0;

template <class T, Transfer kTransfer>
struct ContactUpdateSlots {
  GridSlotsView<T> a, b, normals;
  T min_mass;
  T min_volume;  // contact needs at least this nodal rest volume (kContactVolumeFraction dx^3)
  Friction<T> friction;

  FIRN_HD void operator()(std::size_t s) const {
    using Ch = GridChannels<kTransfer>;
    T* da = a.slot_data(s);
    T* db = b.slot_data(s);
    const T* dn = normals.slot_data(s);
    for (int l = 0; l < kBlockNodes; ++l) {
      const T ma = da[Ch::kMass * kBlockNodes + l], mb = db[Ch::kMass * kBlockNodes + l];
      if (!(ma > min_mass && mb > min_mass) || !(dn[3 * kBlockNodes + l] >= min_volume)) continue;
      T n[3], len2 = T(0);
      for (int d = 0; d < 3; ++d) n[d] = dn[d * kBlockNodes + l], len2 += n[d] * n[d];
      if (!(len2 > T(0))) continue;
      const T inv_len = T(1) / std::sqrt(len2);
      T* va[3];
      T* vb[3];
      T cm[3], r[3];
      for (int d = 0; d < 3; ++d) {
        n[d] *= inv_len;
        va[d] = da + (Ch::kVelocity + d) * kBlockNodes + l;
        vb[d] = db + (Ch::kVelocity + d) * kBlockNodes + l;
        cm[d] = (ma * *va[d] + mb * *vb[d]) / (ma + mb);
        r[d] = *va[d] - cm[d];
      }
      apply_wall(r, n, WallType::separate, friction);
      for (int d = 0; d < 3; ++d) {
        *va[d] = cm[d] + r[d];
        *vb[d] = cm[d] - ma / mb * r[d];
      }
    }
  }
};

}  // namespace firn

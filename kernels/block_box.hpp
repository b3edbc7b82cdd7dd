// The domain's box of grid blocks: count[d] blocks along axis d, numbered
// b = (bz * count[1] + by) * count[0] + bx, x fastest. The sparse grid's block map
// (kernels/block_window.hpp), the binning's keys (engine/particle_binning.hpp) and the block lists
// (kernels/block_lists.hpp) all number blocks this way, and G2P walks the particles in that order
// (P2G too, within each colour of blocks). x is fastest because the scenes' bulk motion is along
// x (the tire rolls and the conveyor carries the bed along x, the snowballs fly along x): a
// particle that crosses into the next block along x is then found in the block the walk has just
// left or is about to reach, in the cache, until the arrays are reordered (issue 15,
// docs/performance.md).
#pragma once

#include <cstdint>

#include "kernels/hd.hpp"

namespace firn {

struct BlockBox {
  int count[3];

  FIRN_HD int id(int bx, int by, int bz) const { return (bz * count[1] + by) * count[0] + bx; }
  // The id's step for one block along axis d: id(c + e_d) - id(c).
  FIRN_HD int stride(int d) const { return d == 0 ? 1 : d == 1 ? count[0] : count[0] * count[1]; }
  FIRN_HD void coords(std::uint32_t b, int c[3]) const {
    c[0] = int(b) % count[0];
    c[1] = (int(b) / count[0]) % count[1];
    c[2] = int(b) / (count[0] * count[1]);
  }
};

}  // namespace firn

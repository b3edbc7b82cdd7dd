// The domain's box of grid blocks: count[d] blocks along axis d, numbered
// b = (bx * count[1] + by) * count[2] + bz. The sparse grid's block map (kernels/block_window.hpp),
// the binning's keys (engine/particle_binning.hpp) and the block lists (kernels/block_lists.hpp)
// all number blocks this way.
#pragma once

#include <cstdint>

#include "kernels/hd.hpp"

namespace firn {

struct BlockBox {
  int count[3];

  FIRN_HD int id(int bx, int by, int bz) const { return (bx * count[1] + by) * count[2] + bz; }
  FIRN_HD void coords(std::uint32_t b, int c[3]) const {
    c[0] = int(b) / (count[1] * count[2]);
    c[1] = (int(b) / count[2]) % count[1];
    c[2] = int(b) % count[2];
  }
};

}  // namespace firn

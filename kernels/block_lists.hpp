// The block lists a step builds by compaction (kernels/block_compaction.hpp) over the domain's box
// of grid blocks (kernels/block_box.hpp):
//   ParticleBlocks  the binning's (engine/particle_binning.hpp): blocks whose bucket holds a
//                   particle of some material, classed by parity colour; they are listed in id
//                   order and by colour, and flagged in `occupied`;
//   ActiveBlocks    the sparse grid's (engine/sparse_grid.hpp): blocks b + {0,1}^3 of every
//                   particle block, the nodes P2G writes; slot s holds the s-th in id order, and
//                   the block map takes every block's slot or -1.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kernels/backend/block_colouring.hpp"
#include "kernels/block_box.hpp"
#include "kernels/hd.hpp"

namespace firn {

struct ParticleBlockColour {  // classify: the colour of a block holding particles, else -1
  const std::uint32_t* bucket_begin;  // the binning's, [m * block_count + b]
  std::size_t block_count, material_count;
  BlockBox box;

  FIRN_HD int operator()(std::size_t b) const {
    for (std::size_t m = 0; m < material_count; ++m)
      if (bucket_begin[m * block_count + b] != bucket_begin[m * block_count + b + 1]) {
        int c[3];
        box.coords(b, c);
        return backend::block_colour(c[0], c[1], c[2]);
      }
    return -1;
  }
};

struct ParticleBlockLists {  // emit
  std::uint32_t* blocks;    // in id order
  std::uint32_t* coloured;  // grouped by colour
  std::uint8_t* occupied;   // [b]: 1 for a particle block

  FIRN_HD void selected(std::size_t b, int, std::uint32_t by_colour, std::uint32_t in_order) const {
    blocks[in_order] = std::uint32_t(b);
    coloured[by_colour] = std::uint32_t(b);
    occupied[b] = 1;
  }
  FIRN_HD void rejected(std::size_t b) const { occupied[b] = 0; }
};

// Block b is written by the particle blocks b - o, o in {0,1}^3, found as ids b - id(o) with no
// coordinates (which took three integer divisions per block of the box; issue 15): where a
// coordinate of b - o would be negative, the id either is negative (z) or, borrowing, lands in the
// box's last layer along x or y, which holds no particle block (a particle's stencil starts at most
// at node count - support, blocks[d] = ((nodes - 1) >> kBlockShift) + 2: engine/sparse_grid.hpp).
struct ActiveBlock {  // classify: 0 for a block some particle block writes, else -1
  const std::uint8_t* occupied;
  BlockBox box;

  FIRN_HD int operator()(std::size_t b) const {
    const std::size_t sx = std::size_t(box.stride(0)), sy = std::size_t(box.stride(1)), sz = std::size_t(box.stride(2));
    int written = 0;
    for (int o = 0; o < 8; ++o) {
      const std::size_t offset = (o >> 2) * sx + ((o >> 1) & 1) * sy + (o & 1) * sz;  // box.id(o)
      written |= b >= offset ? occupied[b - offset] : 0;
    }
    return written ? 0 : -1;
  }
};

struct ActiveBlockSlots {  // emit
  std::int32_t* map;     // [b]: slot or -1
  std::uint32_t* slots;  // slot -> block id
  int* coords;           // slot -> block coordinates
  BlockBox box;

  FIRN_HD void selected(std::size_t b, int, std::uint32_t, std::uint32_t slot) const {
    map[b] = std::int32_t(slot);
    slots[slot] = std::uint32_t(b);
    box.coords(b, coords + 3 * std::size_t(slot));
  }
  FIRN_HD void rejected(std::size_t b) const { map[b] = -1; }
};

}  // namespace firn

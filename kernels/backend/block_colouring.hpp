// Grid blocks grouped into the eight 2x2x2 parity colours used by the race-free scatter
// (DESIGN.md section 2, rule 7). A particle binned to block b writes only nodes of blocks
// b + {0,1}^3, so two blocks of the same colour (at least two blocks apart on some axis)
// never write the same node and can be processed concurrently without atomics.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kernels/hd.hpp"

namespace firn::backend {

struct BlockColouring {
  static constexpr int kColours = 8;
  const std::uint32_t* blocks = nullptr;  // block ids, grouped by colour
  std::size_t begin[kColours + 1] = {};   // colour c owns blocks[begin[c] .. begin[c+1])
};

// Parity colour of a block from its integer block coordinates.
FIRN_HD int block_colour(int bx, int by, int bz) { return (bx & 1) | ((by & 1) << 1) | ((bz & 1) << 2); }

}  // namespace firn::backend

// Geometry of the background grid shared by the kernels: node (i, j, k) sits at
// origin + (i, j, k) dx. Nodes are stored in blocks of 4x4x4 (kBlockSize^3) so that the grid can
// be sparse; inside a block, channel c of local node l = (lx * 4 + ly) * 4 + lz is at c * 64 + l.
#pragma once

#include "kernels/hd.hpp"

namespace firn {

constexpr int kBlockSize = 4;
constexpr int kBlockShift = 2;
constexpr int kBlockNodes = kBlockSize * kBlockSize * kBlockSize;

FIRN_HD int local_node(int lx, int ly, int lz) { return (lx * kBlockSize + ly) * kBlockSize + lz; }

// Global index n of local node l of the block at block coordinates `block`.
FIRN_HD void block_node(const int block[3], int l, int n[3]) {
  n[0] = block[0] * kBlockSize + l / (kBlockSize * kBlockSize);
  n[1] = block[1] * kBlockSize + (l / kBlockSize) % kBlockSize;
  n[2] = block[2] * kBlockSize + l % kBlockSize;
}

template <class T>
struct GridGeometry {
  T origin[3];
  T dx;
  T inv_dx;
  int nodes[3];  // node count per axis
};

}  // namespace firn

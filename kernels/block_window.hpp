// Block-local windows of the sparse grid used by the CPU scatter and gather strategies.
// A particle binned to block b (by its stencil base node) touches nodes 4b .. 4b + kSpan - 1,
// kSpan = 4 + support - 1, all inside blocks b + {0,1}^3. P2G accumulates a block's particles into
// a small dense scratch (L1-resident, no atomics) and then adds it to the grid; G2P first copies
// the window's velocities out of the sparse grid so the particle loop reads a dense array.
#pragma once

#include <cstdint>

#include "kernels/grid_geometry.hpp"
#include "kernels/hd.hpp"

namespace firn {

// The sparse grid as kernels see it: block slots of kBlockNodes nodes x `channels` values,
// found through a dense map from block coordinates to slot (-1: inactive).
template <class T>
struct SparseGridView {
  T* data;
  int channels;
  const std::int32_t* block_map;
  int blocks[3];

  FIRN_HD T* block(int bx, int by, int bz) const {
    return data + static_cast<long>(block_map[(bx * blocks[1] + by) * blocks[2] + bz]) * channels * kBlockNodes;
  }
};

template <class T, int kSpan, int kChannels>
struct BlockScratch {
  int origin[3];  // global index of local node (0, 0, 0)
  T values[kSpan * kSpan * kSpan * kChannels];

  FIRN_HD void reset(int bx, int by, int bz) {
    origin[0] = bx * kBlockSize;
    origin[1] = by * kBlockSize;
    origin[2] = bz * kBlockSize;
    for (int i = 0; i < kSpan * kSpan * kSpan * kChannels; ++i) values[i] = T(0);
  }
  // The scatter target of p2g_particle.
  FIRN_HD void add(int i, int j, int k, const T* v) {
    T* node = values + (((i - origin[0]) * kSpan + (j - origin[1])) * kSpan + (k - origin[2])) * kChannels;
    for (int c = 0; c < kChannels; ++c) node[c] += v[c];
  }
  // Adds the scratch into the grid. Only one block of a parity colour touches these nodes.
  FIRN_HD void flush(const SparseGridView<T>& grid) const {
    for (int a = 0; a < kSpan; ++a)
      for (int b = 0; b < kSpan; ++b) {
        const int gi = origin[0] + a, gj = origin[1] + b;
        for (int c = 0; c < kSpan; ++c) {
          const int gk = origin[2] + c;
          T* blk = grid.block(gi >> kBlockShift, gj >> kBlockShift, gk >> kBlockShift);
          const int l = local_node(gi & (kBlockSize - 1), gj & (kBlockSize - 1), gk & (kBlockSize - 1));
          const T* v = values + ((a * kSpan + b) * kSpan + c) * kChannels;
          for (int ch = 0; ch < kChannels; ++ch) blk[ch * kBlockNodes + l] += v[ch];
        }
      }
  }
};

// Dense copy of grid channels [first, first + kChannels) over a block's window; lanes past the
// grid's last channel read as zero.
template <class T, int kSpan, int kChannels>
struct BlockGather {
  int origin[3];
  T values[kSpan * kSpan * kSpan * kChannels];

  FIRN_HD void load(const SparseGridView<T>& grid, int first, int bx, int by, int bz) {
    origin[0] = bx * kBlockSize;
    origin[1] = by * kBlockSize;
    origin[2] = bz * kBlockSize;
    for (int a = 0; a < kSpan; ++a)
      for (int b = 0; b < kSpan; ++b) {
        const int gi = origin[0] + a, gj = origin[1] + b;
        for (int c = 0; c < kSpan; ++c) {
          const int gk = origin[2] + c;
          const T* blk = grid.block(gi >> kBlockShift, gj >> kBlockShift, gk >> kBlockShift);
          const int l = local_node(gi & (kBlockSize - 1), gj & (kBlockSize - 1), gk & (kBlockSize - 1));
          T* v = values + ((a * kSpan + b) * kSpan + c) * kChannels;
          for (int ch = 0; ch < kChannels; ++ch)
            v[ch] = first + ch < grid.channels ? blk[(first + ch) * kBlockNodes + l] : T(0);
        }
      }
  }
  // The grid source of g2p_particle.
  FIRN_HD const T* node(int i, int j, int k) const {
    return values + (((i - origin[0]) * kSpan + (j - origin[1])) * kSpan + (k - origin[2])) * kChannels;
  }
};

}  // namespace firn

// Block-local windows of the sparse grid used by the scatter and gather strategies.
// A particle binned to block b (by its stencil base node) touches nodes 4b .. 4b + kSpan - 1,
// kSpan = 4 + support - 1, all inside blocks b + {0,1}^3. P2G accumulates a block's particles into
// a small dense scratch (L1-resident on the CPU, shared memory on a GPU; no atomics) and then adds
// it to the grid; G2P first copies the window's velocities out of the sparse grid so the particle
// loop reads a dense array. Both windows work node by node (`flush_node`, `load_node`) so that a
// GPU thread block can share the work; `flush` and `load` are the single-thread loops, block by
// block of the window (for_each_window_node).
#pragma once

#include <cstdint>
#include <type_traits>

#include "kernels/block_box.hpp"
#include "kernels/grid_geometry.hpp"
#include "kernels/hd.hpp"

namespace firn {

// The sparse grid as kernels see it: block slots of kBlockNodes nodes x `channels` values,
// found through a dense map from block coordinates to slot (-1: inactive).
template <class T>
struct SparseGridView {
  T* data;
  int channels;
  const std::int32_t* block_map;  // [box.id(bx, by, bz)]
  BlockBox box;

  FIRN_HD T* block(int bx, int by, int bz) const {
    return data + static_cast<long>(block_map[box.id(bx, by, bz)]) * channels * kBlockNodes;
  }
};

// The window's local node n = (a kSpan + b) kSpan + c as global node indices from `origin`.
template <int kSpan>
FIRN_HD void window_node(const int origin[3], int n, int g[3]) {
  g[0] = origin[0] + n / (kSpan * kSpan);
  g[1] = origin[1] + (n / kSpan) % kSpan;
  g[2] = origin[2] + n % kSpan;
}

// f(n, data, l) for every local node n of the window whose node (0, 0, 0) is `origin` (a block's
// first node): data is the grid block holding the node and l the node's index in it. The window lies
// in the blocks origin / kBlockSize + {0, 1}^3, so each of them is looked up once for all its nodes
// (the single-thread loops `flush` and `load`; a GPU thread takes one node by window_node).
template <int kSpan, class T, class F>
FIRN_HD void for_each_window_node(const SparseGridView<T>& grid, const int origin[3], F&& f) {
  static_assert(kSpan > kBlockSize && kSpan <= 2 * kBlockSize, "a window spans two blocks per axis");
  for (int bx = 0; bx < 2; ++bx)
    for (int by = 0; by < 2; ++by)
      for (int bz = 0; bz < 2; ++bz) {
        T* data = grid.block((origin[0] >> kBlockShift) + bx, (origin[1] >> kBlockShift) + by,
                             (origin[2] >> kBlockShift) + bz);
        for (int x = bx * kBlockSize; x < (bx ? kSpan : kBlockSize); ++x)
          for (int y = by * kBlockSize; y < (by ? kSpan : kBlockSize); ++y)
            for (int z = bz * kBlockSize; z < (bz ? kSpan : kBlockSize); ++z)
              f((x * kSpan + y) * kSpan + z, data,
                local_node(x - bx * kBlockSize, y - by * kBlockSize, z - bz * kBlockSize));
      }
}

template <class T, int kSpan, int kChannels>
struct BlockScratch {
  static constexpr int kNodes = kSpan * kSpan * kSpan;
  int origin[3];  // global index of local node (0, 0, 0)
  T values[kNodes * kChannels];

  FIRN_HD void set_origin(const int block[3]) {
    for (int d = 0; d < 3; ++d) origin[d] = block[d] * kBlockSize;
  }
  FIRN_HD void reset(const int block[3]) {
    set_origin(block);
    for (int i = 0; i < kNodes * kChannels; ++i) values[i] = T(0);
  }
  // The first channel of global node (i, j, k); nodes (i, j, k .. k + n) are consecutive.
  FIRN_HD T* node(int i, int j, int k) {
    return values + (((i - origin[0]) * kSpan + (j - origin[1])) * kSpan + (k - origin[2])) * kChannels;
  }
  // The scatter target of p2g_particle: nodes (i, j, k .. k + kRow - 1).
  template <int kRow>
  FIRN_HD void add_row(int i, int j, int k, const T* v) {
    T* node = this->node(i, j, k);
    FIRN_LANES
    for (int c = 0; c < kRow * kChannels; ++c) node[c] += v[c];
  }
  // Adds local node n into the grid. Only one block of a parity colour touches these nodes.
  FIRN_HD void flush_node(const SparseGridView<T>& grid, int n) const {
    int g[3];
    window_node<kSpan>(origin, n, g);
    T* blk = grid.block(g[0] >> kBlockShift, g[1] >> kBlockShift, g[2] >> kBlockShift);
    const int l = local_node(g[0] & (kBlockSize - 1), g[1] & (kBlockSize - 1), g[2] & (kBlockSize - 1));
    add_node(n, blk, l);
  }
  FIRN_HD void flush(const SparseGridView<T>& grid) const {
    for_each_window_node<kSpan>(grid, origin, [&](int n, T* blk, int l) { add_node(n, blk, l); });
  }
  // Adds local node n into node l of the grid block blk.
  FIRN_HD void add_node(int n, T* blk, int l) const {
    for (int ch = 0; ch < kChannels; ++ch) blk[ch * kBlockNodes + l] += values[n * kChannels + ch];
  }
};

// Dense copy of grid channels [first, first + kChannels) over a block's window; lanes past the
// grid's last channel read as zero.
template <class T, int kSpan, int kChannels>
struct BlockGather {
  static constexpr int kNodes = kSpan * kSpan * kSpan;
  int origin[3];
  T values[kNodes * kChannels];

  FIRN_HD void set_origin(const int block[3]) {
    for (int d = 0; d < 3; ++d) origin[d] = block[d] * kBlockSize;
  }
  FIRN_HD void load_node(const SparseGridView<T>& grid, int first, int n) {
    int g[3];
    window_node<kSpan>(origin, n, g);
    const T* blk = grid.block(g[0] >> kBlockShift, g[1] >> kBlockShift, g[2] >> kBlockShift);
    const int l = local_node(g[0] & (kBlockSize - 1), g[1] & (kBlockSize - 1), g[2] & (kBlockSize - 1));
    copy_node(n, blk, l, grid.channels, first);
  }
  FIRN_HD void load(const SparseGridView<T>& grid, int first, const int block[3]) {
    set_origin(block);
    for_each_window_node<kSpan>(grid, origin,
                                [&](int n, const T* blk, int l) { copy_node(n, blk, l, grid.channels, first); });
  }
  // Copies channels [first, first + kChannels) of node l of the grid block blk (which has
  // `channels` channels) into local node n.
  FIRN_HD void copy_node(int n, const T* blk, int l, int channels, int first) {
    T* v = values + n * kChannels;
    for (int ch = 0; ch < kChannels; ++ch) v[ch] = first + ch < channels ? blk[(first + ch) * kBlockNodes + l] : T(0);
  }
  // The grid source of g2p_particle: nodes (i, j, k ..) are consecutive here.
  FIRN_HD const T* row(int i, int j, int k) const {
    return values + (((i - origin[0]) * kSpan + (j - origin[1])) * kSpan + (k - origin[2])) * kChannels;
  }
};

static_assert(std::is_trivially_copyable_v<SparseGridView<float>>, "views are copied into kernels");

}  // namespace firn

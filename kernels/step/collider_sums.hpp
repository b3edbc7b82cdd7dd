// The sums over blocks of what the grid update records per block (kernels/grid_update.hpp), as
// launches on the backend, so that under the CUDA backend the per-block buffers never leave the
// device (issue 14, item 3):
//   SlotReactions   parallel_reduce over slots: one collider's force and torque (6 components),
//                   in double, both contact groups' blocks when `b` is set;
//   SlotWork        parallel_reduce over slots: the energy budget's work kinds;
//   FootprintColumns parallel_for over the box's block columns (bx, bz): adds each column's vertical
//                   impulse to the footprint map, the blocks of a column in increasing by, which is
//                   their slot order (slots are numbered in increasing block id), so every map entry
//                   receives the same additions in the same order as a loop over the slots would.
// The reductions' order depends only on the slot count (reduce_chunks.hpp), never on the threads.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kernels/block_lists.hpp"
#include "kernels/block_window.hpp"
#include "kernels/hd.hpp"

namespace firn {

template <int N>
struct DoubleSums {
  double v[N] = {};
  FIRN_HD DoubleSums& operator+=(const DoubleSums& o) {
    for (int i = 0; i < N; ++i) v[i] += o.v[i];
    return *this;
  }
};

// Adds entries [slot * stride + offset, + N) of `a` (and of `b` where set) to the sums.
template <class T, int N>
struct SlotSums {
  const T* a;
  const T* b;  // the second contact group's, or nullptr
  std::size_t stride, offset;

  FIRN_HD void operator()(std::size_t slot, DoubleSums<N>& acc) const {
    const std::size_t q = slot * stride + offset;
    for (int i = 0; i < N; ++i) acc.v[i] += double(a[q + std::size_t(i)]) + (b ? double(b[q + std::size_t(i)]) : 0.0);
  }
};

template <class T>
struct FootprintColumns {
  const T* a;  // [slot][kBlockSize * kBlockSize] vertical force per node column
  const T* b;  // the second contact group's, or nullptr
  const std::int32_t* map;  // block id -> slot or -1
  BlockBox box;
  double dt;
  double* impulse;  // [i * nz + k]
  int nx, nz;

  FIRN_HD void operator()(std::size_t column) const {
    const int bx = int(column / std::size_t(box.count[2])), bz = int(column % std::size_t(box.count[2]));
    for (int by = 0; by < box.count[1]; ++by) {
      const std::int32_t slot = map[box.id(bx, by, bz)];
      if (slot < 0) continue;
      for (int lx = 0; lx < kBlockSize; ++lx)
        for (int lz = 0; lz < kBlockSize; ++lz) {
          const int i = bx * kBlockSize + lx, k = bz * kBlockSize + lz;
          if (i >= nx || k >= nz) continue;
          const std::size_t q = std::size_t(slot) * kBlockSize * kBlockSize + std::size_t(lx * kBlockSize + lz);
          impulse[std::size_t(i) * std::size_t(nz) + std::size_t(k)] += dt * (double(a[q]) + (b ? double(b[q]) : 0.0));
        }
    }
  }
};

}  // namespace firn

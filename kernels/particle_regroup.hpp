// The permutations that regroup the particle columns (ParticleStorage::gather), built where the
// columns live (on the GPU under the CUDA backend) so that adding and removing particles, as a
// conveyor does every few steps, does not bring the columns to the host (issue 14, item 3):
//   RunOrder           order[i] for a concatenation of contiguous runs of old indices (the
//                      particles grouped by material after some were added);
//   KeptParticle       classifies the particle at position first + i of a walk (walk[first + i]) for
//                      a compaction (kernels/block_compaction.hpp): 0 where it stays, -1 where
//                      `remove` takes it;
//   KeptList           writes the kept particles' indices, in the walk's order, into `order`.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kernels/hd.hpp"
#include "kernels/particle_attributes.hpp"

namespace firn {

// New indices [to, to + count) take old indices [from, from + count).
struct ParticleRun {
  std::size_t to, from, count;
};

struct RunOrder {
  const ParticleRun* runs;  // by increasing `to`, covering [0, n) without gaps
  std::size_t run_count;
  std::uint32_t* order;

  FIRN_HD void operator()(std::size_t i) const {
    std::size_t lo = 0, hi = run_count;  // the last run with to <= i
    while (hi - lo > 1) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (runs[mid].to <= i) lo = mid;
      else hi = mid;
    }
    order[i] = std::uint32_t(runs[lo].from + (i - runs[lo].to));
  }
};

template <class T, class Remove>
struct KeptParticle {
  Remove remove;  // remove(pv, p): a kernel-style predicate
  ParticleView<T> pv;
  const std::uint32_t* walk;  // old indices in the order they are to keep
  std::size_t first;          // the material's first position in the walk

  FIRN_HD int operator()(std::size_t i) const { return remove(pv, walk[first + i]) ? -1 : 0; }
};

struct KeptList {
  std::uint32_t* order;       // the material's first new position
  const std::uint32_t* walk;  // as in KeptParticle
  std::size_t first;

  FIRN_HD void selected(std::size_t i, int, std::uint32_t, std::uint32_t position) const {
    order[position] = walk[first + i];
  }
  FIRN_HD void rejected(std::size_t) const {}
};

}  // namespace firn

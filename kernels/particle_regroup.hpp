// The permutations and moves that regroup the particle columns (ParticleStorage::gather and
// ParticleStorage::move), built where the columns live (on the GPU under the CUDA backend) so that
// adding and removing particles, as a conveyor does every few steps, does not bring the columns to
// the host (issue 14, item 3):
//   RunOrder           order[i] for a concatenation of contiguous runs of old indices (the
//                      particles grouped by material after some were added);
//   RefillClass, RefillList  a removal's holes in a material's range and the particles from its
//                      tail that fill them (ParticleStorage::move);
//   RunMoves           the moves that shift a run of particles.
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

// A removal's refill of one material's range [first, first + n) that keeps `end - first`
// particles: each removed particle below `end` is a hole (class 0), each kept one from `end` on a
// source (class 1), as many of each, for a compaction (kernels/block_compaction.hpp). RefillList
// writes the holes' positions and then the sources', each in increasing order, so that source i
// fills hole i.
template <class T, class Remove>
struct RefillClass {
  Remove remove;  // remove(pv, p): a kernel-style predicate
  ParticleView<T> pv;
  std::size_t first, end;

  FIRN_HD int operator()(std::size_t i) const {
    const std::size_t p = first + i;
    const bool removed = remove(pv, p);
    return p < end ? (removed ? 0 : -1) : (removed ? -1 : 1);
  }
};

struct RefillList {
  std::uint32_t* moves;  // [holes..., sources...]
  std::size_t first;

  FIRN_HD void selected(std::size_t i, int, std::uint32_t position, std::uint32_t) const {
    moves[position] = std::uint32_t(first + i);
  }
  FIRN_HD void rejected(std::size_t) const {}
};

// A run's move: particles [from, from + count) onto [to, to + count), two ranges that do not
// overlap, as the lists ParticleStorage::move reads ([to..., from...]).
struct RunMoves {
  std::uint32_t* moves;
  std::size_t to, from, count;

  FIRN_HD void operator()(std::size_t i) const {
    moves[i] = std::uint32_t(to + i);
    moves[count + i] = std::uint32_t(from + i);
  }
};

}  // namespace firn

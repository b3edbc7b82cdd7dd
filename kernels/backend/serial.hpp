// The serial reference backend: the same small API as the OpenMP and CUDA backends (parallel_for,
// parallel_reduce, a scatter over coloured blocks, a gather over blocks), every launch named, run
// on one thread.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kernels/backend/block_colouring.hpp"
#include "kernels/backend/launch_profile.hpp"
#include "kernels/backend/memory_space.hpp"
#include "kernels/backend/reduce_chunks.hpp"
#include "kernels/backend/scatter_skip.hpp"
#include "kernels/backend/schedule.hpp"
#include "kernels/lanes.hpp"

namespace firn::backend {

struct Serial {
  static constexpr const char* kName = "serial";
  static constexpr int kVectorBytes = kHostVectorBytes;  // lanes per batch: kernels/lanes.hpp
  LaunchProfile* profile = nullptr;
  // true: scatter_blocks runs every block, also those a scatter's keeps(b) leaves out. Those add
  // only to nodes nothing reads, so the results must not change: a check of keeps(b) (the
  // restriction of the pooled contact's moments, tests/test_pooled_contact.cpp).
  bool scatter_every_block = false;

  int threads() const { return 1; }
  static const MemorySpace& memory() { return kHostMemory; }

  template <class F>
  void parallel_for(const char* name, std::size_t n, F&& f, Schedule = Schedule::uniform) const {
    ScopedLaunch timer(profile, name);
    for (std::size_t i = 0; i < n; ++i) f(i);
  }

  // f(i, acc) accumulates item i into acc; combine(acc, partial) merges; init must be the
  // identity of combine; grain is the items per chunk. Deterministic: see reduce_chunks.hpp.
  template <class R, class F, class Combine>
  R parallel_reduce(const char* name, std::size_t n, R init, F&& f, Combine&& combine,
                    std::size_t grain = kReduceGrain) const {
    ScopedLaunch timer(profile, name);
    R result = init;
    for (std::size_t c = 0; c < reduce_chunk_count(n, grain); ++c) {
      R partial = init;
      reduce_chunk(c, n, grain, partial, f);
      combine(result, partial);
    }
    return result;
  }

  // The P2G scatter strategy: f(block) for every block f keeps (scatter_skip.hpp), colour after colour.
  template <class F>
  void scatter_blocks(const char* name, const BlockColouring& colouring, F&& f) const {
    ScopedLaunch timer(profile, name);
    for (int c = 0; c < BlockColouring::kColours; ++c)
      for (std::size_t i = colouring.begin[c]; i < colouring.begin[c + 1]; ++i)
        if (scatter_every_block || scatter_keeps(f, colouring.blocks[i])) f(colouring.blocks[i]);
  }

  // The G2P gather strategy: f(block) -> R for blocks[0 .. count), combined in block order into
  // R{} (the identity of combine).
  template <class F, class Combine>
  auto gather_blocks(const char* name, const std::uint32_t* blocks, std::size_t count, const F& f,
                     Combine&& combine) const {
    ScopedLaunch timer(profile, name);
    decltype(f(blocks[0])) result{};
    for (std::size_t i = 0; i < count; ++i) combine(result, f(blocks[i]));
    return result;
  }
};

}  // namespace firn::backend

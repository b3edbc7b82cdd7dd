// The OpenMP backend: same API as backend::Serial. Results are bitwise identical to the serial
// backend for any thread count: parallel_for writes disjoint items, reductions use the fixed
// chunking of reduce_chunks.hpp, and the scatter runs same-colour blocks (which never share a
// node) concurrently, colour after colour; the gather combines its per-block results in block order.
#pragma once

#include <omp.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernels/backend/block_colouring.hpp"
#include "kernels/backend/launch_profile.hpp"
#include "kernels/backend/memory_space.hpp"
#include "kernels/backend/reduce_chunks.hpp"
#include "kernels/backend/scatter_skip.hpp"
#include "kernels/backend/schedule.hpp"
#include "kernels/lanes.hpp"

namespace firn::backend {

struct OpenMP {
  static constexpr const char* kName = "openmp";
  static constexpr int kVectorBytes = kHostVectorBytes;  // lanes per batch: kernels/lanes.hpp
  // Launches with fewer items run on the calling thread: waking the team costs more than they do.
  static constexpr long kMinParallelItems = 4096;
  static constexpr long kMinParallelBlocks = 64;
  static constexpr int kGatherChunk = 16;  // blocks per hand-out in gather_blocks
  static constexpr int kScatterChunk = 4;  // blocks of one colour per hand-out in scatter_blocks
  int thread_count = omp_get_max_threads();
  LaunchProfile* profile = nullptr;

  OpenMP() = default;
  // `threads` threads; 0 or less: all cores (the default above).
  explicit OpenMP(int threads) : thread_count(threads > 0 ? threads : omp_get_max_threads()) {}

  int threads() const { return thread_count; }
  static const MemorySpace& memory() { return kHostMemory; }

  template <class F>
  void parallel_for(const char* name, std::size_t n, F&& f, Schedule schedule = Schedule::uniform) const {
    ScopedLaunch timer(profile, name);
    const long count = static_cast<long>(n);
    if (schedule == Schedule::uniform) {
#pragma omp parallel for num_threads(thread_count) schedule(static) if (count >= kMinParallelItems)
      for (long i = 0; i < count; ++i) f(static_cast<std::size_t>(i));
    } else if (schedule == Schedule::parts) {
#pragma omp parallel for num_threads(thread_count) schedule(static, 1)
      for (long i = 0; i < count; ++i) f(static_cast<std::size_t>(i));
    } else if (schedule == Schedule::uneven) {
#pragma omp parallel for num_threads(thread_count) schedule(dynamic, 1) if (count >= kMinParallelBlocks)
      for (long i = 0; i < count; ++i) f(static_cast<std::size_t>(i));
    } else {
      // From 64 blocks on, guided: runs that shrink as the launch ends, for the blocks that reach a
      // collider. tire_on_snow's grid update (issue 15, Intel Xeon, 2 threads) took 2.76 ms per step
      // as uniform items (fewer than kMinParallelItems: one thread), 1.40 ms guided, 1.45-1.80 ms
      // dynamic in runs of 1 to 16 blocks.
#pragma omp parallel for num_threads(thread_count) schedule(guided) if (count >= kMinParallelBlocks)
      for (long i = 0; i < count; ++i) f(static_cast<std::size_t>(i));
    }
  }

  template <class R, class F, class Combine>
  R parallel_reduce(const char* name, std::size_t n, R init, F&& f, Combine&& combine,
                    std::size_t grain = kReduceGrain) const {
    ScopedLaunch timer(profile, name);
    const long chunks = static_cast<long>(reduce_chunk_count(n, grain));
    std::vector<R> partial(static_cast<std::size_t>(chunks), init);
#pragma omp parallel for num_threads(thread_count) schedule(static) if (chunks > 1)
    for (long c = 0; c < chunks; ++c) reduce_chunk(static_cast<std::size_t>(c), n, grain, partial[c], f);
    R result = init;
    for (const R& p : partial) combine(result, p);
    return result;
  }

  template <class F>
  void scatter_blocks(const char* name, const BlockColouring& colouring, F&& f) const {
    ScopedLaunch timer(profile, name);
#pragma omp parallel num_threads(thread_count) \
    if (static_cast<long>(colouring.begin[BlockColouring::kColours]) >= kMinParallelBlocks)
    for (int c = 0; c < BlockColouring::kColours; ++c) {
      const long begin = static_cast<long>(colouring.begin[c]), end = static_cast<long>(colouring.begin[c + 1]);
      // The implicit barrier at the end of each loop separates the colours. Runs of kScatterChunk
      // blocks rather than single ones (issue 15, Intel Xeon, 2 threads, P2G alternated over 8
      // rounds: tire_on_snow 17.2-18.5 -> 15.4-18.1 ms per step, snowball_pair 6.8-7.5 -> 6.2-7.4;
      // faster in 19 of 21 runs, cube_drop's included). Why runs help was not measured (no
      // hardware counters there).
#pragma omp for schedule(dynamic, kScatterChunk)
      for (long i = begin; i < end; ++i)
        if (scatter_keeps(f, colouring.blocks[i])) f(colouring.blocks[i]);
    }
  }

  template <class F, class Combine>
  auto gather_blocks(const char* name, const std::uint32_t* blocks, std::size_t count, const F& f,
                     Combine&& combine) const {
    ScopedLaunch timer(profile, name);
    using R = decltype(f(blocks[0]));
    std::vector<R> partial(count);
    const long n = static_cast<long>(count);
    // Runs of kGatherChunk consecutive blocks per thread, not single blocks: consecutive blocks'
    // particles are neighbours in the particle arrays (and their results in `partial`), so handing
    // them to different threads made the threads write the same cache lines at every block
    // boundary. The result does not depend on the schedule (partial is combined in order).
#pragma omp parallel for num_threads(thread_count) schedule(dynamic, kGatherChunk) if (n >= kMinParallelBlocks)
    for (long i = 0; i < n; ++i) partial[static_cast<std::size_t>(i)] = f(blocks[i]);
    R result{};
    for (const R& p : partial) combine(result, p);
    return result;
  }
};

}  // namespace firn::backend

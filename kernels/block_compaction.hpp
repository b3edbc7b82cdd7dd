// Stream compaction of grid blocks, in three data-parallel launches, so that the block lists a step
// needs are built where the buffers live (on the GPU under the CUDA backend; issue 14, item 3).
// A `Classify` functor puts each block id b of [0, n) in a class k in [0, kClasses) or leaves it out
// (-1); the compaction lists the selected blocks in increasing id, grouped by class:
//   CompactionCount   per chunk of kCompactionChunk ids, how many of each class (one item a chunk),
//                     keeping each block's class so that the write does not classify again;
//   CompactionPrefix  one item: each chunk's first position per class (exclusive prefix over the
//                     chunks, class after class), and the classes' begins in `begins`;
//   CompactionWrite   per chunk: `emit.selected(b, k, position in the class-grouped list, position
//                     in the plain increasing list)` for each selected block, `emit.rejected(b)`
//                     for the others.
// The result is unique (it depends on neither the thread count nor the backend). The prefix runs
// on one thread: a domain's block box has a few hundred thousand blocks at most, so a few thousand
// chunks.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kernels/hd.hpp"

namespace firn {

constexpr std::size_t kCompactionChunk = 256;

FIRN_HD std::size_t compaction_chunks(std::size_t n) { return (n + kCompactionChunk - 1) / kCompactionChunk; }

template <int kClasses, class Classify>
struct CompactionCount {
  Classify classify;
  std::size_t n;
  std::uint32_t* counts;  // [chunk][kClasses]
  std::int8_t* classes;   // [b]: classify(b)

  FIRN_HD void operator()(std::size_t chunk) const {
    std::uint32_t c[kClasses] = {};
    const std::size_t end = (chunk + 1) * kCompactionChunk < n ? (chunk + 1) * kCompactionChunk : n;
    for (std::size_t b = chunk * kCompactionChunk; b < end; ++b) {
      const int k = classify(b);
      classes[b] = std::int8_t(k);
      if (k >= 0) ++c[k];
    }
    for (int k = 0; k < kClasses; ++k) counts[chunk * kClasses + std::size_t(k)] = c[k];
  }
};

template <int kClasses>
struct CompactionPrefix {
  std::size_t chunks;
  std::uint32_t* counts;  // in: per chunk and class; out: the chunk's first position in its class's list
  std::uint32_t* begins;  // out: [kClasses + 1], class k's list is [begins[k], begins[k + 1])

  FIRN_HD void operator()(std::size_t) const {
    std::uint32_t running = 0;
    for (int k = 0; k < kClasses; ++k) {
      begins[k] = running;
      for (std::size_t c = 0; c < chunks; ++c) {
        const std::uint32_t count = counts[c * kClasses + std::size_t(k)];
        counts[c * kClasses + std::size_t(k)] = running;
        running += count;
      }
    }
    begins[kClasses] = running;
  }
};

template <int kClasses, class Emit>
struct CompactionWrite {
  Emit emit;
  std::size_t n;
  const std::int8_t* classes;    // CompactionCount's
  const std::uint32_t* offsets;  // CompactionPrefix's counts
  const std::uint32_t* begins;   // CompactionPrefix's begins

  FIRN_HD void operator()(std::size_t chunk) const {
    std::uint32_t next[kClasses];
    std::uint32_t plain = 0;  // selected blocks before this chunk: its first position in the plain list
    for (int k = 0; k < kClasses; ++k) {
      next[k] = offsets[chunk * kClasses + std::size_t(k)];
      plain += next[k] - begins[k];
    }
    const std::size_t end = (chunk + 1) * kCompactionChunk < n ? (chunk + 1) * kCompactionChunk : n;
    for (std::size_t b = chunk * kCompactionChunk; b < end; ++b) {
      const int k = classes[b];
      if (k >= 0)
        emit.selected(b, k, next[k]++, plain++);
      else
        emit.rejected(b);
    }
  }
};

}  // namespace firn

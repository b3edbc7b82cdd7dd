// Fixed chunking for reductions: the partition of [0, n) depends only on n, never on the thread
// count, and partial results are combined in chunk order, so a floating-point reduction gives
// bitwise identical results on every backend and thread count. A launch whose items are heavy
// (batches of particles, kernels/step/constitutive_update.hpp) passes a smaller grain, so that a
// range of a few chunks still spreads over the threads; the partition still depends only on n and
// the grain.
#pragma once

#include <cstddef>

namespace firn::backend {

constexpr std::size_t kReduceGrain = 4096;

inline std::size_t reduce_chunk_count(std::size_t n, std::size_t grain) { return (n + grain - 1) / grain; }

// Runs f(i, acc) over chunk c (of `grain` items) of [0, n) into acc, through a local copy: one
// whose address the loop never exposes stays in a register, where the compiler can vectorise the
// reduction, which it cannot prove safe through a reference into the caller's array.
template <class R, class F>
void reduce_chunk(std::size_t c, std::size_t n, std::size_t grain, R& acc, F& f) {
  const std::size_t end = (c + 1) * grain < n ? (c + 1) * grain : n;
  R local = acc;
  for (std::size_t i = c * grain; i < end; ++i) f(i, local);
  acc = local;
}

}  // namespace firn::backend

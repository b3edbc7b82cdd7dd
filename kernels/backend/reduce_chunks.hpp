// Fixed chunking for reductions: the partition of [0, n) depends only on n, never on the thread
// count, and partial results are combined in chunk order, so a floating-point reduction gives
// bitwise identical results on every backend and thread count.
#pragma once

#include <cstddef>

namespace firn::backend {

constexpr std::size_t kReduceGrain = 4096;

inline std::size_t reduce_chunk_count(std::size_t n) { return (n + kReduceGrain - 1) / kReduceGrain; }

// Runs f(i, acc) over chunk c of [0, n) into acc.
template <class R, class F>
void reduce_chunk(std::size_t c, std::size_t n, R& acc, F& f) {
  const std::size_t end = (c + 1) * kReduceGrain < n ? (c + 1) * kReduceGrain : n;
  for (std::size_t i = c * kReduceGrain; i < end; ++i) f(i, acc);
}

}  // namespace firn::backend

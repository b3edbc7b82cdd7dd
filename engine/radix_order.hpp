// The indices 0..n-1 in increasing order of their 32-bit keys, ties in index order, by a least
// significant digit radix sort (Knuth, TAOCP vol. 3, sec. 5.2.5): two stable counting passes of
// 16 bits each, O(n), where a comparison sort of particle ids took O(n log n) with a random
// access per comparison (14 ms per output frame of 359,208 particles). Passes whose digit is the
// same for every key are skipped.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace firn {

// The second buffer of indices and the digit counts, kept by a caller that sorts every frame so
// that nothing is allocated after the first call.
struct RadixBuffers {
  std::vector<std::uint32_t> scratch, count;
};

// Fills `order` with the sorted indices.
inline void radix_order(const std::uint32_t* keys, std::size_t n, std::vector<std::uint32_t>& order,
                        RadixBuffers& buffers) {
  std::vector<std::uint32_t>& scratch = buffers.scratch;
  std::vector<std::uint32_t>& count = buffers.count;
  order.resize(n);
  scratch.resize(n);
  count.resize(1u << 16);
  for (std::size_t i = 0; i < n; ++i) order[i] = std::uint32_t(i);
  for (int shift = 0; shift < 32; shift += 16) {
    std::fill(count.begin(), count.end(), 0u);
    for (std::size_t i = 0; i < n; ++i) ++count[(keys[i] >> shift) & 0xffffu];
    if (n && count[(keys[0] >> shift) & 0xffffu] == n) continue;  // one digit for all: order stands
    std::uint32_t sum = 0;
    for (std::uint32_t& c : count) {
      const std::uint32_t here = c;
      c = sum;
      sum += here;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t index = order[i];
      scratch[count[(keys[index] >> shift) & 0xffffu]++] = index;
    }
    order.swap(scratch);
  }
}

}  // namespace firn

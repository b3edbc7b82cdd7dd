// A few physical index ranges [begin, end) of particles (materials are contiguous ranges), as a
// kernel tests membership: the averaged materials of the F-bar stage, the second contact group.
#pragma once

#include <cstddef>

#include "kernels/hd.hpp"

namespace firn {

struct ParticleRanges {
  static constexpr int kMax = 8;
  std::size_t begin[kMax], end[kMax];
  int count = 0;
  FIRN_HD bool holds(std::size_t p) const {
    for (int r = 0; r < count; ++r)
      if (p >= begin[r] && p < end[r]) return true;
    return false;
  }
};

}  // namespace firn

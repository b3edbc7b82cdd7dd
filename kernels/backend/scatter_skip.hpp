// Which blocks a block scatter runs: every block, but where the scatter functor has a member
// keeps(b), only the blocks it keeps (kernels/step/contact_pool_moments.hpp keeps the particle
// blocks that reach the nodes its pool reads). Every backend asks before it scatters a block, so
// the CPU and the GPU skip the same blocks.
#pragma once

#include <cstdint>

#include "kernels/hd.hpp"

namespace firn::backend {

template <class S>
FIRN_HD auto scatter_keeps_impl(const S& scatter, std::uint32_t b, int) -> decltype(bool(scatter.keeps(b))) {
  return scatter.keeps(b);
}
template <class S>
FIRN_HD bool scatter_keeps_impl(const S&, std::uint32_t, long) {
  return true;
}

// Whether block b of the scatter's blocks is scattered.
template <class S>
FIRN_HD bool scatter_keeps(const S& scatter, std::uint32_t b) {
  return scatter_keeps_impl(scatter, b, 0);
}

}  // namespace firn::backend

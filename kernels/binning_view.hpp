// The particle binning as kernels see it (engine/particle_binning.hpp builds it): the sorted
// order of physical particle indices and, per (non-empty material m, grid block b), the bucket of
// sorted positions [bucket_begin(m, b), bucket_end(m, b)). Trivially copyable, raw pointers only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "kernels/hd.hpp"

namespace firn {

struct BinningView {
  const std::uint32_t* order;   // sorted position -> physical particle index
  const std::uint32_t* begins;  // [m * block_count + b], block_count * material_count + 1 entries
  std::size_t block_count;
  std::size_t material_count;   // the non-empty materials
  // Bit m set: bucket m takes part; a cleared bit makes it empty, so that a launch over one
  // contact group's grid sees only that group's materials (kernels/step/contact_update.hpp).
  std::uint64_t material_mask = ~std::uint64_t(0);

  FIRN_HD std::uint32_t bucket_begin(std::size_t m, std::uint32_t b) const { return begins[m * block_count + b]; }
  FIRN_HD std::uint32_t bucket_end(std::size_t m, std::uint32_t b) const {
    return begins[m * block_count + b + ((material_mask >> m) & 1u)];
  }
};

static_assert(std::is_trivially_copyable_v<BinningView>, "views are copied into kernels");

}  // namespace firn

// The sparse grid's active blocks by storage slot, as the grid update sees them: slot s holds
// `channels` x kBlockNodes values at data + s * channels * kBlockNodes and sits at block
// coordinates coords[3 s .. 3 s + 2]. Trivially copyable.
#pragma once

#include <cstddef>
#include <type_traits>

#include "kernels/grid_geometry.hpp"
#include "kernels/hd.hpp"

namespace firn {

template <class T>
struct GridSlotsView {
  T* data;
  const int* coords;
  int channels;

  FIRN_HD T* slot_data(std::size_t s) const { return data + s * std::size_t(channels) * kBlockNodes; }
  FIRN_HD const int* slot_coords(std::size_t s) const { return coords + 3 * s; }
};

static_assert(std::is_trivially_copyable_v<GridSlotsView<float>>, "views are copied into kernels");

}  // namespace firn

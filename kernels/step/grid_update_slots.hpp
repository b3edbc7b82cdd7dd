// The step's grid update as a parallel_for over the active block slots (kernels/grid_update.hpp
// for one block). The parameters, about 9 KB with the colliders in float, are read through a
// pointer rather than copied into every launch (a CUDA kernel's parameters are limited in size).
#pragma once

#include <cstddef>

#include "kernels/grid_slots.hpp"
#include "kernels/grid_update.hpp"
#include "kernels/hd.hpp"

namespace firn {

template <class T, Transfer kTransfer>
struct GridUpdateSlots {
  GridSlotsView<T> slots;
  const GridUpdateParams<T>* params;

  FIRN_HD void operator()(std::size_t s) const {
    grid_update_block<T, kTransfer>(slots.slot_data(s), slots.slot_coords(s), s, *params);
  }
};

}  // namespace firn

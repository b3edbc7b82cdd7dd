// std::vector over a backend's memory space (kernels/backend/memory_space.hpp): 64-byte aligned
// host memory on the CPU backends, so that every structure-of-arrays column starts on a line
// boundary; memory the device can reach on the CUDA backend. Every buffer a kernel reads or writes
// is an AlignedVector. A vector keeps the space it was constructed in (the default then), and its
// moves and swaps carry the space along with the storage.
#pragma once

#include <cstddef>
#include <type_traits>
#include <vector>

#include "kernels/backend/memory_space.hpp"

namespace firn {

template <class T>
struct AlignedAllocator {
  using value_type = T;
  using propagate_on_container_move_assignment = std::true_type;
  using propagate_on_container_swap = std::true_type;
  using is_always_equal = std::false_type;

  const backend::MemorySpace* space = &backend::default_memory_space();

  AlignedAllocator() = default;
  template <class U>
  AlignedAllocator(const AlignedAllocator<U>& other) : space(other.space) {}

  T* allocate(std::size_t n) { return static_cast<T*>(space->allocate(n * sizeof(T))); }
  void deallocate(T* p, std::size_t n) { space->deallocate(p, n * sizeof(T)); }

  template <class U>
  bool operator==(const AlignedAllocator<U>& other) const { return space == other.space; }
  template <class U>
  bool operator!=(const AlignedAllocator<U>& other) const { return space != other.space; }
};

template <class T>
using AlignedVector = std::vector<T, AlignedAllocator<T>>;

}  // namespace firn

// Where a backend's buffers live (issue 14, item 3): a MemorySpace allocates and frees raw bytes.
// The CPU backends use host memory (64-byte aligned: a cache line, and a full AVX-512 register);
// the CUDA backend uses memory the device reads and writes (kernels/backend/cuda.hpp). Each
// backend names its space (Backend::memory()). Containers take the default space when they are
// constructed and keep it (engine/aligned_vector.hpp); code that builds a simulation for a backend
// makes that backend's space the default while it runs (UseMemorySpace), so every buffer of the
// simulation, and every buffer a kernel is given, lives where the backend's kernels can reach it.
#pragma once

#include <cstddef>
#include <new>

namespace firn::backend {

struct MemorySpace {
  const char* name;
  void* (*allocate)(std::size_t bytes);            // throws on failure
  void (*deallocate)(void* p, std::size_t bytes);  // never throws
};

namespace memory_detail {
constexpr std::align_val_t kHostAlignment{64};
inline void* host_allocate(std::size_t bytes) { return ::operator new(bytes, kHostAlignment); }
inline void host_deallocate(void* p, std::size_t) { ::operator delete(p, kHostAlignment); }
}  // namespace memory_detail

inline constexpr MemorySpace kHostMemory{"host", memory_detail::host_allocate, memory_detail::host_deallocate};

namespace memory_detail {
inline const MemorySpace* default_space = &kHostMemory;
}  // namespace memory_detail

// The space new containers allocate in: host memory unless a UseMemorySpace is alive.
inline const MemorySpace& default_memory_space() { return *memory_detail::default_space; }

// Makes `space` the default for the scope's lifetime (scopes nest). The default is one per process:
// open scopes on the thread that builds simulations, not inside parallel regions.
class UseMemorySpace {
 public:
  explicit UseMemorySpace(const MemorySpace& space) : previous_(memory_detail::default_space) {
    memory_detail::default_space = &space;
  }
  ~UseMemorySpace() { memory_detail::default_space = previous_; }
  UseMemorySpace(const UseMemorySpace&) = delete;
  UseMemorySpace& operator=(const UseMemorySpace&) = delete;

 private:
  const MemorySpace* previous_;
};

}  // namespace firn::backend

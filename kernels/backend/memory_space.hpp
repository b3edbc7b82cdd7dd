// Where a backend's buffers live (issue 14, item 3): a MemorySpace allocates and frees raw bytes.
// The CPU backends use host memory (64-byte aligned: a cache line, and a full AVX-512 register);
// the CUDA backend uses memory the device reads and writes (kernels/backend/cuda.hpp). Each
// backend names its space (Backend::memory()). Containers take the default space when they are
// constructed and keep it (engine/aligned_vector.hpp); code that builds a simulation for a backend
// makes that backend's space the default while it runs (UseMemorySpace), so every buffer of the
// simulation, and every buffer a kernel is given, lives where the backend's kernels can reach it.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace firn::backend {

struct MemorySpace {
  const char* name;
  void* (*allocate)(std::size_t bytes);            // throws on failure
  void (*deallocate)(void* p, std::size_t bytes);  // never throws
};

namespace memory_detail {
constexpr std::align_val_t kHostAlignment{64};

// Buffers of at least kHugeFrom bytes (a particle column from 262,144 floats on, a grid's channels)
// lie in 2 MiB pages that Linux is asked to back with transparent huge pages (madvise
// MADV_HUGEPAGE; the kernel's "madvise" mode, Debian's default, gives them to no one else). A step
// reads some 25 columns at every particle: with 4 KiB pages their translations outgrow the TLB, and
// a particle out of block order costs a page walk per column. Huge pages made the snowball pair's
// P2G and G2P 5-10% faster (issue 15, docs/performance.md). Such a buffer starts kStagger bytes
// times a count into its first page, the count going round kStaggers values from one buffer to the
// next: columns that all began on a page boundary would put a particle's values of every column
// in the same set of each cache, and the 24 lines G2P writes per particle overflowed the ways of
// L1 and L2 (G2P 2.3 times slower). Rounded up to whole pages, a buffer of 1 MiB takes twice its
// bytes, one of 20 MiB at most a tenth more.
constexpr std::size_t kHugePage = std::size_t(2) << 20, kHugeFrom = std::size_t(1) << 20;
constexpr std::size_t kStagger = 4096 + 64, kStaggers = 32;  // a line and a 4 KiB page apart
// host_deallocate finds a buffer's offset in its page as its address modulo the page.
static_assert(kStagger % 64 == 0 && kStagger * (kStaggers - 1) < kHugePage, "staggers within a page, by lines");

inline std::size_t huge_bytes(std::size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }

// Whether the kernel gives transparent huge pages to a region that asks (its mode is "always" or
// "madvise", not "never"): where it does not, rounding buffers up to 2 MiB would cost memory for
// nothing. Read once per process, so that a buffer is freed the way it was allocated.
inline bool transparent_huge_pages() {
  static const bool available = [] {
    std::FILE* f = std::fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
    if (f == nullptr) return false;
    char mode[128] = {};
    const std::size_t n = std::fread(mode, 1, sizeof mode - 1, f);
    std::fclose(f);
    return n > 0 && std::strstr(mode, "[never]") == nullptr;
  }();
  return available;
}

inline void* host_allocate(std::size_t bytes) {
#if defined(__linux__)
  if (bytes >= kHugeFrom && transparent_huge_pages()) {
    if (bytes > SIZE_MAX - kStagger * kStaggers - 2 * kHugePage) throw std::bad_alloc();  // the sums below
    static std::atomic<std::size_t> buffers{0};
    const std::size_t offset = kStagger * (buffers++ % kStaggers), size = huge_bytes(offset + bytes);
    // Mapped with a page to spare, then trimmed to the aligned pages (mmap aligns to 4 KiB only).
    void* base = mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (base == MAP_FAILED) throw std::bad_alloc();
    char* const b = static_cast<char*>(base);
    char* const p = b + (kHugePage - reinterpret_cast<std::uintptr_t>(b) % kHugePage) % kHugePage;
    if (p != b) munmap(b, std::size_t(p - b));
    munmap(p + size, kHugePage - std::size_t(p - b));
    madvise(p, size, MADV_HUGEPAGE);  // a hint: where the kernel refuses, 4 KiB pages serve
    return p + offset;
  }
#endif
  return ::operator new(bytes, kHostAlignment);
}

inline void host_deallocate(void* p, std::size_t bytes) {
#if defined(__linux__)
  if (bytes >= kHugeFrom && transparent_huge_pages()) {
    const std::size_t offset = reinterpret_cast<std::uintptr_t>(p) % kHugePage;
    munmap(static_cast<char*>(p) - offset, huge_bytes(offset + bytes));
    return;
  }
#endif
  ::operator delete(p, kHostAlignment);
}
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

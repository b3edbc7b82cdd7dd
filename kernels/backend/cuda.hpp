// The CUDA backend: the API of backend::Serial and backend::OpenMP (parallel_for, parallel_reduce,
// the block scatter and the block gather) launching the same FIRN_HD functors as CUDA kernels.
// Compiled by nvcc only (FIRN_CUDA builds, .cu translation units).
//
// Determinism: every result is the same bits on every run.
//   parallel_reduce: items are split into a number of thread blocks that depends only on n, each
//     thread folds a fixed strided subset, and the partials are combined in a fixed binary tree
//     (shared memory), then the blocks' partials by the same tree in a second launch.
//   scatter_blocks (P2G): one thread block per grid block the scatter keeps (scatter_skip.hpp; a
//     block left out returns at once), colour after colour as on the CPU (same
//     colour blocks never share a node, so the flush into the grid needs no atomics). The block's
//     scratch lives in shared memory. The block's particles go in rounds of as many as fit in
//     shared memory (at most 64): each is staged (its contributions in shared memory) by one
//     thread; bit masks (mark_bases) say which staged particles have their stencil base at each
//     position of the block along each axis, so each thread, owning some scratch nodes, finds the
//     particles that touch a node (touching_node) and adds their contributions in particle order.
//     So every node receives the same additions in the same order as the CPU scatter (the scratch
//     then the flush), with no atomics. The price, measured against one float atomicAdd per
//     contribution whose order, and so whose rounding, changes from run to run
//     (ScatterOrder::atomic, kept for that measurement), is in docs/cuda.md.
//   gather_blocks (G2P): one thread block per grid block loads the window into shared memory,
//     threads take the particles, and the per-block results are reduced by the fixed tree.
// Memory: the backend's buffers are CUDA managed memory (cudaMallocManaged), which both the device
// and the host address: pages move to the side that touches them. Every launch synchronises before
// it returns, so the host may read what a kernel wrote (the list lengths of the block compactions,
// the collider reactions); the block bookkeeping of a step runs as launches (issue 14, item 3).
// With a LaunchProfile, each launch's device time is measured with CUDA events.
#pragma once

#if !defined(__CUDACC__)
#error "kernels/backend/cuda.hpp is compiled by nvcc only"
#endif

#include <cub/device/device_radix_sort.cuh>
#include <cuda_runtime.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "kernels/backend/block_colouring.hpp"
#include "kernels/backend/launch_profile.hpp"
#include "kernels/backend/memory_space.hpp"
#include "kernels/backend/scatter_skip.hpp"
#include "kernels/backend/schedule.hpp"
#include "kernels/block_window.hpp"
#include "kernels/hd.hpp"

namespace firn::backend {
namespace cuda_detail {

inline void check(cudaError_t e, const char* what) {
  if (e != cudaSuccess) throw std::runtime_error(std::string("CUDA ") + what + ": " + cudaGetErrorString(e));
}

constexpr int kThreads = 256;          // per thread block of parallel_for, reductions and the gather
constexpr int kMaxReduceBlocks = 1024;  // the second reduction pass folds at most this many partials
constexpr std::size_t kSharedBytes = 40 * 1024;  // below the 48 KB a block may use without opting in

template <class F>
__global__ void for_each(std::size_t n, F f) {
  const std::size_t i = std::size_t(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < n) f(i);
}

// Combines the blockDim.x (a power of two) values of `shared` into shared[0] by a fixed tree.
template <class R, class Combine>
__device__ void tree_reduce(R* shared, const Combine& combine) {
  __syncthreads();
  for (unsigned w = blockDim.x / 2; w > 0; w >>= 1) {
    if (threadIdx.x < w) combine(shared[threadIdx.x], shared[threadIdx.x + w]);
    __syncthreads();
  }
}

// Thread block k folds items [k per_block, (k + 1) per_block) into partial[k].
template <class R, class F, class Combine>
__global__ void reduce_items(std::size_t n, std::size_t per_block, R init, F f, Combine combine, R* partial) {
  extern __shared__ __align__(16) unsigned char shared_bytes[];
  R* shared = reinterpret_cast<R*>(shared_bytes);
  R acc = init;
  const std::size_t begin = std::size_t(blockIdx.x) * per_block, end = begin + per_block < n ? begin + per_block : n;
  for (std::size_t i = begin + threadIdx.x; i < end; i += blockDim.x) f(i, acc);
  shared[threadIdx.x] = acc;
  tree_reduce(shared, combine);
  if (threadIdx.x == 0) partial[blockIdx.x] = shared[0];
}

// The term of the second pass: folds the first pass's partials.
template <class R, class Combine>
struct FoldPartials {
  const R* partial;
  Combine combine;
  FIRN_HD void operator()(std::size_t i, R& acc) const { combine(acc, partial[i]); }
};

// The scatter target of one particle in a round: its contributions in stencil order.
template <class T, int kSupport, int kChannels>
struct StagedParticle {
  int base[3];
  int count;
  T values[kSupport * kSupport * kSupport * kChannels];

  template <int kRow>
  FIRN_HD void add_row(int i, int j, int k, const T* v) {
    if (count == 0) {
      base[0] = i;
      base[1] = j;
      base[2] = k;
    }
    for (int c = 0; c < kRow * kChannels; ++c) values[count * kChannels + c] = v[c];
    count += kRow;
  }
  // The contribution to global node g, or null when g is outside the stencil.
  FIRN_HD const T* at(const int g[3]) const {
    int o[3];
    for (int d = 0; d < 3; ++d) {
      o[d] = g[d] - base[d];
      if (o[d] < 0 || o[d] >= kSupport) return nullptr;
    }
    return values + ((o[0] * kSupport + o[1]) * kSupport + o[2]) * kChannels;
  }
};

template <class S>
using StagedOf = StagedParticle<typename S::Value, S::kSupport, S::kChannels>;

// Particles staged per round: as many as fit beside the scratch, at most 64.
template <class S>
constexpr int scatter_round() {
  const std::size_t room = (kSharedBytes - sizeof(typename S::Scratch)) / sizeof(StagedOf<S>);
  return room >= 64 ? 64 : room >= 1 ? int(room) : 1;
}

// The particles of a scatter round as bits (particle q of the round is bit q).
using RoundMask = unsigned long long;

// Run by the first kWords warps after a round is staged: bit q of masks[d][v] is set when staged
// particle q has its stencil base node at v along axis d, counted from the block's first node
// (binning puts it inside the block: 0 <= v < kBlockSize).
template <class Staged, int kWords>
__device__ void mark_bases(const Staged* staged, int count, const int origin[3],
                           std::uint32_t (&masks)[3][kBlockSize][kWords]) {
  const int q = threadIdx.x;
  for (int d = 0; d < 3; ++d) {
    const int base = q < count ? staged[q].base[d] - origin[d] : -1;
    for (int v = 0; v < kBlockSize; ++v) {
      const std::uint32_t bits = __ballot_sync(0xffffffffu, base == v);
      if (q % 32 == 0) masks[d][v][q / 32] = bits;
    }
  }
}

// The staged particles whose stencil covers global node g: along each axis, the base lies in
// [g - kSupport + 1, g].
template <int kSupport, int kWords>
__device__ RoundMask touching_node(const std::uint32_t (&masks)[3][kBlockSize][kWords], const int origin[3],
                                   const int g[3]) {
  RoundMask touching = ~RoundMask(0);
  for (int d = 0; d < 3; ++d) {
    const int a = g[d] - origin[d];
    RoundMask axis = 0;
    for (int v = a - kSupport + 1 > 0 ? a - kSupport + 1 : 0; v <= a && v < kBlockSize; ++v)
      for (int w = 0; w < kWords; ++w) axis |= RoundMask(masks[d][v][w]) << (32 * w);
    touching &= axis;
  }
  return touching;
}

// Opens grid block b's scratch for a scatter launch: its origin set and its values zeroed.
template <class S>
__device__ void open_scratch(const S& scatter, std::uint32_t b, typename S::Scratch& scratch) {
  using Scratch = typename S::Scratch;
  if (threadIdx.x == 0) {
    int block[3];
    scatter.grid.box.coords(b, block);
    scratch.set_origin(block);
  }
  for (int i = threadIdx.x; i < Scratch::kNodes * S::kChannels; i += blockDim.x) scratch.values[i] = 0;
  __syncthreads();
}

// Adds the scratch into the grid (after a __syncthreads).
template <class S>
__device__ void flush_scratch(const S& scatter, const typename S::Scratch& scratch) {
  for (int n = threadIdx.x; n < S::Scratch::kNodes; n += blockDim.x) scratch.flush_node(scatter.grid, n);
}

// One thread block per grid block of one colour, in the fixed order (see the top of this file).
template <class S>
__global__ void scatter_colour(const std::uint32_t* blocks, S scatter) {
  using Scratch = typename S::Scratch;
  using T = typename S::Value;
  constexpr int kRound = scatter_round<S>();
  constexpr int kWords = (kRound + 31) / 32;
  __shared__ Scratch scratch;
  __shared__ StagedOf<S> staged[kRound];
  __shared__ std::uint32_t base_masks[3][kBlockSize][kWords];
  const std::uint32_t b = blocks[blockIdx.x];
  if (!scatter_keeps(scatter, b)) return;  // the whole thread block: before any barrier
  open_scratch(scatter, b, scratch);
  for (std::size_t m = 0; m < scatter.bins.material_count; ++m) {
    const std::uint32_t end = scatter.bins.bucket_end(m, b);
    for (std::uint32_t round = scatter.bins.bucket_begin(m, b); round < end; round += kRound) {
      const int count = end - round < std::uint32_t(kRound) ? int(end - round) : kRound;
      for (int q = threadIdx.x; q < count; q += blockDim.x) {
        staged[q].count = 0;
        scatter.particle(round + q, staged[q]);
      }
      __syncthreads();
      if (threadIdx.x < 32 * kWords) mark_bases(staged, count, scratch.origin, base_masks);
      __syncthreads();
      for (int n = threadIdx.x; n < Scratch::kNodes; n += blockDim.x) {
        int g[3];
        window_node<S::kSpan>(scratch.origin, n, g);
        auto* node = scratch.values + n * S::kChannels;
        for (RoundMask touching = touching_node<S::kSupport>(base_masks, scratch.origin, g); touching;
             touching &= touching - 1) {
          const T* v = staged[__ffsll(static_cast<long long>(touching)) - 1].at(g);
          for (int c = 0; c < S::kChannels; ++c) node[c] += v[c];
        }
      }
      __syncthreads();
    }
  }
  flush_scratch(scatter, scratch);
}

// The scatter target of ScatterOrder::atomic: each contribution added to the shared scratch by a
// float atomicAdd.
template <class Scratch, int kChannels>
struct AtomicScratchTarget {
  Scratch* scratch;
  template <int kRow, class T>
  __device__ void add_row(int i, int j, int k, const T* v) const {
    T* node = scratch->node(i, j, k);
    for (int c = 0; c < kRow * kChannels; ++c) atomicAdd(node + c, v[c]);
  }
};

// One thread block per grid block of one colour, each thread adding its particles' contributions
// by float atomics (ScatterOrder::atomic): no staging, an order that changes from run to run.
template <class S>
__global__ void scatter_colour_atomic(const std::uint32_t* blocks, S scatter) {
  using Scratch = typename S::Scratch;
  __shared__ Scratch scratch;
  const std::uint32_t b = blocks[blockIdx.x];
  if (!scatter_keeps(scatter, b)) return;  // the whole thread block: before any barrier
  open_scratch(scatter, b, scratch);
  const AtomicScratchTarget<Scratch, S::kChannels> target{&scratch};
  for (std::size_t m = 0; m < scatter.bins.material_count; ++m)
    for (std::uint32_t s = scatter.bins.bucket_begin(m, b) + threadIdx.x, e = scatter.bins.bucket_end(m, b); s < e;
         s += blockDim.x)
      scatter.particle(s, target);
  __syncthreads();
  flush_scratch(scatter, scratch);
}

// One thread block per grid block: the window in shared memory, the particles over the threads,
// then the block's results by the fixed tree into out[blockIdx.x].
template <class G, class Combine>
__global__ void gather_block(const std::uint32_t* blocks, G gather, Combine combine, typename G::Result* out) {
  using Window = typename G::Window;
  using R = typename G::Result;
  __shared__ Window window;
  __shared__ __align__(16) unsigned char shared_bytes[kThreads * sizeof(R)];
  R* shared = reinterpret_cast<R*>(shared_bytes);
  const std::uint32_t b = blocks[blockIdx.x];
  if (threadIdx.x == 0) {
    int block[3];
    gather.grid.box.coords(b, block);
    window.set_origin(block);
  }
  __syncthreads();
  for (int n = threadIdx.x; n < Window::kNodes; n += blockDim.x) window.load_node(gather.grid, G::kFirstChannel, n);
  __syncthreads();
  R acc{};
  for (std::size_t m = 0; m < gather.bins.material_count; ++m)
    for (std::uint32_t s = gather.bins.bucket_begin(m, b) + threadIdx.x, e = gather.bins.bucket_end(m, b); s < e;
         s += blockDim.x)
      gather.particle(s, window, acc);
  shared[threadIdx.x] = acc;
  tree_reduce(shared, combine);
  if (threadIdx.x == 0) out[blockIdx.x] = shared[0];
}

// Scratch for one launch, from the stream-ordered pool (cheap after the first steps), freed with
// free_buffer in stream order.
template <class T>
T* device_buffer(std::size_t n) {
  void* p = nullptr;
  check(cudaMallocAsync(&p, n * sizeof(T), 0), "cudaMallocAsync");
  return static_cast<T*>(p);
}
inline void free_buffer(void* p) { check(cudaFreeAsync(p, 0), "cudaFreeAsync"); }

static __global__ void iota(std::uint32_t n, std::uint32_t* out) {
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < n) out[i] = i;
}

// begin[k] = the first position of key k in the sorted keys (lower bound), for k in [0, K].
static __global__ void bucket_bounds(const std::uint32_t* sorted, std::uint32_t n, std::uint32_t K, std::uint32_t* begin) {
  const std::uint32_t k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k > K) return;
  std::uint32_t lo = 0, hi = n;
  while (lo < hi) {
    const std::uint32_t mid = lo + (hi - lo) / 2;
    if (sorted[mid] < k) lo = mid + 1;
    else hi = mid;
  }
  begin[k] = lo;
}

inline void* managed_allocate(std::size_t bytes) {
  void* p = nullptr;
  check(cudaMallocManaged(&p, bytes), "cudaMallocManaged");
  return p;
}
// Errors are dropped: a buffer freed after the runtime has shut down (a static) has nothing to free.
inline void managed_deallocate(void* p, std::size_t) { cudaFree(p); }

inline unsigned grid_size(std::size_t n, int threads) { return unsigned((n + std::size_t(threads) - 1) / std::size_t(threads)); }

}  // namespace cuda_detail

// The order in which the P2G block scatter adds contributions (see the top of this file): `fixed`,
// the deterministic default, or `atomic` (float atomicAdd into the shared scratch, an order that
// changes from run to run), kept to measure what determinism costs (kernel/p2g/cuda_atomic in
// bench/step_kernels.hpp, docs/cuda.md).
enum class ScatterOrder { fixed, atomic };

struct Cuda {
  static constexpr const char* kName = "cuda";
  static constexpr int kVectorBytes = 0;  // lanes per batch: kernels/lanes.hpp
  LaunchProfile* profile = nullptr;
  ScatterOrder scatter_order = ScatterOrder::fixed;
  // Threads per block of the fixed-order scatter, a multiple of 32 and at least 64: a round's
  // particles are staged and their masks made by the first threads, and its nodes are summed by
  // all of them.
  int scatter_block_threads = cuda_detail::kThreads;

  int threads() const { return 1; }
  static const MemorySpace& memory() {
    static constexpr MemorySpace kManaged{"cuda_managed", cuda_detail::managed_allocate, cuda_detail::managed_deallocate};
    return kManaged;
  }

  template <class F>
  void parallel_for(const char* name, std::size_t n, const F& f, Schedule = Schedule::uniform) const {
    launch(name, [&] {
      if (n) cuda_detail::for_each<<<cuda_detail::grid_size(n, cuda_detail::kThreads), cuda_detail::kThreads>>>(n, f);
    });
  }

  // f(i, acc) accumulates item i into acc; combine(acc, partial) merges; init is combine's identity.
  // The partition depends on n only (see the top of this file): the CPU backends' grain is unused.
  template <class R, class F, class Combine>
  R parallel_reduce(const char* name, std::size_t n, R init, const F& f, const Combine& combine,
                    std::size_t /*grain*/ = 0) const {
    R result = init;
    launch(name, [&] { result = reduce(n, init, f, combine); });
    return result;
  }

  // The binning's stable sort (engine/particle_binning.hpp) on the device: order = the stable
  // permutation sorting keys[0, n) (each below K), begin[k] = the first sorted position of key k
  // (K + 1 entries). CUB's radix sort is stable and its result unique, so it is the CPU's counting
  // sort's result, the same on every run.
  void sort_into_buckets(const std::uint32_t* keys, std::size_t n, std::size_t K, std::uint32_t* order,
                         std::uint32_t* begin) const {
    launch("bin.sort", [&] {
      using cuda_detail::kThreads;
      int bits = 1;
      while (bits < 32 && (std::size_t(1) << bits) < K) ++bits;
      std::uint32_t* sorted = cuda_detail::device_buffer<std::uint32_t>(2 * n + 1);
      std::uint32_t* index = sorted + n;
      if (n) cuda_detail::iota<<<cuda_detail::grid_size(n, kThreads), kThreads>>>(std::uint32_t(n), index);
      std::size_t temp_bytes = 0;
      cuda_detail::check(cub::DeviceRadixSort::SortPairs(nullptr, temp_bytes, keys, sorted, index, order, n, 0, bits),
                         "radix sort");
      void* temp = cuda_detail::device_buffer<unsigned char>(temp_bytes + 1);
      cuda_detail::check(cub::DeviceRadixSort::SortPairs(temp, temp_bytes, keys, sorted, index, order, n, 0, bits),
                         "radix sort");
      cuda_detail::bucket_bounds<<<cuda_detail::grid_size(K + 1, kThreads), kThreads>>>(sorted, std::uint32_t(n),
                                                                                          std::uint32_t(K), begin);
      cuda_detail::free_buffer(temp);
      cuda_detail::free_buffer(sorted);
    });
  }

  // The P2G scatter strategy over a kernels/step/p2g_scatter.hpp functor (see the top of this file).
  template <class S>
  void scatter_blocks(const char* name, const BlockColouring& colouring, const S& scatter) const {
    launch(name, [&] {
      for (int c = 0; c < BlockColouring::kColours; ++c) {
        const std::size_t count = colouring.begin[c + 1] - colouring.begin[c];
        const std::uint32_t* blocks = colouring.blocks + colouring.begin[c];
        if (count == 0) continue;
        if (scatter_order == ScatterOrder::atomic)
          cuda_detail::scatter_colour_atomic<S><<<unsigned(count), cuda_detail::kThreads>>>(blocks, scatter);
        else
          cuda_detail::scatter_colour<S><<<unsigned(count), unsigned(scatter_block_threads)>>>(blocks, scatter);
      }
    });
  }

  // The G2P gather strategy over a kernels/step/g2p_gather.hpp functor: its per-block results
  // combined into G::Result{} (combine's identity).
  template <class G, class Combine>
  typename G::Result gather_blocks(const char* name, const std::uint32_t* blocks, std::size_t count, const G& gather,
                                   const Combine& combine) const {
    using R = typename G::Result;
    R result{};
    launch(name, [&] {
      if (count == 0) return;
      R* partial = cuda_detail::device_buffer<R>(count);
      cuda_detail::gather_block<<<unsigned(count), cuda_detail::kThreads>>>(blocks, gather, combine, partial);
      cuda_detail::check(cudaGetLastError(), name);
      result = reduce(count, R{}, cuda_detail::FoldPartials<R, Combine>{partial, combine}, combine);
      cuda_detail::free_buffer(partial);
    });
    return result;
  }

 private:
  // Runs `launches` (kernel launches on the default stream), checks them, waits for them and adds
  // their device time to the profile.
  template <class Launches>
  void launch(const char* name, const Launches& launches) const {
    cudaEvent_t start = nullptr, stop = nullptr;
    if (profile) {
      cuda_detail::check(cudaEventCreate(&start), name);
      cuda_detail::check(cudaEventCreate(&stop), name);
      cuda_detail::check(cudaEventRecord(start), name);
    }
    launches();
    cuda_detail::check(cudaGetLastError(), name);
    if (profile) {
      cuda_detail::check(cudaEventRecord(stop), name);
      cuda_detail::check(cudaEventSynchronize(stop), name);
      float ms = 0;
      cuda_detail::check(cudaEventElapsedTime(&ms, start, stop), name);
      profile->add(name, 1e-3 * double(ms));
      cudaEventDestroy(start);
      cudaEventDestroy(stop);
    }
    cuda_detail::check(cudaDeviceSynchronize(), name);
  }

  // The two-pass fixed-tree reduction (see the top of this file).
  template <class R, class F, class Combine>
  static R reduce(std::size_t n, R init, const F& f, const Combine& combine) {
    using cuda_detail::kThreads;
    if (n == 0) return init;
    const std::size_t blocks = std::min<std::size_t>(cuda_detail::kMaxReduceBlocks, cuda_detail::grid_size(n, kThreads));
    const std::size_t per_block = (n + blocks - 1) / blocks;
    R* partial = cuda_detail::device_buffer<R>(blocks + 1);
    const std::size_t shared = kThreads * sizeof(R);
    cuda_detail::reduce_items<<<unsigned(blocks), kThreads, shared>>>(n, per_block, init, f, combine, partial);
    cuda_detail::reduce_items<<<1, kThreads, shared>>>(blocks, blocks, init,
                                                       cuda_detail::FoldPartials<R, Combine>{partial, combine}, combine,
                                                       partial + blocks);
    R result = init;
    cuda_detail::check(cudaMemcpy(&result, partial + blocks, sizeof(R), cudaMemcpyDeviceToHost), "reduce");
    cuda_detail::free_buffer(partial);
    return result;
  }
};

}  // namespace firn::backend

// The one annotation macro of the kernel layer (DESIGN.md section 2, rule 1).
// Empty on the CPU; __host__ __device__ under a CUDA compiler, so the same kernel source
// can be launched by a CUDA backend. Kernel bodies contain no #ifdef.
#pragma once

#if defined(__CUDACC__)
#define FIRN_HD __host__ __device__ inline
#else
#define FIRN_HD inline
#endif

// A lambda handed to a backend launch: [=] FIRN_HD_LAMBDA (std::size_t i) { ... }. Device-callable
// under nvcc (--extended-lambda); the step's stages are named functors instead (kernels/step/).
#if defined(__CUDACC__)
#define FIRN_HD_LAMBDA __host__ __device__
#else
#define FIRN_HD_LAMBDA
#endif

// Marks a loop over a kernel's short vector of lanes (a stencil row's nodes x channels, a node's
// channels, the stencil's axes, a batch's particles): the CPU compiler vectorises it as one loop
// rather than unrolling it into scalar code first (OpenMP's `simd`, which needs no threads);
// nothing in device code, where a thread is one lane.
#if defined(__CUDA_ARCH__) || !defined(_OPENMP)
#define FIRN_LANES
#else
#define FIRN_LANES _Pragma("omp simd")
#endif

// On a kernel that works on a batch of lanes (kernels/lanes.hpp): inline everything it calls, so
// that the lanes stay in vector registers across the small functions of Mat3 and the models
// rather than passing through memory at every call. Nothing in device code.
#if defined(__CUDA_ARCH__) || !defined(__GNUC__)
#define FIRN_FLATTEN
#else
#define FIRN_FLATTEN __attribute__((flatten))
#endif

// On a function whose body is one loop over lanes, a lane's whole computation in scalar code
// (FIRN_LANES): kept out of a FIRN_FLATTEN kernel. Inlined into the large flattened body, GCC 12
// leaves such a loop scalar ("no vectype for stmt" on its first load); called, it vectorises
// (docs/performance.md, "The J2 return's stretch in one loop"). Device code inlines as it sees fit.
#if defined(__CUDA_ARCH__) || !defined(__GNUC__)
#define FIRN_NOINLINE
#else
#define FIRN_NOINLINE __attribute__((noinline))
#endif

// On a short loop of fixed count: inside a loop over lanes (a polynomial's terms), unrolled so that
// the lanes loop around it is innermost and vectorises; around lane loops (G2P's loop over a
// stencil axis), unrolled so that its per-turn values stay in registers.
#if defined(__CUDACC__)
#define FIRN_UNROLL _Pragma("unroll")
#elif defined(__GNUC__)
#define FIRN_UNROLL _Pragma("GCC unroll 16")
#else
#define FIRN_UNROLL
#endif

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

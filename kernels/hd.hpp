// The one annotation macro of the kernel layer (DESIGN.md section 2, rule 1).
// Empty on the CPU; __host__ __device__ under a CUDA compiler, so the same kernel source
// can be launched by a CUDA backend. Kernel bodies contain no #ifdef.
#pragma once

#if defined(__CUDACC__)
#define FIRN_HD __host__ __device__ inline
#else
#define FIRN_HD inline
#endif

// A short vector of W values of T, one per particle, for kernels that run the same arithmetic on W
// particles at once (issue 15: vectorise across particles, lanes as a compile-time width). Every
// operation is a loop over the lanes that the CPU compiler turns into vector instructions
// (FIRN_LANES), so AVX-512, AVX2 and SSE builds come from this one source; a backend that runs one
// particle per thread (CUDA) uses W = 1. Lanes are independent: what a lane computes never
// depends on the other lanes, so a particle's result does not depend on how particles are batched.
// Branches become masks (LaneMask) and select().
#pragma once

#include <cmath>

#include "kernels/hd.hpp"

namespace firn {

// The host's vector register in bytes, from the compiler's target flags.
#if defined(__AVX512F__)
constexpr int kHostVectorBytes = 64;
#elif defined(__AVX__)
constexpr int kHostVectorBytes = 32;
#else
constexpr int kHostVectorBytes = 16;
#endif

// Lanes of T in one vector of a backend whose vectors are `bytes` wide (0: one particle per thread).
template <class T>
constexpr int lane_width(int bytes) {
  return bytes >= int(sizeof(T)) ? bytes / int(sizeof(T)) : 1;
}

// Lanes of T per batch: two of the backend's vectors. A return mapping is one long chain of
// dependent operations (Newton steps through the power law, divisions), so one vector per batch
// leaves the core waiting on each result; two give it two independent chains to interleave
// (firn_bench_kernels constitutive/hyperelastic_plastic/lanes against /one_vector: 1.34 times the
// rate with AVX-512; docs/performance.md). Four were no faster than two.
template <class T>
constexpr int batch_width(int bytes) {
  return bytes >= int(sizeof(T)) ? 2 * lane_width<T>(bytes) : 1;
}

// A lane's condition as 0 or 1 in an int: a bool array does not vectorise beside float lanes (GCC 12).
template <int W>
struct LaneMask {
  int m[W];
  FIRN_HD static LaneMask all() {
    LaneMask r;
    for (int l = 0; l < W; ++l) r.m[l] = 1;
    return r;
  }
  FIRN_HD static LaneMask none() {
    LaneMask r;
    for (int l = 0; l < W; ++l) r.m[l] = 0;
    return r;
  }
};

template <class T, int W>
struct Lanes {
  T v[W];
  Lanes() = default;
  FIRN_HD explicit Lanes(T s) {
    FIRN_LANES
    for (int l = 0; l < W; ++l) v[l] = s;
  }
  FIRN_HD Lanes& operator+=(const Lanes& b) {
    FIRN_LANES
    for (int l = 0; l < W; ++l) v[l] += b.v[l];
    return *this;
  }
  FIRN_HD Lanes& operator-=(const Lanes& b) {
    FIRN_LANES
    for (int l = 0; l < W; ++l) v[l] -= b.v[l];
    return *this;
  }
};

#define FIRN_LANE_BINARY(op)                                                \
  template <class T, int W>                                                 \
  FIRN_HD Lanes<T, W> operator op(const Lanes<T, W>& a, const Lanes<T, W>& b) { \
    Lanes<T, W> r;                                                          \
    FIRN_LANES                                                              \
    for (int l = 0; l < W; ++l) r.v[l] = a.v[l] op b.v[l];                  \
    return r;                                                               \
  }
FIRN_LANE_BINARY(+)
FIRN_LANE_BINARY(-)
FIRN_LANE_BINARY(*)
FIRN_LANE_BINARY(/)
#undef FIRN_LANE_BINARY

#define FIRN_LANE_COMPARE(op)                                                    \
  template <class T, int W>                                                      \
  FIRN_HD LaneMask<W> operator op(const Lanes<T, W>& a, const Lanes<T, W>& b) {  \
    LaneMask<W> r;                                                               \
    FIRN_LANES                                                                   \
    for (int l = 0; l < W; ++l) r.m[l] = a.v[l] op b.v[l];                       \
    return r;                                                                    \
  }
FIRN_LANE_COMPARE(<)
FIRN_LANE_COMPARE(<=)
FIRN_LANE_COMPARE(>)
#undef FIRN_LANE_COMPARE

template <class T, int W>
FIRN_HD Lanes<T, W> operator-(const Lanes<T, W>& a) {
  Lanes<T, W> r;
  FIRN_LANES
  for (int l = 0; l < W; ++l) r.v[l] = -a.v[l];
  return r;
}

template <int W>
FIRN_HD LaneMask<W> operator&&(const LaneMask<W>& a, const LaneMask<W>& b) {
  LaneMask<W> r;
  FIRN_LANES
  for (int l = 0; l < W; ++l) r.m[l] = a.m[l] & b.m[l];
  return r;
}
template <int W>
FIRN_HD LaneMask<W> operator||(const LaneMask<W>& a, const LaneMask<W>& b) {
  LaneMask<W> r;
  FIRN_LANES
  for (int l = 0; l < W; ++l) r.m[l] = a.m[l] | b.m[l];
  return r;
}
template <int W>
FIRN_HD LaneMask<W> operator!(const LaneMask<W>& a) {
  LaneMask<W> r;
  FIRN_LANES
  for (int l = 0; l < W; ++l) r.m[l] = a.m[l] ^ 1;
  return r;
}
template <int W>
FIRN_HD bool any(const LaneMask<W>& a) {
  int r = 0;
  for (int l = 0; l < W; ++l) r = r | a.m[l];
  return r != 0;
}

// The largest lane, by halving: without NaNs or -0 the result does not depend on the order of the
// comparisons, so it is the maximum a loop over the lanes finds, in log2(W) vector steps rather
// than a chain of W dependent ones.
template <class T, int W>
FIRN_HD T largest(Lanes<T, W> a) {
  static_assert((W & (W - 1)) == 0, "lanes in a power of two");
  for (int w = W / 2; w > 0; w /= 2) {
    FIRN_LANES
    for (int l = 0; l < w; ++l) a.v[l] = a.v[l] < a.v[l + w] ? a.v[l + w] : a.v[l];
  }
  return a.v[0];
}

// dst[l] = a.v[l] for l < count: one vector store where count is W (a loop to count alone became a
// call to memcpy per column; issue 15).
template <class T, int W>
FIRN_HD void store_lanes(T* dst, const Lanes<T, W>& a, int count) {
  if (count == W) {
    FIRN_LANES
    for (int l = 0; l < W; ++l) dst[l] = a.v[l];
  } else {
    for (int l = 0; l < count; ++l) dst[l] = a.v[l];
  }
}

// mask ? a : b, lane by lane.
template <class T, int W>
FIRN_HD Lanes<T, W> select(const LaneMask<W>& mask, const Lanes<T, W>& a, const Lanes<T, W>& b) {
  Lanes<T, W> r;
  FIRN_LANES
  for (int l = 0; l < W; ++l) r.v[l] = mask.m[l] ? a.v[l] : b.v[l];
  return r;
}

template <class T, int W>
FIRN_HD Lanes<T, W> abs(const Lanes<T, W>& a) {
  Lanes<T, W> r;
  FIRN_LANES
  for (int l = 0; l < W; ++l) r.v[l] = std::fabs(a.v[l]);
  return r;
}

// Finite (neither infinite nor NaN), lane by lane: x - x is 0 only for a finite x.
template <class T, int W>
FIRN_HD LaneMask<W> finite(const Lanes<T, W>& a) {
  LaneMask<W> r;
  FIRN_LANES
  for (int l = 0; l < W; ++l) r.m[l] = a.v[l] - a.v[l] == T(0);
  return r;
}

}  // namespace firn

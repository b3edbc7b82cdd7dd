// firn bench surface: the snow surface reconstruction (viz/surface) timed on a synthetic snow
// block, a jittered lattice at 8 particles per cell of dx = 0.01 m with rest positions; the mesh's
// topology is checked outside the timing.
#pragma once

#include <cstddef>

#include "viz/surface/reconstruct_surface.hpp"

namespace firn::bench {

struct SurfaceBenchmarkOptions {
  long particles = 100000;
  int threads = 0;  // 0: all cores
  int repeats = 5;
};

struct SurfaceBenchmarkResult {
  int threads = 0;
  std::size_t vertices = 0, triangles = 0, crystals = 0;
  bool closed_manifold = false;
  long euler_characteristic = 0;
  surface::SurfaceTimings stages;     // the median of each stage over the repeats
  double seconds = 0;                 // the median total without the crystals
  double seconds_with_crystals = 0;   // the median total
};

SurfaceBenchmarkResult benchmark_surface(const SurfaceBenchmarkOptions& o);

}  // namespace firn::bench

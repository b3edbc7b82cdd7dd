#include "studies/bench/surface_benchmark.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "engine/particle_storage.hpp"
#include "kernels/backend/openmp.hpp"
#include "viz/surface/mesh_topology.hpp"

namespace firn::bench {
namespace {

// A synthetic snow block: a jittered lattice at 8 particles per cell of dx (spacing dx/2, jitter
// +-dx/8), as wide as deep and as tall as the count needs, rest positions = positions.
void fill_snow_block(ParticleStorage<float>& storage, long count, double dx) {
  const double spacing = dx / 2;
  const long side = std::max(1L, std::lround(std::cbrt(double(count))));
  storage.enable(Attribute::x0);
  storage.resize(std::size_t(count));
  ParticleView<float> pv = storage.view();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  for (long p = 0; p < count; ++p) {
    const long lattice[3] = {p % side, p / (side * side), p / side % side};
    for (int d = 0; d < 3; ++d) pv.x[d][p] = pv.x0[d][p] = float((lattice[d] + 0.5 + jitter(random)) * spacing);
    pv.vol0[p] = float(spacing * spacing * spacing);
  }
}

}  // namespace

SurfaceBenchmarkResult benchmark_surface(const SurfaceBenchmarkOptions& o) {
  const backend::OpenMP omp(o.threads);
  surface::SurfaceParams params;
  params.simulation_dx = 0.01;
  ParticleStorage<float> storage;
  fill_snow_block(storage, o.particles, params.simulation_dx);
  std::vector<surface::SurfaceTimings> runs(std::size_t(o.repeats));
  surface::SurfaceMesh mesh;
  for (auto& run : runs) mesh = surface::reconstruct_surface(storage.view(), params, omp, &run);
  auto median = [&runs](auto seconds_of) {
    std::vector<double> values;
    for (const auto& run : runs) values.push_back(seconds_of(run));
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
  };
  using Timings = surface::SurfaceTimings;
  SurfaceBenchmarkResult r;
  r.threads = omp.threads();
  r.vertices = mesh.vertex_count();
  r.triangles = mesh.triangle_count();
  r.crystals = mesh.crystals.size();
  const surface::MeshTopology topology = surface::analyse_topology(mesh.triangles, mesh.vertex_count());
  r.closed_manifold = topology.closed_manifold();
  r.euler_characteristic = topology.euler_characteristic();
  r.stages.field = median([](const Timings& t) { return t.field; });
  r.stages.marching = median([](const Timings& t) { return t.marching; });
  r.stages.smoothing = median([](const Timings& t) { return t.smoothing; });
  r.stages.detail = median([](const Timings& t) { return t.detail; });
  r.stages.crystals = median([](const Timings& t) { return t.crystals; });
  r.seconds = median([](const Timings& t) { return t.total() - t.crystals; });
  r.seconds_with_crystals = median([](const Timings& t) { return t.total(); });
  return r;
}

}  // namespace firn::bench

// firn bench step [--problem NAME] [--steps N] [--threads N] [--backend serial|openmp|cuda]
//                 [--precision float|double] [--transfer apic|pic|flip] [--domain-scale S]
//                 [--enable ATTR]... [--idle-materials N]
// Times the step loop alone (setup excluded) and prints particles, steps,
// particle_steps_per_second and state_hash, plus backend, threads, seconds and memory. --domain-scale,
// --enable and --idle-materials add what the problem does not need (empty grid, attributes nobody
// reads, materials without particles) to measure what skipping them saves (docs/performance.md).
// firn bench surface [--particles N] [--threads N] [--repeats N]
// Times the snow surface reconstruction of a synthetic snow block; prints particles_per_second and
// checks that the mesh is a closed manifold (outside the timing).
#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <stdexcept>
#include <random>
#include <string>
#include <vector>

#include "apps/backend_option.hpp"
#include "apps/commands.hpp"
#include "engine/particle_storage.hpp"
#include "kernels/backend/openmp.hpp"
#include "studies/bench/step_benchmark.hpp"
#include "viz/surface/mesh_topology.hpp"
#include "viz/surface/reconstruct_surface.hpp"

namespace firn::app {
namespace {

int g_status = 0;

struct BenchSurfaceOptions {
  long particles = 100000;
  int threads = 0;  // 0: all cores
  int repeats = 5;
};

// A synthetic snow block: a jittered lattice at 8 particles per cell of dx = 0.01 m (spacing
// dx/2, jitter +-dx/8), as wide as deep and as tall as the count needs, rest positions = positions.
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

void bench_surface(const BenchSurfaceOptions& o) {
  const backend::OpenMP omp(o.threads);
  surface::SurfaceParams params;
  params.simulation_dx = 0.01;
  ParticleStorage<float> storage;
  fill_snow_block(storage, o.particles, params.simulation_dx);
  std::vector<surface::SurfaceTimings> runs(std::size_t(o.repeats));
  surface::SurfaceMesh mesh;
  for (auto& run : runs) mesh = surface::reconstruct_surface(storage.view(), params, omp, &run);
  // Medians of each stage and of the total without and with the crystals.
  auto median = [&runs](auto seconds_of) {
    std::vector<double> values;
    for (const auto& run : runs) values.push_back(seconds_of(run));
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
  };
  using Timings = surface::SurfaceTimings;
  const double surface_seconds = median([](const Timings& t) { return t.total() - t.crystals; });
  const double all_seconds = median([](const Timings& t) { return t.total(); });
  const surface::MeshTopology topology = surface::analyse_topology(mesh.triangles, mesh.vertex_count());
  std::printf("particles %ld\nthreads %d\nrepeats %d\nvertices %zu\ntriangles %zu\ncrystals %zu\n", o.particles,
              omp.threads(), o.repeats, mesh.vertex_count(), mesh.triangle_count(), mesh.crystals.size());
  std::printf("closed_manifold %d\neuler_characteristic %ld\n", int(topology.closed_manifold()),
              topology.euler_characteristic());
  std::printf("field_seconds %.4f\nmarching_seconds %.4f\nsmoothing_seconds %.4f\nnoise_normals_seconds %.4f\n"
              "crystals_seconds %.4f\n",
              median([](const Timings& t) { return t.field; }), median([](const Timings& t) { return t.marching; }),
              median([](const Timings& t) { return t.smoothing; }), median([](const Timings& t) { return t.detail; }),
              median([](const Timings& t) { return t.crystals; }));
  std::printf("seconds %.4f\nparticles_per_second %.0f\nparticles_per_second_with_crystals %.0f\n", surface_seconds,
              double(o.particles) / surface_seconds, double(o.particles) / all_seconds);
}

}  // namespace

int exit_status() { return g_status; }
void set_exit_status(int status) { g_status = status; }

void add_bench_command(CLI::App& app) {
  CLI::App* bench = app.add_subcommand("bench", "time the engine's kernels and step loop");
  bench->require_subcommand(1);
  auto opts = std::make_shared<bench::BenchStepOptions>();
  CLI::App* step = bench->add_subcommand("step", "time the step loop on a reference problem");
  step->add_option("--problem", opts->problem, "reference problem")->check(CLI::IsMember({"cube_drop"}))
      ->capture_default_str();
  step->add_option("--steps", opts->steps, "steps to time")->check(CLI::PositiveNumber)->capture_default_str();
  step->add_option("--threads", opts->threads, "OpenMP threads (default: all cores)")->check(CLI::PositiveNumber);
  step->add_option("--precision", opts->precision, "float or double")->check(CLI::IsMember({"float", "double"}))
      ->capture_default_str();
  step->add_option("--transfer", opts->transfer, "transfer scheme")->check(CLI::IsMember({"apic", "pic", "flip"}))
      ->capture_default_str();
  step->add_option("--enable", opts->enable, "allocate an on-demand attribute nothing reads (to measure the skip)")
      ->check(CLI::IsMember({"x0", "alpha", "Jp", "body_accel", "load"}));
  step->add_option("--idle-materials", opts->idle_materials, "add materials without particles (to measure the skip)")
      ->check(CLI::Range(0, 64))->capture_default_str();
  step->add_option("--domain-scale", opts->domain_scale,
                   "scale the domain box (same particles) to show that cost follows the particles")
      ->check(CLI::Range(1.0, 16.0))->capture_default_str();
  add_backend_option(step, opts->backend);
  step->callback([opts]() {
    const std::optional<BackendKind> backend = usable_backend(opts->backend);
    if (!backend) return;
    if (*backend == BackendKind::serial) return bench::bench_step_serial(*opts);
    if (*backend == BackendKind::cuda) return bench::bench_step_cuda(*opts);
    bench::bench_step_on(*opts, backend::OpenMP(opts->threads));
  });

  auto surface_opts = std::make_shared<BenchSurfaceOptions>();
  CLI::App* surface = bench->add_subcommand("surface", "time the snow surface reconstruction of a synthetic block");
  surface->add_option("--particles", surface_opts->particles, "particles in the block")->check(CLI::PositiveNumber)
      ->capture_default_str();
  surface->add_option("--threads", surface_opts->threads, "OpenMP threads (default: all cores)")
      ->check(CLI::PositiveNumber);
  surface->add_option("--repeats", surface_opts->repeats, "timed runs; the medians are printed")
      ->check(CLI::PositiveNumber)->capture_default_str();
  surface->callback([surface_opts]() { bench_surface(*surface_opts); });
  add_bench_render_command(*bench);
}

}  // namespace firn::app

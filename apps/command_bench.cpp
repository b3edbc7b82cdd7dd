// firn bench step [--problem NAME] [--steps N] [--threads N] [--backend serial|openmp|cuda]
//                 [--precision float|double] [--transfer apic|pic|flip] [--domain-scale S]
//                 [--enable ATTR]... [--idle-materials N] [--energy-budget] [--material PRESET] [--profile]
// Times the step loop alone (setup excluded) and prints particles, steps,
// particle_steps_per_second and state_hash, plus backend, threads, seconds and memory. --domain-scale,
// --enable and --idle-materials add what the problem does not need (empty grid, attributes nobody
// reads, materials without particles) to measure what skipping them saves (docs/performance.md);
// --energy-budget keeps the energy budget that `firn run` keeps, to measure its cost; --material
// makes the cube of a material preset (a plastic snow times the plastic path); --profile prints each
// launch's time per step and the time outside launches (host work).
// firn bench surface [--particles N] [--threads N] [--repeats N]
// Times the snow surface reconstruction of a synthetic snow block; prints particles_per_second and
// checks that the mesh is a closed manifold (outside the timing).
#include <cinttypes>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "apps/backend_option.hpp"
#include "apps/commands.hpp"
#include "apps/launch_table.hpp"
#include "engine/material_catalog.hpp"
#include "engine/openmp_wait.hpp"
#include "studies/bench/step_benchmark.hpp"
#include "studies/bench/surface_benchmark.hpp"

namespace firn::app {
namespace {

int g_status = 0;

void print_step_benchmark(const bench::StepBenchmarkOptions& o) {
  const bench::StepBenchmarkResult r = bench::benchmark_step(o);
  std::printf("problem %s\nprecision %s\ntransfer %s\nbackend %s\nthreads %d\nopenmp_wait %s\nparticles %zu\n"
              "bytes_per_particle %zu\nsteps %d\nseconds %.4f\n",
              o.problem.c_str(), o.precision.c_str(), o.transfer.c_str(), r.backend.c_str(), r.threads,
              firn::openmp_wait().c_str(), r.particles, r.bytes_per_particle, o.steps, r.seconds);
  std::printf("grid_blocks_active %zu\ngrid_memory_mb %.2f\n", r.grid_blocks_active, r.grid_memory_bytes / 1048576.0);
  std::printf("particle_steps_per_second %.0f\nstate_hash %016" PRIx64 "\n", r.particle_steps_per_second, r.state_hash);
  if (o.profile) print_launch_table(r.launches, r.seconds, o.steps);
}

void print_surface_benchmark(const bench::SurfaceBenchmarkOptions& o) {
  const bench::SurfaceBenchmarkResult r = bench::benchmark_surface(o);
  std::printf("particles %ld\nthreads %d\nrepeats %d\nvertices %zu\ntriangles %zu\ncrystals %zu\n", o.particles,
              r.threads, o.repeats, r.vertices, r.triangles, r.crystals);
  std::printf("closed_manifold %d\neuler_characteristic %ld\n", int(r.closed_manifold), r.euler_characteristic);
  std::printf("field_seconds %.4f\nmarching_seconds %.4f\nsmoothing_seconds %.4f\nnoise_normals_seconds %.4f\n"
              "crystals_seconds %.4f\n",
              r.stages.field, r.stages.marching, r.stages.smoothing, r.stages.detail, r.stages.crystals);
  std::printf("seconds %.4f\nparticles_per_second %.0f\nparticles_per_second_with_crystals %.0f\n", r.seconds,
              double(o.particles) / r.seconds, double(o.particles) / r.seconds_with_crystals);
}

}  // namespace

int exit_status() { return g_status; }
void set_exit_status(int status) { g_status = status; }

void add_bench_command(CLI::App& app) {
  CLI::App* bench = app.add_subcommand("bench", "time the engine's kernels and step loop");
  bench->require_subcommand(1);
  struct StepOptions {
    bench::StepBenchmarkOptions benchmark;
    std::string backend = "openmp";
  };
  auto step_opts = std::make_shared<StepOptions>();
  bench::StepBenchmarkOptions* opts = &step_opts->benchmark;
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
  step->add_flag("--energy-budget", opts->energy_budget, "keep the energy budget, as firn run does (to measure its cost)");
  std::vector<std::string> presets;
  for (const MaterialPreset& p : material_presets()) presets.push_back(p.name);
  step->add_option("--material", opts->material,
                   "make the cube of a material preset instead of the neo-Hookean solid (e.g. thesis_hard_snow, "
                   "which yields as it lands: the plastic path)")
      ->check(CLI::IsMember(presets));
  step->add_option("--domain-scale", opts->domain_scale,
                   "scale the domain box (same particles) to show that cost follows the particles")
      ->check(CLI::Range(1.0, 16.0))->capture_default_str();
  step->add_flag("--profile", opts->profile,
                 "time every launch and print the time per step of each (the profiling adds its own cost to seconds)");
  add_backend_option(step, step_opts->backend);
  step->callback([step_opts]() {
    const std::optional<BackendKind> backend = usable_backend(step_opts->backend);
    if (!backend) return;
    step_opts->benchmark.backend = *backend;
    print_step_benchmark(step_opts->benchmark);
  });

  auto surface_opts = std::make_shared<bench::SurfaceBenchmarkOptions>();
  CLI::App* surface = bench->add_subcommand("surface", "time the snow surface reconstruction of a synthetic block");
  surface->add_option("--particles", surface_opts->particles, "particles in the block")->check(CLI::PositiveNumber)
      ->capture_default_str();
  surface->add_option("--threads", surface_opts->threads, "OpenMP threads (default: all cores)")
      ->check(CLI::PositiveNumber);
  surface->add_option("--repeats", surface_opts->repeats, "timed runs; the medians are printed")
      ->check(CLI::PositiveNumber)->capture_default_str();
  surface->callback([surface_opts]() { print_surface_benchmark(*surface_opts); });
  add_bench_render_command(*bench);
}

}  // namespace firn::app

// firn bench step [--problem NAME] [--steps N] [--threads N] [--precision float|double]
// Times the step loop alone (setup excluded) and prints particles, steps,
// particle_steps_per_second and state_hash, plus threads, seconds and memory.
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <map>
#include <string>

#include "apps/commands.hpp"
#include "apps/run_rendering.hpp"
#include "engine/reference_problems.hpp"
#include "kernels/backend/openmp.hpp"

namespace firn::app {
namespace {

int g_status = 0;

struct BenchStepOptions {
  std::string problem = "cube_drop";
  int steps = 100;
  int threads = 0;  // 0: all cores
  std::string precision = "float";
  double domain_scale = 1;
};

template <class T>
void bench_step(const BenchStepOptions& o) {
  backend::OpenMP omp;
  if (o.threads > 0) omp.thread_count = o.threads;
  Simulation<T, backend::OpenMP> sim(cube_drop_config(o.domain_scale), omp);
  add_cube_drop_particles(sim);
  sim.prepare();
  const auto t0 = std::chrono::steady_clock::now();
  for (int s = 0; s < o.steps; ++s) sim.step();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double rate = double(sim.particle_count()) * o.steps / seconds;
  std::printf("problem %s\nprecision %s\nthreads %d\nparticles %zu\nsteps %d\nseconds %.4f\n", o.problem.c_str(),
              o.precision.c_str(), omp.threads(), sim.particle_count(), o.steps, seconds);
  std::printf("grid_blocks_active %zu\ngrid_memory_mb %.2f\n", sim.grid().active_count(),
              sim.grid().memory_bytes() / 1048576.0);
  std::printf("particle_steps_per_second %.0f\nstate_hash %016" PRIx64 "\n", rate, sim.state_hash());
}

}  // namespace

int exit_status() { return g_status; }
void set_exit_status(int status) { g_status = status; }

void add_bench_command(CLI::App& app) {
  CLI::App* bench = app.add_subcommand("bench", "time the engine's kernels and step loop");
  bench->require_subcommand(1);
  auto opts = std::make_shared<BenchStepOptions>();
  CLI::App* step = bench->add_subcommand("step", "time the step loop on a reference problem");
  step->add_option("--problem", opts->problem, "reference problem")->check(CLI::IsMember({"cube_drop"}))
      ->capture_default_str();
  step->add_option("--steps", opts->steps, "steps to time")->check(CLI::PositiveNumber)->capture_default_str();
  step->add_option("--threads", opts->threads, "OpenMP threads (default: all cores)")->check(CLI::PositiveNumber);
  step->add_option("--precision", opts->precision, "float or double")->check(CLI::IsMember({"float", "double"}))
      ->capture_default_str();
  step->add_option("--domain-scale", opts->domain_scale,
                   "scale the domain box (same particles) to show that cost follows the particles")
      ->check(CLI::Range(1.0, 16.0))->capture_default_str();
  step->callback([opts]() {
    if (opts->precision == "float") bench_step<float>(*opts);
    else bench_step<double>(*opts);
  });
  add_bench_render_command(*bench);
}

}  // namespace firn::app

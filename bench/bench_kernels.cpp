// Microbenchmarks of every kernel of the step (binning, stress per material, P2G, grid update,
// G2P) and of the whole step, each timed inside real steps of a falling cube through the
// backend's launch profile, so that caches and data layout are those of a run.
// Argument: OpenMP threads. items_per_second counts particles (grid nodes for the grid update).
//   build/release/bench/firn_bench_kernels --benchmark_filter=p2g
#include <benchmark/benchmark.h>

#include <chrono>
#include <string>

#include "kernels/backend/openmp.hpp"
#include "studies/bench/reference_problems.hpp"

namespace firn {
namespace {

constexpr double kSide = 0.2;  // 20^3 cells x 8 particles = 64,000 particles at dx = 0.01

// Seconds spent in launches whose name starts with `prefix` during one step.
double launch_seconds(const backend::LaunchProfile& profile, const std::string& prefix) {
  double s = 0;
  for (const auto& [name, entry] : profile.entries)
    if (name.compare(0, prefix.size(), prefix) == 0) s += entry.seconds;
  return s;
}

void BM_StepKernel(benchmark::State& state, const std::string& launch, const std::string& model) {
  Simulation<float, backend::OpenMP> sim(cube_drop_config(), backend::OpenMP(int(state.range(0))));
  const double dx = sim.config().dx;
  const int m = sim.add_material({"cube", model, 1000, ElasticModuli::from_E_nu(1e5, 0.3)});
  sim.add_particles(m, fill_box(sim.config().domain_min, dx, 2, {0.4, 0.3, 0.4}, {0.4 + kSide, 0.3 + kSide, 0.4 + kSide}),
                    {0, -1, 0}, dx * dx * dx / 8);
  for (int s = 0; s < 3; ++s) sim.step();  // settle the layout (first reorder, grid allocation)
  backend::LaunchProfile profile;
  sim.backend().profile = &profile;
  for (auto _ : state) {
    profile.entries.clear();
    const auto t0 = std::chrono::steady_clock::now();
    sim.step();
    const double whole = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    state.SetIterationTime(launch == "step" ? whole : launch_seconds(profile, launch));
  }
  const double items = launch == "grid_update" ? double(sim.grid().active_count()) * kBlockNodes : double(sim.particle_count());
  state.SetItemsProcessed(int64_t(items * double(state.iterations())));
  state.counters["particles"] = double(sim.particle_count());
}

void register_all() {
  const std::pair<const char*, const char*> kernels[] = {
      {"bin.", "neo_hookean"},       {"constitutive.neo_hookean", "neo_hookean"},
      {"constitutive.fixed_corotated", "fixed_corotated"}, {"p2g", "neo_hookean"},
      {"grid_update", "neo_hookean"}, {"g2p", "neo_hookean"},
      {"step", "neo_hookean"},
  };
  for (const auto& [launch, model] : kernels) {
    const std::string name = std::string("kernel/") + (std::string(launch) == "bin." ? "binning" : launch);
    benchmark::RegisterBenchmark(name.c_str(), BM_StepKernel, std::string(launch), std::string(model))
        ->Arg(1)
        ->Arg(2)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
  }
}

const bool registered = (register_all(), true);

}  // namespace
}  // namespace firn

// Microbenchmarks of every kernel of the step (binning, stress per material, P2G, grid update,
// G2P) and of the whole step, each timed inside real steps of a falling cube through the
// backend's launch profile, so that caches and data layout are those of a run. Written once for
// any backend: bench_kernels.cpp registers them for serial and OpenMP (1 and 2 threads),
// bench_kernels_cuda.cu for CUDA in builds with it, so one table holds a kernel's cost on every
// backend: kernel/<launch>/<backend>[/<threads>]. items_per_second counts particles (grid nodes
// for the grid update).
#pragma once

#include <benchmark/benchmark.h>

#include <chrono>
#include <initializer_list>
#include <string>
#include <utility>

#include "engine/backend_kind.hpp"
#include "kernels/backend/launch_profile.hpp"
#include "kernels/backend/memory_space.hpp"
#include "studies/bench/reference_problems.hpp"

namespace firn::bench_kernels {

constexpr double kSide = 0.2;       // 20^3 cells x 8 particles = 64,000 particles at dx = 0.01
constexpr double kLargeSide = 0.4;  // 512,000 particles, for a GPU

// Seconds spent in launches whose name starts with `prefix` during one step.
inline double launch_seconds(const backend::LaunchProfile& profile, const std::string& prefix) {
  double s = 0;
  for (const auto& [name, entry] : profile.entries)
    if (name.compare(0, prefix.size(), prefix) == 0) s += entry.seconds;
  return s;
}

// make_backend(state) gives the backend for the run (the OpenMP instances read threads from the
// argument).
template <class Backend, class MakeBackend>
void step_kernel(benchmark::State& state, const std::string& launch, const std::string& model, double side,
                 const MakeBackend& make_backend) {
  const std::string why = backend_unavailable(backend_named(Backend::kName));
  if (!why.empty()) {
    state.SkipWithError(why.c_str());
    return;
  }
  const backend::UseMemorySpace memory(Backend::memory());
  Simulation<float, Backend> sim(cube_drop_config(), make_backend(state));
  const double dx = sim.config().dx;
  const int m = sim.add_material({"cube", model, 1000, ElasticModuli::from_E_nu(1e5, 0.3)});
  sim.add_particles(m, fill_box(sim.config().domain_min, dx, 2, {0.4, 0.3, 0.4}, {0.4 + side, 0.3 + side, 0.4 + side}),
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

// Registers launch for Backend as `name` over a cube of the given side, with `threads` as
// arguments where the backend has any.
template <class Backend, class MakeBackend>
void register_step_kernel(const std::string& name, const std::string& launch, const std::string& model, double side,
                          const MakeBackend& make_backend, std::initializer_list<int> threads = {}) {
  auto* b = benchmark::RegisterBenchmark(name.c_str(), step_kernel<Backend, MakeBackend>, launch, model, side,
                                         make_backend);
  for (int t : threads) b->Arg(t);
  b->UseManualTime()->Unit(benchmark::kMillisecond);
}

// Registers every kernel for Backend as kernel/<launch>/<backend><suffix> over a cube of the given
// side, with `threads` as arguments where it has any.
template <class Backend, class MakeBackend>
void register_step_kernels(const MakeBackend& make_backend, std::initializer_list<int> threads = {},
                           double side = kSide, const std::string& suffix = "") {
  const std::pair<const char*, const char*> kernels[] = {
      {"bin.", "neo_hookean"},       {"constitutive.neo_hookean", "neo_hookean"},
      {"constitutive.fixed_corotated", "fixed_corotated"}, {"p2g", "neo_hookean"},
      {"grid_update", "neo_hookean"}, {"g2p", "neo_hookean"},
      {"step", "neo_hookean"},
  };
  for (const auto& [launch, model] : kernels) {
    const std::string name = std::string("kernel/") + (std::string(launch) == "bin." ? "binning" : launch) + "/" +
                             Backend::kName + suffix;
    register_step_kernel<Backend>(name, launch, model, side, make_backend, threads);
  }
}

}  // namespace firn::bench_kernels

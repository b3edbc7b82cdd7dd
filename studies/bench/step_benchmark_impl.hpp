// The step benchmark of step_benchmark.hpp on any backend: included by one translation unit per
// backend (step_benchmark.cpp for OpenMP, step_benchmark_serial.cpp, step_benchmark_cuda.cu). The
// CUDA one compiles its backend's step; the serial and OpenMP steps are compiled once, in
// engine/simulation_serial.cpp and engine/simulation_openmp.cpp.
#pragma once

#include <chrono>
#include <stdexcept>
#include <string>

#include "engine/simulation.hpp"
#include "studies/bench/reference_problems.hpp"
#include "studies/bench/step_benchmark.hpp"

namespace firn::bench {

inline Transfer transfer_named(const std::string& name) {
  return name == "pic" ? Transfer::pic : name == "flip" ? Transfer::flip : Transfer::apic;
}

inline Attribute attribute_named(const std::string& name) {
#define FIRN_ATTRIBUTE_NAMED(attribute, n, kind, alloc, doc) \
  if (name == #attribute) return Attribute::attribute;
  FIRN_PARTICLE_ATTRIBUTES(FIRN_ATTRIBUTE_NAMED)
#undef FIRN_ATTRIBUTE_NAMED
  throw std::invalid_argument("unknown attribute " + name);
}

template <class T, class Backend>
StepBenchmarkResult benchmark_step_in(const StepBenchmarkOptions& o, const Backend& backend) {
  SimulationConfig config = cube_drop_config(o.domain_scale);
  config.transfer = transfer_named(o.transfer);
  Simulation<T, Backend> sim(config, backend);
  add_cube_drop_particles(sim, o.material.empty() ? cube_drop_material() : preset_material_info(o.material));
  for (int m = 0; m < o.idle_materials; ++m) {
    MaterialInfo idle = cube_drop_material();
    idle.name = "idle" + std::to_string(m);
    sim.add_material(idle);
  }
  for (const std::string& name : o.enable) sim.enable(attribute_named(name));
  if (o.energy_budget) sim.enable_energy_budget();
  sim.prepare();
  backend::LaunchProfile profile;
  if (o.profile) sim.backend().profile = &profile;
  const auto t0 = std::chrono::steady_clock::now();
  for (int s = 0; s < o.steps; ++s) sim.step();
  StepBenchmarkResult r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.backend = Backend::kName;
  r.threads = backend.threads();
  r.particles = sim.particle_count();
  r.bytes_per_particle = sim.bytes_per_particle();
  r.grid_blocks_active = sim.grid().active_count();
  r.grid_memory_bytes = sim.grid().memory_bytes();
  r.particle_steps_per_second = double(sim.particle_count()) * o.steps / r.seconds;
  r.state_hash = sim.state_hash();
  r.launches = profile.entries;
  return r;
}

// The benchmark in the options' precision.
template <class Backend>
StepBenchmarkResult benchmark_step_on(const StepBenchmarkOptions& o, const Backend& backend) {
  const backend::UseMemorySpace memory(Backend::memory());
  return o.precision == "float" ? benchmark_step_in<float>(o, backend) : benchmark_step_in<double>(o, backend);
}

// The serial and CUDA instances, each in its own translation unit (step_benchmark_serial.cpp,
// step_benchmark_cuda.cu or, without FIRN_CUDA, step_benchmark_cuda_absent.cpp).
StepBenchmarkResult benchmark_step_serial(const StepBenchmarkOptions& o);
StepBenchmarkResult benchmark_step_cuda(const StepBenchmarkOptions& o);

}  // namespace firn::bench

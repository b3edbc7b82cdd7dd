// firn bench step on any backend: times the step loop alone (setup excluded) on a reference problem
// (reference_problems.hpp) and prints what apps/command_bench.cpp describes. Included by one
// translation unit per backend.
#pragma once

#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/simulation.hpp"
#include "studies/bench/reference_problems.hpp"

namespace firn::bench {

struct BenchStepOptions {
  std::string problem = "cube_drop";
  int steps = 100;
  int threads = 0;  // OpenMP threads, 0: all cores
  std::string backend = "openmp";
  std::string precision = "float";
  std::string transfer = "apic";
  double domain_scale = 1;
  std::vector<std::string> enable;  // on_demand attributes to allocate although nothing reads them
  int idle_materials = 0;           // extra materials with no particles
};

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
void bench_step(const BenchStepOptions& o, const Backend& backend) {
  SimulationConfig config = cube_drop_config(o.domain_scale);
  config.transfer = transfer_named(o.transfer);
  Simulation<T, Backend> sim(config, backend);
  add_cube_drop_particles(sim);
  for (int m = 0; m < o.idle_materials; ++m)
    sim.add_material({"idle" + std::to_string(m), "neo_hookean", 1000, ElasticModuli::from_E_nu(1e5, 0.3)});
  for (const std::string& name : o.enable) sim.enable(attribute_named(name));
  sim.prepare();
  const auto t0 = std::chrono::steady_clock::now();
  for (int s = 0; s < o.steps; ++s) sim.step();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double rate = double(sim.particle_count()) * o.steps / seconds;
  std::printf("problem %s\nprecision %s\ntransfer %s\nbackend %s\nthreads %d\nparticles %zu\nbytes_per_particle %zu\n"
              "steps %d\nseconds %.4f\n",
              o.problem.c_str(), o.precision.c_str(), o.transfer.c_str(), Backend::kName, backend.threads(),
              sim.particle_count(),
              sim.bytes_per_particle(), o.steps, seconds);
  std::printf("grid_blocks_active %zu\ngrid_memory_mb %.2f\n", sim.grid().active_count(),
              sim.grid().memory_bytes() / 1048576.0);
  std::printf("particle_steps_per_second %.0f\nstate_hash %016" PRIx64 "\n", rate, sim.state_hash());
}

// Runs bench_step in the options' precision.
template <class Backend>
void bench_step_on(const BenchStepOptions& o, const Backend& backend) {
  if (o.precision == "float") bench_step<float>(o, backend);
  else bench_step<double>(o, backend);
}

// The serial and CUDA instances, each in its own translation unit (step_benchmark_serial.cpp,
// step_benchmark_cuda.cu or, without FIRN_CUDA, step_benchmark_cuda_absent.cpp).
void bench_step_serial(const BenchStepOptions& o);
void bench_step_cuda(const BenchStepOptions& o);

}  // namespace firn::bench

// firn bench step: the step loop alone (setup excluded) timed on a reference problem
// (reference_problems.hpp), on any backend, with the state it ends in. Options that add what the
// problem does not need (a larger domain, attributes nobody reads, materials without particles)
// measure what skipping them saves (docs/performance.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "engine/backend_kind.hpp"
#include "kernels/backend/launch_profile.hpp"

namespace firn::bench {

struct StepBenchmarkOptions {
  std::string problem = "cube_drop";
  int steps = 100;
  BackendKind backend = BackendKind::openmp;  // available here (backend_unavailable)
  int threads = 0;                            // OpenMP threads, 0: all cores
  std::string precision = "float";
  std::string transfer = "apic";
  double domain_scale = 1;
  std::vector<std::string> enable;  // on_demand attributes to allocate although nothing reads them
  int idle_materials = 0;           // extra materials with no particles
  bool energy_budget = false;       // keep the energy budget, as `firn run` does
  std::string material;             // a material preset for the cube; empty: the neo-Hookean one
  bool profile = false;             // time every launch (backend::LaunchProfile)
};

struct StepBenchmarkResult {
  std::string backend;  // its name
  int threads = 0;
  std::size_t particles = 0, bytes_per_particle = 0;
  double seconds = 0;  // the timed steps
  std::size_t grid_blocks_active = 0, grid_memory_bytes = 0;
  double particle_steps_per_second = 0;
  std::uint64_t state_hash = 0;
  std::map<std::string, backend::LaunchProfile::Entry> launches;  // with `profile`: per launch name
};

StepBenchmarkResult benchmark_step(const StepBenchmarkOptions& o);

}  // namespace firn::bench

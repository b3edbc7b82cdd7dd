// summary.json (DESIGN.md section 5): how a run ended and what it cost.
#pragma once

#include <map>
#include <string>

#include "kernels/backend/launch_profile.hpp"

namespace firn {

struct RunSummary {
  std::string status = "ok";  // ok, unstable, interrupted or failed
  std::string error;          // the message, when not ok
  long steps = 0;
  std::size_t particles = 0;      // at the start
  double particle_steps = 0;       // sum over steps of the particles stepped (a conveyor changes the count)
  double simulated_time = 0;
  double wall_seconds = 0;
  double step_seconds = 0;  // inside the step loop
  int threads = 0;
  std::string openmp_wait;  // how idle OpenMP threads waited (engine/openmp_wait.hpp)
  std::string backend = "openmp";
  std::string precision = "float";
  double peak_memory_mb = 0;
  std::string state_hash;  // of the final particle state (Simulation::state_hash), hex
  // With RunOptions::profile: the step loop's launches by name (summary.json: launch_seconds).
  std::map<std::string, backend::LaunchProfile::Entry> launches;
  double particle_steps_per_second() const { return step_seconds > 0 ? particle_steps / step_seconds : 0; }
  std::string to_json() const;
};

// Peak resident memory of this process so far (MB).
double peak_memory_mb();

}  // namespace firn

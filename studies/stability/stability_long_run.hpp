// A long run of a resting body: energy drift and creep over many steps.
//   energy drift = (E(end) - E(0)) / E(0), E = kinetic + elastic + gravitational potential (from the
//                  domain's lowest corner, stability_probe.hpp);
//   creep rate   = the settling speed of the top surface over the second half of the run: minus the
//                  least-squares slope of the top layer's mean height against time
//                  (engine/verification/least_squares.hpp), m/s, positive when it sinks.
#pragma once

#include <vector>

#include "studies/stability/stability_probe.hpp"

namespace firn::study {

struct LongRunResult {
  ProbeResult run;
  std::vector<ProbeSample> history;  // about 1,000 samples, evenly spaced in steps
  double energy_drift = 0;
  double creep_rate = 0;   // m/s
  double settlement = 0;   // m: top height at step 0 minus at the end
};

// Runs `steps` steps of the scene (its end time must not come first; throws std::invalid_argument
// if it does).
LongRunResult long_run(const SceneSpec& scene, long steps, ProbeSettings probe);

}  // namespace firn::study

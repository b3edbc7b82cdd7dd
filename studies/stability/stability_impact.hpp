// The highest impact speed a body survives: bisection (geometric) on the speed of every body of the
// scene, each keeping its direction of motion; "survives" = the run ends without the stability
// guard stopping it (and with nothing non-finite and no energy blow-up: ProbeResult::ok()).
#pragma once

#include <functional>

#include "studies/stability/stability_bisection.hpp"
#include "studies/stability/stability_probe.hpp"

namespace firn::study {

using SpeedTrialReport = std::function<void(double speed, const ProbeResult&)>;

// Throws std::invalid_argument when a body of the scene is at rest (it has no direction to scale).
BisectionResult highest_survived_speed(const SceneSpec& scene, const BisectionSettings& bracket,
                                       const ProbeSettings& probe, const SpeedTrialReport& report);

}  // namespace firn::study

// The largest CFL number at which a scene runs to its end: bisection on simulation.cfl in
// dt = cfl dx / max_p(c_p + |v_p|) (DESIGN.md section 3), with the dt_max cap lifted to 1 s so
// that it never hides the CFL limit. "Runs to the end" is ProbeResult::ok(): no guard stop, nothing
// non-finite, no energy blow-up (stability_probe.hpp).
#pragma once

#include <functional>

#include "studies/stability/stability_bisection.hpp"
#include "studies/stability/stability_probe.hpp"

namespace firn::study {

// Called after each trial run with its CFL number and result.
using CflTrialReport = std::function<void(double cfl, const ProbeResult&)>;

BisectionResult largest_stable_cfl(const SceneSpec& scene, const BisectionSettings& bracket, const ProbeSettings& probe,
                                   const CflTrialReport& report);

}  // namespace firn::study

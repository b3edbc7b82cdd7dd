#include "studies/stability/stability_cfl.hpp"

namespace firn::study {

BisectionResult largest_stable_cfl(const SceneSpec& scene, const BisectionSettings& bracket, const ProbeSettings& probe,
                                   const CflTrialReport& report) {
  return bisect_largest_ok(bracket, [&](double cfl) {
    SceneSpec s = scene;
    s.config.cfl = cfl;
    s.config.dt_max = 1.0;
    const ProbeResult r = probe_scene(s, probe);
    if (report) report(cfl, r);
    return r.ok();
  });
}

}  // namespace firn::study

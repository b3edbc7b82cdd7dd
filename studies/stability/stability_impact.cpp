#include "studies/stability/stability_impact.hpp"

#include <cmath>
#include <stdexcept>

namespace firn::study {

BisectionResult highest_survived_speed(const SceneSpec& scene, const BisectionSettings& bracket,
                                       const ProbeSettings& probe, const SpeedTrialReport& report) {
  for (const BodySpec& b : scene.bodies)
    if (std::hypot(b.velocity[0], b.velocity[1], b.velocity[2]) == 0)
      throw std::invalid_argument("impact speed: body '" + b.name + "' of " + scene.path + " is at rest");
  return bisect_largest_ok(bracket, [&](double speed) {
    SceneSpec s = scene;
    for (BodySpec& b : s.bodies) {
      const double v = std::hypot(b.velocity[0], b.velocity[1], b.velocity[2]);
      for (int d = 0; d < 3; ++d) b.velocity[d] *= speed / v;
    }
    const ProbeResult r = probe_scene(s, probe);
    if (report) report(speed, r);
    return r.ok();
  });
}

}  // namespace firn::study

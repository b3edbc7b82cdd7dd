#include "studies/stability/stability_long_run.hpp"

#include <algorithm>
#include <stdexcept>

#include "engine/verification/least_squares.hpp"

namespace firn::study {

LongRunResult long_run(const SceneSpec& scene, long steps, ProbeSettings probe) {
  LongRunResult r;
  probe.max_steps = steps;
  probe.sample_every = std::max(1L, steps / 1000);
  probe.track_top = true;
  probe.on_sample = [&r](const ProbeSample& s) { r.history.push_back(s); };
  r.run = probe_scene(scene, probe);
  if (r.run.ok() && r.run.steps < steps)
    throw std::invalid_argument("long run: " + scene.path + " reached its end time after " + std::to_string(r.run.steps) +
                                " of " + std::to_string(steps) + " steps");
  const ProbeSample &first = r.run.first, &last = r.history.empty() ? first : r.history.back();
  if (first.total() > 0) r.energy_drift = (last.total() - first.total()) / first.total();
  std::vector<double> t, h;
  for (const ProbeSample& s : r.history) {
    t.push_back(s.time);
    h.push_back(s.top_height);
  }
  r.creep_rate = -least_squares_slope(t, h, 0.5 * last.time, last.time);
  r.settlement = first.top_height - last.top_height;
  return r;
}

}  // namespace firn::study

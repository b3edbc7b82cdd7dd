#include "studies/stability/stability_probe.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <type_traits>

#include "engine/backend_dispatch.hpp"
#include "engine/scene/scene_stepper.hpp"
#include "studies/stability/stability_checkerboard.hpp"

namespace firn::study {

const char* probe_outcome_text(ProbeOutcome o) {
  switch (o) {
    case ProbeOutcome::finished: return "finished";
    case ProbeOutcome::guard_stop: return "guard_stop";
    case ProbeOutcome::not_finite: return "nan";
    case ProbeOutcome::energy_blow_up: return "energy_blow_up";
  }
  return "finished";
}

namespace {

using Clock = std::chrono::steady_clock;

// The energy test needs a scene whose only energy source is its initial state: no moving
// collider, tire, conveyor or load doing work on it.
bool closed_system(const SceneSpec& s) {
  if (s.tire || s.conveyor || !s.loads.empty()) return false;
  for (const ColliderSpec& c : s.colliders)
    for (int d = 0; d < 3; ++d)
      if (c.velocity[d] != 0 || c.angular_velocity[d] != 0) return false;
  return true;
}

template <class T, class Backend>
class Probe {
 public:
  Probe(const SceneSpec& scene, const ProbeSettings& settings, const Backend& backend)
      : scene_(scene), settings_(settings), stepper_(scene, backend), sim_(stepper_.sim()) {
    const Point& g = scene.config.gravity;
    const double g_norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    for (int d = 0; d < 3; ++d) {
      // The domain corner lowest along g: the potential's zero, so that it is never negative.
      lowest_[d] = g[d] > 0 ? scene.config.domain_max[d] : scene.config.domain_min[d];
      up_[d] = g_norm > 0 ? -g[d] / g_norm : (d == 1 ? 1.0 : 0.0);
    }
    if (settings.track_top) mark_top_layer();
  }

  ProbeResult run() {
    const auto t0 = Clock::now();
    ProbeResult r;
    r.particles = sim_.particle_count();
    r.first = sample();
    r.min_J = r.first.min_J;
    const bool energy_test = closed_system(scene_);
    const double e0 = r.first.total();
    auto record = [&](const ProbeSample& s) {
      if (settings_.on_sample) settings_.on_sample(s);
      r.min_J = std::min(r.min_J, s.min_J);
      if (!std::isfinite(s.total()) || !std::isfinite(s.min_J)) {
        r.outcome = ProbeOutcome::not_finite;
        r.detail = "a non-finite energy or J at step " + std::to_string(s.step) + " the guard did not catch";
        return false;
      }
      if (e0 > 0) r.max_growth = std::max(r.max_growth, (s.total() - e0) / e0);
      if (energy_test && r.max_growth > settings_.blow_up_growth) {
        r.outcome = ProbeOutcome::energy_blow_up;
        r.detail = "total energy grew by " + std::to_string(r.max_growth) + " of its initial value by step " +
                   std::to_string(s.step);
        return false;
      }
      return true;
    };
    bool going = record(r.first);
    try {
      while (going && stepper_.before(scene_.end_time) &&
             (settings_.max_steps <= 0 || sim_.steps() < settings_.max_steps)) {
        stepper_.step_toward(scene_.end_time);
        const bool last = !stepper_.before(scene_.end_time) ||
                          (settings_.max_steps > 0 && sim_.steps() >= settings_.max_steps);
        if (last || sim_.steps() % settings_.sample_every == 0) going = record(r.last = sample());
      }
      if (!energy_test && r.outcome == ProbeOutcome::finished) r.detail = "energy test off: work is done on the scene";
    } catch (const StabilityError& e) {
      r.outcome = ProbeOutcome::guard_stop;
      r.detail = e.what();
    }
    r.steps = sim_.steps();
    r.time = sim_.time();
    if (r.last.step == 0 && r.steps > 0) r.last = sample();
    r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return r;
  }

 private:
  double height(const ParticleView<T>& pv, std::size_t p) const {
    return up_[0] * double(pv.x[0][p]) + up_[1] * double(pv.x[1][p]) + up_[2] * double(pv.x[2][p]);
  }

  // The particles within one lattice spacing of the highest one, by id.
  void mark_top_layer() {
    const ParticleView<T> pv = sim_.particles();
    double top = -std::numeric_limits<double>::max();
    std::uint32_t max_id = 0;
    for (std::size_t p = 0; p < pv.n; ++p) {
      top = std::max(top, height(pv, p));
      max_id = std::max(max_id, pv.id[p]);
    }
    const double spacing = scene_.config.dx / scene_.per_axis();
    in_top_.assign(std::size_t(max_id) + 1, 0);
    for (std::size_t p = 0; p < pv.n; ++p)
      if (height(pv, p) > top - 0.5 * spacing) in_top_[pv.id[p]] = 1;
  }

  ProbeSample sample() {
    const Diagnostics d = sim_.diagnostics();
    ProbeSample s;
    s.step = sim_.steps();
    s.time = sim_.time();
    s.kinetic = d.kinetic_energy;
    s.elastic = d.elastic_energy;
    s.min_J = d.min_J;
    s.max_speed = d.max_speed;
    const ParticleView<T> pv = sim_.particles();
    const Point& g = scene_.config.gravity;
    double top_sum = 0;
    std::size_t top_count = 0;
    PressureField field;
    for (std::size_t p = 0; p < pv.n; ++p) {
      double gx = 0;
      for (int d = 0; d < 3; ++d) gx += g[d] * (lowest_[d] - double(pv.x[d][p]));
      s.potential += double(pv.mass[p]) * gx;
      if (!in_top_.empty() && pv.id[p] < in_top_.size() && in_top_[pv.id[p]]) {
        top_sum += height(pv, p);
        ++top_count;
      }
      if (settings_.measure_checkerboard) {
        Mat3<T> F;
        for (int q = 0; q < 9; ++q) F.m[q] = pv.F[q][p];
        // Cauchy pressure -tr(tau) / (3 J_E), tau the Kirchhoff stress of the last step.
        field.pressures.push_back(-double(pv.tau[0][p] + pv.tau[1][p] + pv.tau[2][p]) / (3 * double(determinant(F))));
        field.positions.push_back({double(pv.x[0][p]), double(pv.x[1][p]), double(pv.x[2][p])});
      }
    }
    if (top_count) s.top_height = top_sum / double(top_count);
    if (settings_.measure_checkerboard && s.step > 0) {
      const CheckerboardMeasure m = pressure_checkerboard(field, scene_.config.dx);
      s.checkerboard = m.indicator;
      s.mean_pressure = m.mean_pressure;
    }
    return s;
  }

  const SceneSpec& scene_;
  const ProbeSettings& settings_;
  SceneStepper<T, Backend> stepper_;
  Simulation<T, Backend>& sim_;  // the stepper's
  double lowest_[3] = {0, 0, 0}, up_[3] = {0, 1, 0};
  std::vector<char> in_top_;  // by particle id
};

}  // namespace

ProbeResult probe_scene(const SceneSpec& scene, const ProbeSettings& settings) {
  return with_backend(settings.backend, settings.threads, [&](const auto& backend) {
    using Backend = std::decay_t<decltype(backend)>;
    if (scene.precision == "double") return Probe<double, Backend>(scene, settings, backend).run();
    return Probe<float, Backend>(scene, settings, backend).run();
  });
}

}  // namespace firn::study

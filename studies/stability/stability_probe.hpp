// One in-process run of a scene for the stability study: stepped to its end time, watched by the
// stability guard (a StabilityError stops it) and by an energy test that catches an instability
// the guard misses.
//
// Energy test. With static colliders and walls, the only energy source is what the scene starts
// with: kinetic + elastic + gravitational potential, the potential measured from the domain's
// lowest corner along g (so it is never negative). MLS-MPM/APIC with plasticity and friction only
// dissipates that energy (Jiang et al. 2015, "The affine particle-in-cell method", section 5: APIC
// is dissipative; plastic flow and Coulomb friction dissipate), so
//   growth(t) = (E(t) - E(0)) / E(0),   E = kinetic + elastic + potential,
// stays at or below zero in a stable run, up to the time-discretisation error. A run whose growth
// exceeds `blow_up_growth` (default 0.01) has created energy that neither gravity nor the initial
// motion could supply and counts as an energy blow-up, even if the guard never fired. Near a CFL
// limit the growth is a continuum (the full study's runs that finished grew by up to 0.0099, those
// stopped by this test by 0.0106 to 6.8), so the limits it reports are those of "at most 1% energy
// created"; at cfl 0.1 (the bisection bracket's low end) the growth was 0 to 5e-7.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "engine/backend_kind.hpp"
#include "engine/scene/scene.hpp"

namespace firn::study {

enum class ProbeOutcome { finished, guard_stop, not_finite, energy_blow_up };
const char* probe_outcome_text(ProbeOutcome o);  // "finished", "guard_stop", "nan", "energy_blow_up"

struct ProbeSample {
  long step = 0;
  double time = 0;
  double kinetic = 0, elastic = 0, potential = 0;  // J; potential from the domain's lowest corner
  double min_J = 1, max_speed = 0;
  double top_height = 0;     // with track_top: mean height (along -g) of the particles that started in the top cell
  double checkerboard = 0;   // with measure_checkerboard: pressure_checkerboard() of this state
  double mean_pressure = 0;  // with measure_checkerboard: mean particle pressure (Pa)
  double total() const { return kinetic + elastic + potential; }
};

struct ProbeSettings {
  BackendKind backend = BackendKind::openmp;  // available here (backend_unavailable)
  int threads = 0;                            // OpenMP threads (0: all cores)
  long sample_every = 10;                     // steps between energy samples (and the last step)
  long max_steps = 0;            // when > 0, stop after this many steps (the end time still bounds it)
  double blow_up_growth = 0.01;  // see the energy test above
  bool track_top = false;
  bool measure_checkerboard = false;
  std::function<void(const ProbeSample&)> on_sample;  // every sample, in order
};

struct ProbeResult {
  ProbeOutcome outcome = ProbeOutcome::finished;
  std::string detail;  // the guard's message, or what was not finite, or the energy growth
  long steps = 0;
  double time = 0;           // simulated time reached
  double seconds = 0;        // wall time
  std::size_t particles = 0;
  ProbeSample first, last;
  double min_J = 1;               // over every sample
  double max_growth = 0;          // max over samples of (E - E0) / E0
  bool ok() const { return outcome == ProbeOutcome::finished; }
};

// Builds the scene (float or double, as its precision says) and runs it to its end time (or
// max_steps). Throws SceneError or std::invalid_argument for a scene that cannot be built.
ProbeResult probe_scene(const SceneSpec& scene, const ProbeSettings& settings);

}  // namespace firn::study

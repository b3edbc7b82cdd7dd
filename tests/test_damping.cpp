// Grid velocity damping (SimulationConfig::damping, kernels/grid_update.hpp): each step divides the
// grid's velocities by 1 + c dt, so a body moving as a whole slows by exactly that factor per step,
// and without damping it keeps its speed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/particle_fill.hpp"
#include "engine/simulation.hpp"
#include "kernels/backend/openmp.hpp"

namespace firn {
namespace {

double speed_after(double damping, int steps, double dt) {
  SimulationConfig c;
  c.gravity = {0, 0, 0};
  c.dx = 0.05;
  c.fixed_dt = dt;
  c.damping = damping;
  Simulation<double, backend::OpenMP> sim(c);
  const int m = sim.add_material({"block", "neo_hookean", 1000, ElasticModuli::from_E_nu(1e5, 0.3)});
  sim.add_particles(m, fill_box(c.domain_min, c.dx, 2, {0.3, 0.3, 0.3}, {0.6, 0.6, 0.6}), {1, 0, 0}, 1.5625e-5);
  for (int s = 0; s < steps; ++s) sim.step();
  const ParticleView<double> pv = sim.particles();
  double worst = 0;  // the particle farthest from the body's speed
  for (std::size_t p = 0; p < pv.n; ++p) worst = std::max(worst, std::fabs(pv.v[0][p] - pv.v[0][0]));
  EXPECT_LT(worst, 1e-12);
  return pv.v[0][0];
}

TEST(Damping, SlowsARigidTranslationByOnePlusCdtPerStep) {
  constexpr int kSteps = 100;
  constexpr double kDt = 1e-4, kRate = 50;
  EXPECT_NEAR(speed_after(kRate, kSteps, kDt), std::pow(1 + kRate * kDt, -kSteps), 1e-12);
  EXPECT_NEAR(speed_after(0, kSteps, kDt), 1.0, 1e-12);
}

}  // namespace
}  // namespace firn

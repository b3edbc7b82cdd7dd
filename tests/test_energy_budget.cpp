// The energy budget of a run (Simulation::energy_budget, issue 19): the work of gravity, colliders,
// walls and loads, the plastic work of the return mappings, and the residual they leave, which is
// the step's own numerical dissipation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/verification/material_driver.hpp"
#include "engine/materials.hpp"
#include "engine/particle_fill.hpp"
#include "engine/simulation.hpp"
#include "kernels/backend/openmp.hpp"
#include "tests/open_box.hpp"

namespace firn {
namespace {

double residual(const EnergyBudget& b, double initial, const Diagnostics& d) {
  return initial + b.gravity + b.colliders + b.loads - b.plastic - d.kinetic_energy - d.elastic_energy;
}

// An elastic ball in free fall, moving and, in `spin`, turning at 2 rad/s about z.
struct FallingBall {
  Simulation<double, backend::OpenMP> sim{open_box()};
  double initial = 0;

  explicit FallingBall(double spin) {
    const int m = sim.add_material({"ball", "neo_hookean", 1000, ElasticModuli::from_E_nu(1e5, 0.3)});
    const Point centre = {0.5, 0.7, 0.5};
    const std::vector<Point> x = fill_sphere(sim.config().domain_min, 0.05, 2, centre, 0.1);
    std::vector<Point> v;
    for (const Point& p : x) v.push_back({0.3 - spin * (p[1] - centre[1]), spin * (p[0] - centre[0]), 0});
    sim.add_particles(m, x, v, 0.025 * 0.025 * 0.025);
    sim.enable_energy_budget();
    sim.prepare();
    initial = sim.diagnostics().kinetic_energy;
    sim.advance_to(0.15);
  }
};

// APIC carries a translation through the grid without loss and F stays the identity, so all the
// kinetic energy the ball gains is gravity's work, to round-off.
TEST(EnergyBudget, ABallInFreeFallGainsExactlyGravitysWork) {
  FallingBall ball(0);
  const Diagnostics d = ball.sim.diagnostics();
  const EnergyBudget& b = ball.sim.energy_budget();
  EXPECT_GT(b.gravity, 0.1 * ball.initial);
  EXPECT_EQ(b.colliders, 0);
  EXPECT_EQ(b.loads, 0);
  EXPECT_EQ(b.plastic, 0);
  EXPECT_LT(d.elastic_energy, 1e-12 * b.gravity);
  EXPECT_LT(std::abs(residual(b, ball.initial, d)), 1e-9 * b.gravity);
}

// A constant load pressing a block onto a sticky floor (no gravity) does the work of its force along
// the way its particles moved, m a . (x - x0) summed, whatever the block's oscillation. With a
// fixed step (x_n+1 = x_n + dt v_n+1) the budget's trapezoid in time, m dt a . (v_n + v_n+1) / 2
// summed, is exactly that less the last half step, m dt a . v_end / 2. Counting the kick's kinetic
// energy instead, m dt a . (v_n + dt a / 2), adds m dt^2 |a|^2 / 2 every step that the stress takes
// back: 2.8% of the work here with the adaptive step (measured with that formula), far outside the
// round-off allowed.
TEST(EnergyBudget, ALoadsWorkIsItsForceAlongTheDisplacement) {
  SimulationConfig c = open_box();
  c.gravity = {0, 0, 0};
  c.walls[2] = {WallType::sticky, 3, 0};
  c.fixed_dt = 1e-3;
  Simulation<double, backend::OpenMP> sim(c);
  const int m = sim.add_material({"block", "neo_hookean", 1000, ElasticModuli::from_E_nu(1e5, 0.3)});
  sim.add_particles(m, fill_box(c.domain_min, c.dx, 2, {0.4, 0.15, 0.4}, {0.6, 0.35, 0.6}), {0, 0, 0},
                    0.025 * 0.025 * 0.025);
  sim.add_load({0, 0, 0}, {1, 1, 1}, {0, -10, 0}, 0);
  sim.enable(Attribute::x0);
  sim.enable_energy_budget();
  sim.advance_to(0.2);
  const ParticleView<double> pv = sim.particles();
  double along = 0, last_half_step = 0;
  for (std::size_t p = 0; p < pv.n; ++p)
    for (int d = 0; d < 3; ++d) {
      along += pv.mass[p] * pv.body_accel[d][p] * (pv.x[d][p] - pv.x0[d][p]);
      last_half_step += 0.5 * pv.mass[p] * c.fixed_dt * pv.body_accel[d][p] * pv.v[d][p];
    }
  EXPECT_GT(along, 0);
  EXPECT_NEAR(sim.energy_budget().loads, along - last_half_step, 1e-9 * along);
}

// Turning, the particles move along straight chords (x += dt v), which lengthens every radius and
// takes kinetic energy out at fixed angular momentum: the residual is the step's dissipation, and
// it is positive (the step loses energy; it never makes it).
TEST(EnergyBudget, ATurningBallShowsTheStepsDissipationAsAPositiveResidual) {
  FallingBall ball(2);
  const Diagnostics d = ball.sim.diagnostics();
  const double r = residual(ball.sim.energy_budget(), ball.initial, d);
  EXPECT_GT(r, 0);
}

// A sticky plate moving at U pushes a ball at rest: its work, impulse . U summed over nodes, is U
// times the momentum it gave the ball (no gravity, nothing else acts), to round-off.
TEST(EnergyBudget, AMovingPlatesWorkIsItsSpeedTimesTheMomentumItGave) {
  SimulationConfig c = open_box();
  c.gravity = {0, 0, 0};
  Simulation<double, backend::OpenMP> sim(c);
  const int m = sim.add_material({"ball", "neo_hookean", 1000, ElasticModuli::from_E_nu(1e5, 0.3)});
  sim.add_particles(m, fill_sphere(c.domain_min, c.dx, 2, {0.5, 0.5, 0.5}, 0.1), Point{0, 0, 0}, 0.025 * 0.025 * 0.025);
  const double U = 0.5;
  Collider<double> plate;  // the solid x <= 0.3 + U t
  plate.shape = ColliderShape::plane;
  plate.center[0] = 0.3;
  const double quarter_turn[9] = {0, 1, 0, -1, 0, 0, 0, 0, 1};  // about z: body y is world +x
  std::copy(quarter_turn, quarter_turn + 9, plate.rotation);
  plate.velocity[0] = U;
  plate.boundary = WallType::sticky;
  sim.add_collider(ColliderBody(plate));
  sim.enable_energy_budget();
  sim.prepare();
  sim.advance_to(0.4);
  const Diagnostics d = sim.diagnostics();
  const EnergyBudget& b = sim.energy_budget();
  EXPECT_GT(d.momentum[0], 0.5 * U * 1000 * 4.0 / 3 * M_PI * 1e-3);  // it has caught the ball
  EXPECT_NEAR(b.colliders, U * d.momentum[0], 1e-9 * b.colliders);
  EXPECT_GE(residual(b, 0, d), 0);  // the capture is inelastic
}

// On a monotonic simple-shear path with linear hardening, sigma_y = sigma_y0 + E_p alpha, the work of
// the stress on the plastic strain is int sigma_y d(alpha) = sigma_y0 alpha + E_p alpha^2 / 2
// (Simo and Hughes, Computational Inelasticity, sec. 2.3). The return mappings' plastic work
// (HyperelasticPlastic::plastic_work, the trapezoid rule in alpha) sums to it at any step size: in
// 1000 steps and in 10, where the elastic energy drop that it replaced overstated it by about
// G dgamma^2 per step (+0.5% at 1000 steps).
TEST(EnergyBudget, PlasticWorkOnALinearHardeningPathMatchesItsClosedForm) {
  MaterialInfo info{"j2", "hyperelastic_plastic", 1000, ElasticModuli::from_E_nu(1e8, 0.3), {}};
  info.params = {{"hardening", 0}, {"sigma_y0", 1e5}, {"E_p", 1e6}};
  const MaterialModel<double> model = make_material_model<double>(info);
  for (const int steps : {1000, 10}) {
    const DriverHistory h = drive_material(model, paths::simple_shear(0.01), steps);
    const double alpha = h.state.back().alpha, sigma_y0 = 1e5, E_p = 1e6;
    ASSERT_GT(alpha, 0.004);
    const double exact = sigma_y0 * alpha + 0.5 * E_p * alpha * alpha;
    EXPECT_NEAR(h.plastic_work.back(), exact, 1e-12 * exact) << steps << " steps";
    for (std::size_t k = 1; k < h.plastic_work.size(); ++k) EXPECT_GE(h.plastic_work[k], h.plastic_work[k - 1]);
  }
}

}  // namespace
}  // namespace firn

// Penalty contact at the particles (kernels/step/penalty_contact.hpp, `contact = "penalty"`): the
// kick of one particle against its closed form, friction on the push, the reaction's sums, and
// an elastic block resting on a penalty ground with its whole weight on the springs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "engine/materials.hpp"
#include "engine/particle_fill.hpp"
#include "engine/simulation.hpp"
#include "kernels/backend/openmp.hpp"
#include "kernels/backend/serial.hpp"
#include "tests/open_box.hpp"
#include "kernels/step/penalty_contact.hpp"

namespace firn {
namespace {

constexpr double kSpacing = 0.01;  // rest spacing: a particle is a ball of radius 5 mm
constexpr double kRadius = 0.5 * kSpacing;

// Particles in columns, for the kernel alone.
struct Particles {
  std::vector<double> x[3], v[3], mass, vol0;

  void add(const double at[3], const double vel[3]) {
    for (int d = 0; d < 3; ++d) {
      x[d].push_back(at[d]);
      v[d].push_back(vel[d]);
    }
    mass.push_back(2.0);
    vol0.push_back(kSpacing * kSpacing * kSpacing);
  }
  ParticleView<double> view() {
    ParticleView<double> pv{};
    for (int d = 0; d < 3; ++d) {
      pv.x[d] = x[d].data();
      pv.v[d] = v[d].data();
    }
    pv.mass = mass.data();
    pv.vol0 = vol0.data();
    pv.n = mass.size();
    return pv;
  }
};

// The ground y <= 0, moving along x at `speed`, with Coulomb friction mu.
PenaltyContact<double> ground_push(ParticleView<double> pv, double speed, double mu, double omega2, double dt) {
  Collider<double> ground;
  ground.shape = ColliderShape::plane;
  ground.boundary = WallType::separate;
  ground.friction = {FrictionLaw::coulomb, mu};
  ground.contact = ColliderContact::penalty;
  ground.velocity[0] = speed;
  PenaltyContact<double> push{pv, ground, {}, {}, omega2, dt};
  ground.bounds(push.lo, push.hi);
  return push;
}

DoubleSums<kPenaltySums> run(const PenaltyContact<double>& push) {
  DoubleSums<kPenaltySums> sums;
  for (std::size_t p = 0; p < push.pv.n; ++p) push(p, sums);
  return sums;
}

// An overlapping particle gains dt omega^2 (overlap) along the normal; one that does not is left
// alone; the collider takes the opposite impulse, its torque about its centre, and does the work of
// that impulse at its own velocity.
TEST(PenaltyContact, PushesAnOverlappingParticleOutAndSumsTheReaction) {
  Particles parts;
  const double in[3] = {0.1, kRadius - 0.002, 0}, out[3] = {0.2, kRadius + 1e-4, 0};
  const double falling[3] = {0, -0.3, 0};
  parts.add(in, falling);
  parts.add(out, falling);
  const double omega2 = 4e6, dt = 1e-4, speed = 0.5;
  const DoubleSums<kPenaltySums> sums = run(ground_push(parts.view(), speed, 0, omega2, dt));
  const double push = dt * omega2 * 0.002;  // 0.8 m/s
  EXPECT_NEAR(parts.v[1][0], -0.3 + push, 1e-12);
  EXPECT_EQ(parts.v[0][0], 0);  // frictionless: the slip along the ground is kept
  EXPECT_EQ(parts.v[1][1], -0.3);
  const double f = -2.0 * push / dt;  // on the ground, downward
  EXPECT_NEAR(sums.v[kPenaltyForce + 1], f, 1e-9 * std::abs(f));
  EXPECT_EQ(sums.v[kPenaltyForce + 0], 0);
  EXPECT_NEAR(sums.v[kPenaltyTorque + 2], 0.1 * f, 1e-9 * std::abs(f));  // r x f about the origin
  EXPECT_EQ(sums.v[kPenaltyWork], 0);  // the ground moves across the push
}

// Friction acts on the push, Coulomb's |J_t| <= mu |J_n|: the slip relative to the moving ground
// loses mu times the normal speed change, and a slip smaller than that stops without reversing.
TEST(PenaltyContact, FrictionTakesAtMostMuTimesThePushAndNeverReversesTheSlip) {
  Particles parts;
  const double at[3] = {0, kRadius - 0.001, 0};
  const double fast[3] = {2.0, 0, 0}, slow[3] = {0.55, 0, 0};
  parts.add(at, fast);
  parts.add(at, slow);
  const double omega2 = 4e6, dt = 1e-4, speed = 0.5, mu = 0.5;
  const DoubleSums<kPenaltySums> sums = run(ground_push(parts.view(), speed, mu, omega2, dt));
  const double push = dt * omega2 * 0.001;  // 0.4 m/s: friction takes up to 0.2 m/s of slip
  EXPECT_NEAR(parts.v[0][0], 2.0 - mu * push, 1e-12);
  EXPECT_NEAR(parts.v[0][1], speed, 1e-12);  // a slip of 0.05 m/s stops at the ground's speed
  EXPECT_NEAR(parts.v[1][0], push, 1e-12);
  // The work of the impulse at the ground's velocity: 2 kg (-mu push - 0.05 m/s) x 0.5 m/s.
  EXPECT_NEAR(sums.v[kPenaltyWork], 2.0 * (-mu * push - 0.05) * speed, 1e-12);
  // Both particles sit at x = 0, y = r - 1 mm: the torque about the ground's origin is -y f_x.
  const double fx = sums.v[kPenaltyForce + 0], y = kRadius - 0.001;
  EXPECT_GT(fx, 0);  // friction drags the ground along the particles' slip
  EXPECT_NEAR(sums.v[kPenaltyTorque + 2], -y * fx, 1e-12 * std::abs(fx));
}

constexpr double kGround = 0.2;

// An elastic block 0.1 high and 2 half_width wide and deep (with two particles per cell and the
// default width, eight by four by eight particles) set down on a penalty ground, the plane
// y = kGround; the ground is collider 0.
template <class T, class Backend>
void set_block_on_penalty_ground(Simulation<T, Backend>& sim, int per_cell = 2, double half_width = 0.1) {
  const SimulationConfig& c = sim.config();
  const int m = sim.add_material({"block", "neo_hookean", 1000, ElasticModuli::from_E_nu(1e5, 0.3)});
  const double h = c.dx / per_cell, lo = 0.5 - half_width, hi = 0.5 + half_width;
  sim.add_particles(m, fill_box(c.domain_min, c.dx, per_cell, {lo, kGround, lo}, {hi, kGround + 0.1, hi}), {0, 0, 0},
                    h * h * h);
  Collider<double> plane;
  plane.shape = ColliderShape::plane;
  plane.center[1] = kGround;
  plane.boundary = WallType::separate;
  plane.contact = ColliderContact::penalty;
  sim.add_collider(plane);
  sim.prepare();
}

SimulationConfig damped_box() {
  SimulationConfig c = open_box();
  c.damping = 80;
  return c;
}

// Damped to rest, the block's weight is on the ground, and its bottom row overlaps the ground by the
// spring's static deflection, (weight per bottom particle) / (m omega^2), a small fraction of the
// particle's radius.
TEST(PenaltyContact, AnElasticBlockRestsOnThePenaltyGroundWithItsWeightOnTheSprings) {
  const SimulationConfig c = damped_box();
  Simulation<double, backend::OpenMP> sim(c);
  set_block_on_penalty_ground(sim);
  sim.advance_to(0.4);
  const int g = 0;
  const double h = c.dx / 2, r = h / 2, ground = kGround;

  const ParticleView<double> pv = sim.particles();
  double weight = 0, lowest = 1;
  for (std::size_t p = 0; p < pv.n; ++p) {
    weight += pv.mass[p] * 9.81;
    lowest = std::min(lowest, pv.x[1][p]);
  }
  EXPECT_NEAR(-sim.collider(g).force[1], weight, 0.005 * weight);
  std::vector<double> overlaps;  // of the bottom row, within half a spacing of the lowest particle
  for (std::size_t p = 0; p < pv.n; ++p)
    if (pv.x[1][p] < lowest + 0.5 * h) overlaps.push_back(ground + r - pv.x[1][p]);
  double mean = 0;
  for (double o : overlaps) mean += o / double(overlaps.size());
  const double omega = sim.wave_speed(/*now=*/false) / c.dx;  // penalty_stiffness 1
  const double deflection = weight / double(overlaps.size()) / (pv.mass[0] * omega * omega);
  EXPECT_EQ(overlaps.size(), std::size_t(8 * 8));
  EXPECT_NEAR(mean, deflection, 0.1 * deflection);
  EXPECT_LT(deflection, 0.1 * r);
}

// The pushes depend on each particle alone and their sums are reduced in a fixed order, so the run,
// the ground's force included, is the same on one thread, two, and the serial backend. The block
// (12,800 particles, four per cell) spans several of the reductions' chunks.
TEST(PenaltyContact, TheRunIsTheSameOnAnyThreadCountAndBackend) {
  Simulation<float, backend::OpenMP> one(damped_box(), backend::OpenMP(1)), two(damped_box(), backend::OpenMP(2));
  Simulation<float, backend::Serial> serial(damped_box());
  set_block_on_penalty_ground(one, 4, 0.25);
  set_block_on_penalty_ground(two, 4, 0.25);
  set_block_on_penalty_ground(serial, 4, 0.25);
  ASSERT_GT(one.particles().n, 3 * backend::kReduceGrain);
  for (int s = 0; s < 40; ++s) {
    one.step();
    two.step();
    serial.step();
  }
  EXPECT_LT(one.collider(0).force[1], 0);  // the block has landed on the springs
  EXPECT_EQ(one.collider(0).force[1], two.collider(0).force[1]);
  EXPECT_EQ(one.collider(0).force[1], serial.collider(0).force[1]);
  const ParticleView<float> a = one.particles(), b = two.particles(), c = serial.particles();
  for (std::size_t p = 0; p < a.n; ++p)
    for (int d = 0; d < 3; ++d) {
      EXPECT_EQ(a.x[d][p], b.x[d][p]);
      EXPECT_EQ(a.x[d][p], c.x[d][p]);
    }
}

// A step too long for the spring (omega dt above 1.9) stops the run rather than explode.
TEST(PenaltyContact, AStepTooLongForTheSpringIsRefused) {
  SimulationConfig c = open_box();
  c.fixed_dt = 0.02;  // omega dt = 4.6 for the block's c / dx = 232 1/s
  Simulation<double, backend::OpenMP> sim(c);
  set_block_on_penalty_ground(sim);
  EXPECT_THROW(sim.step(), std::invalid_argument);
}

TEST(PenaltyContact, NeedsASeparateBoundaryAndAPositiveStiffness) {
  Simulation<double, backend::OpenMP> sim(open_box());
  ColliderBody body;
  body.collider.contact = ColliderContact::penalty;
  body.collider.boundary = WallType::sticky;
  EXPECT_THROW(sim.add_collider(body), std::invalid_argument);
  body.collider.boundary = WallType::separate;
  body.penalty_stiffness = 0;
  EXPECT_THROW(sim.add_collider(body), std::invalid_argument);
  body.penalty_stiffness = 1;
  EXPECT_EQ(sim.add_collider(body), 0);
}

}  // namespace
}  // namespace firn

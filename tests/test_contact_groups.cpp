// Multi-velocity-field contact between contact groups (kernels/step/contact_update.hpp): an
// elastic block thrown along an elastic slab under gravity decelerates at mu g, the closed form of
// Coulomb sliding; without friction it keeps its speed; in one group (one continuum) the two
// blocks stick.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/particle_fill.hpp"
#include "engine/simulation.hpp"
#include "kernels/backend/openmp.hpp"

namespace firn {
namespace {

constexpr double kG = 9.81, kSpeed = 1.0, kEnd = 0.2;

// The upper block's mean velocity along x at kEnd, and the lower block's largest |v_x| then.
struct Slide {
  double upper, lower;
};

Slide slide(double mu, bool two_groups) {
  SimulationConfig c;
  c.domain_min = {0, 0, 0};
  c.domain_max = {0.4, 0.2, 0.1};
  c.dx = 0.01;
  c.gravity = {0, -kG, 0};
  c.walls[2] = {WallType::sticky, 3, 0};  // the floor holds the slab
  Simulation<double, backend::OpenMP> sim(c);
  const ElasticModuli rubbery = ElasticModuli::from_E_nu(1e6, 0.3);
  const int lower = sim.add_material({"slab", "neo_hookean", 1000, rubbery});
  const int upper = sim.add_material({"block", "neo_hookean", 1000, rubbery});
  if (two_groups) sim.set_contact_group(upper, 1, Friction<double>{FrictionLaw::coulomb, mu});
  const double h = c.dx / 2, volume = h * h * h;
  sim.add_particles(lower, fill_box(c.domain_min, c.dx, 2, {0.03, 0.03, 0.03}, {0.37, 0.07, 0.07}), {0, 0, 0}, volume);
  sim.add_particles(upper, fill_box(c.domain_min, c.dx, 2, {0.05, 0.07, 0.03}, {0.11, 0.10, 0.07}), {kSpeed, 0, 0},
                    volume);
  sim.prepare();
  while (sim.time() < kEnd * (1 - 1e-12)) sim.step(std::min(sim.next_dt(), kEnd - sim.time()));
  const ParticleView<double> pv = sim.particles();
  Slide s{0, 0};
  const ParticleRange u = sim.material_range(upper), l = sim.material_range(lower);
  double mass = 0;
  for (std::size_t p = u.begin; p < u.end; ++p) s.upper += pv.mass[p] * pv.v[0][p], mass += pv.mass[p];
  s.upper /= mass;
  for (std::size_t p = l.begin; p < l.end; ++p) s.lower = std::max(s.lower, std::abs(double(pv.v[0][p])));
  return s;
}

TEST(ContactGroups, BlockSlidingOnASlabDeceleratesAtMuG) {
  const double mu = 0.3;
  const Slide s = slide(mu, true);
  const double deceleration = (kSpeed - s.upper) / kEnd;
  EXPECT_NEAR(deceleration, mu * kG, 0.02 * mu * kG) << "v(0.2 s) = " << s.upper << " m/s";
  EXPECT_LT(s.lower, 0.05);  // the slab stays where the floor holds it
}

TEST(ContactGroups, FrictionlessBlockKeepsItsSpeed) {
  const Slide s = slide(0, true);
  EXPECT_NEAR(s.upper, kSpeed, 0.01 * kSpeed);
}

TEST(ContactGroups, OneGroupIsOneContinuum) {
  const Slide s = slide(0.3, false);
  EXPECT_LT(s.upper, 0.1);  // the block is stuck to the slab, which the floor holds
}

}  // namespace
}  // namespace firn

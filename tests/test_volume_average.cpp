// F-bar volume averaging (kernels/step/volume_average.hpp) in the step: a particle field whose
// volume ratio alternates from particle to particle (the checkerboard mode) is smoothed to its
// mean in one step, mass-weighted mean kept, for a nearly incompressible material, and left as it
// is for a compressible one, whose results volume averaging must not change.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/simulation.hpp"
#include "kernels/backend/openmp.hpp"

namespace firn {
namespace {

struct Spread {
  double mean_J = 0, rms = 0;  // mean of J and RMS of J - mean_J, over particles
};

Spread volume_spread(Simulation<double, backend::OpenMP>& sim) {
  const ParticleView<double> pv = sim.particles();
  Spread s;
  for (std::size_t p = 0; p < pv.n; ++p) s.mean_J += Simulation<double, backend::OpenMP>::total_J(pv, p);
  s.mean_J /= double(pv.n);
  for (std::size_t p = 0; p < pv.n; ++p) {
    const double d = Simulation<double, backend::OpenMP>::total_J(pv, p) - s.mean_J;
    s.rms += d * d;
  }
  s.rms = std::sqrt(s.rms / double(pv.n));
  return s;
}

// A block of 8 particles per cell whose J alternates 1 +- 1e-3 with the parity of the particle's
// lattice site, stepped once with a time step too short for any motion to change F.
Spread after_one_step(double nu, Spread& before) {
  SimulationConfig c;
  c.dx = 0.02;
  c.gravity = {0, 0, 0};
  c.fixed_dt = 1e-9;
  Simulation<double, backend::OpenMP> sim(c);
  const int m = sim.add_material({"rubber", "neo_hookean", 1000, ElasticModuli::from_E_nu(1e7, nu)});
  sim.add_particles(m, fill_box(c.domain_min, c.dx, 2, {0.3, 0.3, 0.3}, {0.7, 0.7, 0.7}), {0, 0, 0}, 1e-6);
  sim.prepare();
  const ParticleView<double> pv = sim.particles();
  const double h = c.dx / 2;
  for (std::size_t p = 0; p < pv.n; ++p) {
    const long parity = std::lround(pv.x[0][p] / h - 0.5) + std::lround(pv.x[1][p] / h - 0.5) + std::lround(pv.x[2][p] / h - 0.5);
    const double scale = std::cbrt(parity % 2 ? 1.001 : 0.999);
    for (int d = 0; d < 3; ++d) pv.F[4 * d][p] = scale;
  }
  before = volume_spread(sim);
  sim.step();
  return volume_spread(sim);
}

TEST(VolumeAveraging, SmoothsTheCheckerboardOfANearlyIncompressibleSolid) {
  Spread before;
  const Spread after = after_one_step(0.49, before);
  EXPECT_NEAR(before.rms, 1e-3, 1e-5);
  // Interior particles average to the mean; those of the faces keep part of their mode.
  EXPECT_LT(after.rms, 0.1 * before.rms);
  EXPECT_NEAR(after.mean_J, before.mean_J, 1e-5);
}

TEST(VolumeAveraging, LeavesACompressibleSolidAlone) {
  Spread before;
  const Spread after = after_one_step(0.3, before);
  EXPECT_NEAR(after.rms, before.rms, 1e-9);
  EXPECT_NEAR(after.mean_J, before.mean_J, 1e-9);
}

// Two nearly incompressible blocks side by side, sharing the grid nodes between them: the lower
// compressed to J = 0.97, the upper at J = 1, one step as above. In one contact group F-bar averages
// across the interface; in two it averages each block among its own particles, so both keep their
// uniform J exactly.
TEST(VolumeAveraging, ContactGroupsAverageApart) {
  for (const bool apart : {false, true}) {
    SimulationConfig c;
    c.dx = 0.02;
    c.gravity = {0, 0, 0};
    c.fixed_dt = 1e-9;
    Simulation<double, backend::OpenMP> sim(c);
    const ElasticModuli rubber = ElasticModuli::from_E_nu(1e7, 0.49);
    const int lower = sim.add_material({"lower", "neo_hookean", 1000, rubber});
    const int upper = sim.add_material({"upper", "neo_hookean", 1000, rubber});
    if (apart) sim.set_contact_group(upper, 1, Friction<double>{FrictionLaw::coulomb, 0.0});
    sim.add_particles(lower, fill_box(c.domain_min, c.dx, 2, {0.3, 0.3, 0.3}, {0.7, 0.5, 0.7}), {0, 0, 0}, 1e-6);
    sim.add_particles(upper, fill_box(c.domain_min, c.dx, 2, {0.3, 0.5, 0.3}, {0.7, 0.7, 0.7}), {0, 0, 0}, 1e-6);
    sim.prepare();
    const ParticleView<double> pv = sim.particles();
    const ParticleRange below = sim.material_range(lower);
    for (std::size_t p = below.begin; p < below.end; ++p)
      for (int d = 0; d < 3; ++d) pv.F[4 * d][p] = std::cbrt(0.97);
    sim.step();
    const ParticleView<double> after = sim.particles();
    const ParticleRange lower_now = sim.material_range(lower);
    double worst[2] = {0, 0};  // largest |J - J0| per block
    for (std::size_t p = 0; p < after.n; ++p) {
      const bool in_lower = p >= lower_now.begin && p < lower_now.end;
      double& w = worst[in_lower ? 0 : 1];
      w = std::max(w, std::fabs(Simulation<double, backend::OpenMP>::total_J(after, p) - (in_lower ? 0.97 : 1.0)));
    }
    if (apart) {
      EXPECT_LT(worst[0], 1e-9);
      EXPECT_LT(worst[1], 1e-9);
    } else {
      EXPECT_GT(worst[0], 1e-3);  // the interface's particles take part of the other block's J
      EXPECT_GT(worst[1], 1e-3);
    }
  }
}

}  // namespace
}  // namespace firn

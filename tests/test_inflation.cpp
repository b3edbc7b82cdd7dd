// Inflation pressure (issue 17 item 2): the follower pressure of kernels/body_acceleration.hpp
// against Nanson's formula on one particle, and a pressurised ring against the closed form of a
// thick-walled cylinder (Lame; plane stress, Timoshenko and Goodier, Theory of Elasticity, 1970,
// section 28).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/pressure_surface.hpp"
#include "engine/simulation.hpp"
#include "kernels/backend/openmp.hpp"
#include "kernels/body_acceleration.hpp"
#include "kernels/mat3.hpp"

namespace firn {
namespace {

TEST(Inflation, PressureFollowsTheSurfaceByNansonsFormula) {
  // One particle with F = R U (a turn about a skew axis after a stretch): a = p J F^-T A0 / m, plus its load's.
  const Mat3<double> U = {{1.3, 0.1, 0.0, 0.1, 0.8, 0.05, 0.0, 0.05, 1.1}};
  const Mat3<double> F = axis_angle_rotation(Vec3<double>{{1, 2, 3}}, 0.7) * U;
  double columns[9], area[3] = {0.2, -0.5, 0.4}, mass = 0.25, accel[3] = {0, 0, 0};
  std::uint32_t load = 1;
  ParticleView<double> pv{};
  pv.n = 1;
  for (int q = 0; q < 9; ++q) {
    columns[q] = F.m[q];
    pv.F[q] = &columns[q];
  }
  for (int d = 0; d < 3; ++d) {
    pv.area0[d] = &area[d];
    pv.body_accel[d] = &accel[d];
  }
  pv.mass = &mass;
  pv.load = &load;
  const double table[6] = {0, 0, 0, 1.0, -2.0, 0.5}, pressure = 3.0;
  BodyAcceleration<double>{pv, table, pressure}(0);
  const double J = determinant(F);
  const Mat3<double> inv = inverse(F);
  for (int i = 0; i < 3; ++i) {
    double n = 0;  // (J F^-T A0)_i
    for (int j = 0; j < 3; ++j) n += J * inv(j, i) * area[j];
    EXPECT_NEAR(accel[i], table[3 + i] + pressure * n / mass, 1e-12) << i;
  }
  // Without loads or a surface: zero.
  pv.area0[0] = pv.area0[1] = pv.area0[2] = nullptr;
  BodyAcceleration<double>{pv, nullptr, pressure}(0);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(accel[i], 0.0);
}

TEST(Inflation, PressurisedRingExpandsAsTheThickWalledCylinder) {
  // A ring of inner radius a, outer b, length H along z, no gravity, its bore pressurised to p (ramped
  // over 10 ms) and its motion damped to rest. Plane stress (free faces):
  //   u(r) = ((1 - nu) A r + (1 + nu) B / r) / E,  A = p a^2 / (b^2 - a^2),  B = A b^2.
  constexpr double a = 0.1, b = 0.12, H = 0.016, E = 1e6, nu = 0.3, p = 2000, end = 0.08;
  SimulationConfig c;
  c.domain_min = {-0.16, -0.16, -0.04};
  c.domain_max = {0.16, 0.16, 0.04};
  c.dx = 0.004;
  c.gravity = {0, 0, 0};
  c.damping = 300;
  Simulation<double, backend::OpenMP> sim(c);
  const int ring = sim.add_material({"ring", "neo_hookean", 1000, ElasticModuli::from_E_nu(E, nu)});
  const int per_cell = 2;
  const double h = c.dx / per_cell;
  const std::vector<Point> x = fill_lattice(c.domain_min, c.dx, per_cell, {-b, -b, -H / 2}, {b, b, H / 2}, [&](const Point& q) {
    const double r = std::hypot(q[0], q[1]);
    return r >= a && r < b;
  });
  sim.add_particles(ring, x, {0, 0, 0}, h * h * h);
  sim.add_pressure_surface(0, inner_cylinder_areas(x, {0, 0, 0}, a, H / 2, h));
  sim.set_pressure(p, 0.01);
  sim.advance_to(end);
  const std::vector<std::uint32_t> order = sim.id_order();  // ids follow x's order
  const ParticleView<double> pv = sim.particles();
  const double A = p * a * a / (b * b - a * a), B = A * b * b;
  double measured = 0, exact = 0, drift[2] = {0, 0};
  for (std::size_t i = 0; i < x.size(); ++i) {
    const std::uint32_t q = order[i];
    const double r0 = std::hypot(x[i][0], x[i][1]);
    const double u[2] = {pv.x[0][q] - x[i][0], pv.x[1][q] - x[i][1]};
    measured += (u[0] * x[i][0] + u[1] * x[i][1]) / r0;
    exact += ((1 - nu) * A * r0 + (1 + nu) * B / r0) / E;
    for (int d = 0; d < 2; ++d) drift[d] += u[d];
  }
  const double error = measured / exact - 1;
  std::printf("ring: mean radial displacement %.4g mm, closed form %.4g mm, error %+.2f%%, kinetic %.3g J\n",
              1e3 * measured / double(x.size()), 1e3 * exact / double(x.size()), 100 * error,
              sim.diagnostics().kinetic_energy);
  // Measured: +7.18%, +3.92%, +2.58% at dx = 8, 4, 2 mm (5, 10, 20 particles through the wall):
  // converging at order 1.3 toward about +1.6%, the closed form's own plane-stress and small-strain
  // approximations (H = 16 mm is not thin against the 20 mm wall; u / a = 1.1%).
  EXPECT_LT(std::fabs(error), 0.05);
  // The pressure's net force is zero: the ring's centre stays put.
  EXPECT_LT(std::hypot(drift[0], drift[1]), 1e-3 * measured);
}

}  // namespace
}  // namespace firn

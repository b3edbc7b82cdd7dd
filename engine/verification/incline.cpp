#include "engine/verification/incline.hpp"

#include <chrono>
#include <cmath>

#include "engine/backend_dispatch.hpp"
#include "engine/simulation.hpp"

namespace firn {

namespace {

// Centre of mass x_com (x and y), its velocity along x and the rigid angular velocity about z that
// fits the particle velocities best in the mass-weighted least-squares sense:
//   omega_z = sum m (r_x v_y - r_y v_x) / sum m (r_x^2 + r_y^2),  r = x - x_com,
// i.e. the angular momentum about the centre of mass over the moment of inertia (plane motion).
template <class T>
void planar_motion(const ParticleView<T>& pv, double x_com[2], double& velocity_x, double& omega_z) {
  double m = 0, x[2] = {0, 0}, v = 0;
  for (std::size_t p = 0; p < pv.n; ++p) {
    const double mp = pv.mass[p];
    m += mp;
    x[0] += mp * double(pv.x[0][p]);
    x[1] += mp * double(pv.x[1][p]);
    v += mp * double(pv.v[0][p]);
  }
  x[0] /= m;
  x[1] /= m;
  double angular = 0, inertia = 0;
  for (std::size_t p = 0; p < pv.n; ++p) {
    const double mp = pv.mass[p], rx = double(pv.x[0][p]) - x[0], ry = double(pv.x[1][p]) - x[1];
    angular += mp * (rx * double(pv.v[1][p]) - ry * double(pv.v[0][p]));
    inertia += mp * (rx * rx + ry * ry);
  }
  velocity_x = v / m;
  omega_z = angular / inertia;
  x_com[0] = x[0];
  x_com[1] = x[1];
}

template <class T, class Backend>
InclineHistory run_incline_in(const InclineRun& run, const Backend& backend) {
  const double dx = run.dx, h = dx / run.per_cell;
  SimulationConfig c;
  c.domain_min = {-3 * dx, -3 * dx, -2 * dx};
  c.domain_max = {run.body_max[0] + run.travel + 3 * dx, run.body_max[1] + 3 * dx, 3 * dx};
  c.dx = dx;
  c.gravity = {0, 0, 0};  // applied as a body acceleration, eased in
  c.cfl = 0.4;
  c.dt_max = run.end_time;
  c.transfer = run.method.transfer;
  c.shape = run.method.shape;
  for (auto& wall : c.walls) wall = {WallType::none, 0, 0};
  c.walls[4] = c.walls[5] = {WallType::slip, 3, 0};  // nodes z = -2dx..0 and dx..3dx: all of them
  Simulation<T, Backend> sim(c, backend);
  const int body = sim.add_material(run.material);
  sim.add_particles(body,
                    fill_lattice(c.domain_min, dx, run.per_cell, {0, 0, 0}, {run.body_max[0], run.body_max[1], dx},
                                 run.inside),
                    {0, 0, 0}, h * h * h);
  Collider<double> ground;  // the solid y <= 0
  ground.shape = ColliderShape::plane;
  ground.boundary = WallType::separate;
  ground.friction = {FrictionLaw::coulomb, run.mu};
  ground.contact = run.contact;
  sim.add_collider(ground);
  sim.enable(Attribute::body_accel);
  sim.prepare();

  const double g[2] = {kInclineGravity * std::sin(run.angle), -kInclineGravity * std::cos(run.angle)};
  InclineHistory history;
  const auto t0 = std::chrono::steady_clock::now();
  while (sim.time() < run.end_time * (1 - 1e-12)) {
    const double dt = std::min(sim.next_dt(), run.end_time - sim.time());
    const double t = sim.time() + dt / 2;
    const double ease = t < run.ramp ? (1 - std::cos(M_PI * t / run.ramp)) / 2 : 1;
    ParticleView<T> pv = sim.particles();
    for (std::size_t p = 0; p < pv.n; ++p) {
      pv.body_accel[0][p] = T(ease * g[0]);
      pv.body_accel[1][p] = T(ease * g[1]);
    }
    sim.step(dt);
    double v = 0, omega_z = 0, com[2];
    planar_motion(sim.particles(), com, v, omega_z);
    history.time.push_back(sim.time());
    history.velocity.push_back(v);
    history.spin.push_back(-omega_z);
    // The ground's reaction F and torque tau about the world origin, on the collider; on the body
    // -F, and about the ground point p = (x_com, 0): -(tau_z - (p_x F_y - p_y F_x)).
    const ColliderBody& g = sim.collider(0);
    history.ground_force.push_back(-g.force[0]);
    history.normal_force.push_back(-g.force[1]);
    history.ground_moment.push_back(-(g.torque[2] - com[0] * g.force[1]));
  }
  history.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  history.steps = sim.steps();
  history.particles = sim.particle_count();
  return history;
}

}  // namespace

InclineHistory run_incline(const InclineRun& run, const VerificationOptions& options) {
  return with_precision(run.method, [&](auto scalar) {
    return with_backend(options.backend, options.threads, [&](const auto& backend) {
      return run_incline_in<decltype(scalar)>(run, backend);
    });
  });
}

}  // namespace firn

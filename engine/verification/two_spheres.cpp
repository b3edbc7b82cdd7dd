// Two elastic spheres colliding (Sulsky, Chen and Schreyer 1994, in 3D; DESIGN.md section 6,
// problem 3): neo-Hookean spheres of radius 0.2 (E = 1000 Pa, nu = 0.3, rho = 1000 kg/m^3) moving
// towards each other at 0.1 m/s along the diagonal, no gravity and no walls reached. MPM conserves
// total momentum exactly in exact arithmetic (sum_i w_ip = 1 and sum_i w_ip (x_i - x_p) = 0), so the
// error is the drift of total momentum relative to the initial sum of |m v|, per transfer scheme;
// the kinetic and elastic energy history of each scheme goes to the log.
#include <chrono>
#include <cmath>
#include <ostream>

#include "engine/simulation.hpp"
#include "engine/verification/verification.hpp"
#include "kernels/backend/openmp.hpp"

namespace firn {

std::vector<VerificationRow> verify_two_spheres(const VerificationOptions& options) {
  const double dx = 1.0 / 32, radius = 0.2, speed = 0.1, end_time = 4.0;
  const int per_cell = 2;
  const double bound = 1e-10;  // double precision round-off over a few hundred steps
  const double s = speed / std::sqrt(3.0);
  std::vector<VerificationRow> rows;
  const std::pair<const char*, Transfer> schemes[] = {
      {"apic", Transfer::apic}, {"pic", Transfer::pic}, {"flip", Transfer::flip}};
  for (const auto& [name, transfer] : schemes) {
    SimulationConfig c;
    c.domain_min = {0, 0, 0};
    c.domain_max = {1, 1, 1};
    c.dx = dx;
    c.gravity = {0, 0, 0};
    c.transfer = transfer;
    c.cfl = 0.4;
    c.dt_max = 0.05;
    backend::OpenMP omp;
    if (options.threads > 0) omp.thread_count = options.threads;
    Simulation<double, backend::OpenMP> sim(c, omp);
    const int m = sim.add_material({"sphere", "neo_hookean", 1000, ElasticModuli::from_E_nu(1000, 0.3)});
    const double h = dx / per_cell;
    sim.add_particles(m, fill_sphere(c.domain_min, dx, per_cell, {0.3, 0.3, 0.3}, radius), {s, s, s}, h * h * h);
    sim.add_particles(m, fill_sphere(c.domain_min, dx, per_cell, {0.7, 0.7, 0.7}, radius), {-s, -s, -s}, h * h * h);
    sim.prepare();
    const Diagnostics d0 = sim.diagnostics();
    double scale = 0;  // sum of |m v| at the start
    const ParticleView<double> pv = sim.particles();
    for (std::size_t p = 0; p < pv.n; ++p) scale += pv.mass[p] * speed;

    const auto t0 = std::chrono::steady_clock::now();
    double drift = 0;
    int next_log = 0;
    const int log_samples = 8;
    while (sim.time() < end_time * (1 - 1e-12)) {
      sim.step(std::min(sim.next_dt(), end_time - sim.time()));
      const Diagnostics d = sim.diagnostics();
      double dp = 0;
      for (int k = 0; k < 3; ++k) dp += (d.momentum[k] - d0.momentum[k]) * (d.momentum[k] - d0.momentum[k]);
      drift = std::max(drift, std::sqrt(dp) / scale);
      if (options.log && sim.time() >= next_log * end_time / log_samples) {
        *options.log << "two_spheres " << name << " t " << sim.time() << " kinetic " << d.kinetic_energy
                     << " elastic " << d.elastic_energy << " total " << d.kinetic_energy + d.elastic_energy << "\n";
        ++next_log;
      }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rows.push_back({std::string("two_spheres.") + name, 0, dx, per_cell, sim.steps(), drift, bound, seconds});
  }
  return rows;
}

}  // namespace firn

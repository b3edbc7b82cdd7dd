// Two elastic spheres colliding (Sulsky, Chen and Schreyer 1994, in 3D; DESIGN.md section 6,
// problem 3): neo-Hookean spheres of radius 0.2 (E = 1000 Pa, nu = 0.3, rho = 1000 kg/m^3) moving
// towards each other at 0.1 m/s along the diagonal, no gravity and no walls reached. MPM conserves
// total momentum exactly in exact arithmetic (sum_i w_ip = 1 and sum_i w_ip (x_i - x_p) = 0), so the
// error is the drift of total momentum relative to the initial sum of |m v|, per transfer scheme;
// the kinetic and elastic energy history of each scheme goes to the log. The collision is elastic,
// so the exact total energy is constant: the case error (for `firn study accuracy`) is the relative
// loss of kinetic + elastic energy at t = 4 s, after the spheres have separated, the measure of a
// transfer scheme's numerical dissipation (PIC's is large; Jiang et al. 2015, APIC).
#include <chrono>
#include <cmath>
#include <ostream>

#include "engine/backend_dispatch.hpp"
#include "engine/simulation.hpp"
#include "engine/verification/verification.hpp"

namespace firn {
namespace {

constexpr double kRadius = 0.2, kSpeed = 0.1, kEndTime = 4.0;
constexpr int kPerCell = 2;

template <class T, class Backend>
TwoSpheresCase run_spheres(int level, const VerificationMethod& method, const EnergyHistory& history,
                           const Backend& backend) {
  const double dx = 1.0 / (16 << level), s = kSpeed / std::sqrt(3.0), h = dx / kPerCell;
  SimulationConfig c;
  c.domain_min = {0, 0, 0};
  c.domain_max = {1, 1, 1};
  c.dx = dx;
  c.gravity = {0, 0, 0};
  c.transfer = method.transfer;
  c.shape = method.shape;
  c.cfl = 0.4;
  c.dt_max = 0.05;
  Simulation<T, Backend> sim(c, backend);
  const int m = sim.add_material({"sphere", "neo_hookean", 1000, ElasticModuli::from_E_nu(1000, 0.3)});
  sim.add_particles(m, fill_sphere(c.domain_min, dx, kPerCell, {0.3, 0.3, 0.3}, kRadius), {s, s, s}, h * h * h);
  sim.add_particles(m, fill_sphere(c.domain_min, dx, kPerCell, {0.7, 0.7, 0.7}, kRadius), {-s, -s, -s}, h * h * h);
  sim.prepare();
  const Diagnostics d0 = sim.diagnostics();
  const double e0 = d0.kinetic_energy + d0.elastic_energy;
  double scale = 0;  // sum of |m v| at the start
  const ParticleView<T> pv = sim.particles();
  for (std::size_t p = 0; p < pv.n; ++p) scale += double(pv.mass[p]) * kSpeed;
  if (history) history(0, d0.kinetic_energy, d0.elastic_energy);

  double seconds = 0, drift = 0;
  Diagnostics d = d0;
  while (sim.time() < kEndTime * (1 - 1e-12)) {
    const auto t0 = std::chrono::steady_clock::now();
    sim.step(std::min(sim.next_dt(), kEndTime - sim.time()));
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    d = sim.diagnostics();
    double dp = 0;
    for (int k = 0; k < 3; ++k) dp += (d.momentum[k] - d0.momentum[k]) * (d.momentum[k] - d0.momentum[k]);
    drift = std::max(drift, std::sqrt(dp) / scale);
    if (history) history(sim.time(), d.kinetic_energy, d.elastic_energy);
  }
  const double energy_error = std::abs(1 - (d.kinetic_energy + d.elastic_energy) / e0);
  return {{dx, kPerCell, sim.particle_count(), sim.steps(), energy_error, seconds}, drift};
}

}  // namespace

TwoSpheresCase two_spheres_case(int level, const VerificationMethod& method, const VerificationOptions& options,
                                const EnergyHistory& history) {
  return with_precision(method, [&](auto scalar) {
    return with_backend(options.backend, options.threads, [&](const auto& backend) {
      return run_spheres<decltype(scalar)>(level, method, history, backend);
    });
  });
}

std::vector<VerificationRow> verify_two_spheres(const VerificationOptions& options) {
  const double bound = 1e-10;  // double precision round-off over a few hundred steps
  const int level = 1;         // dx = 1/32
  std::vector<VerificationRow> rows;
  for (const Transfer transfer : {Transfer::apic, Transfer::pic, Transfer::flip}) {
    VerificationMethod method;
    method.transfer = transfer;
    const std::string name = transfer_name(transfer);
    double next_log = 0;  // eight samples of the history per scheme
    const EnergyHistory log = [&](double t, double kinetic, double elastic) {
      if (!options.log || t < next_log) return;
      *options.log << "two_spheres " << name << " t " << t << " kinetic " << kinetic << " elastic " << elastic
                   << " total " << kinetic + elastic << "\n";
      next_log += kEndTime / 8;
    };
    const TwoSpheresCase r = two_spheres_case(level, method, options, log);
    rows.push_back({"two_spheres." + name, level, r.run.dx, r.run.particles_per_cell, r.run.steps, r.momentum_drift,
                    bound, r.run.seconds, r.run.particles});
  }
  return rows;
}

}  // namespace firn

// Axially vibrating bar (Bardenhagen 2002; Tielen et al. 2017; DESIGN.md section 6, problem 1):
// a bar of length L = 25 fixed at x = 0 and free at x = L, E = 100, rho = 1, in its first mode
// v(x, 0) = v0 sin(beta x) with v0 = 0.1, beta = pi / (2L). Exact solution
//   u(x, t) = v0 / w sin(w t) sin(beta x),  w = beta sqrt(E / rho).
// With nu = 0 the fixed-corotated model is exactly linear in nominal stress for uniaxial motion
// (P = E (F - 1)), so the exact solution is that of the linear wave equation in the reference
// configuration and any error is the method's. The error is the largest deviation of the free end's
// displacement from the exact one over one period, relative to the amplitude v0 / w.
// The fixed end carries the largest stress, and MPM's nodes next to a material boundary miss the
// particles beyond it (see manufactured_solution.cpp), so the error converges at first order; the
// bound at level l is 1% (the requirement at the finest level) times dx / dx_finest.
#include <algorithm>
#include <chrono>
#include <cmath>

#include "engine/simulation.hpp"
#include "engine/verification/verification.hpp"
#include "kernels/backend/openmp.hpp"

namespace firn {

std::vector<VerificationRow> verify_vibrating_bar(const VerificationOptions& options) {
  const double L = 25, E = 100, rho = 1, v0 = 0.1;
  const double beta = M_PI / (2 * L), w = beta * std::sqrt(E / rho), amplitude = v0 / w, period = 2 * M_PI / w;
  const int per_cell = 2;
  const double finest_bound = 0.01;  // 1% of the amplitude at the finest level
  const int levels = 3;
  std::vector<VerificationRow> rows;
  for (int level = 0; level < levels; ++level) {
    const double dx = L / (50 << level);
    SimulationConfig c;
    c.domain_min = {-2 * dx, -2 * dx, -2 * dx};
    c.domain_max = {L + 4 * dx, 3 * dx, 3 * dx};
    c.dx = dx;
    c.gravity = {0, 0, 0};
    c.cfl = 0.4;
    c.dt_max = period;
    for (auto& wall : c.walls) wall = {WallType::none, 0, 0};
    c.walls[0] = {WallType::sticky, 3, 0};  // nodes at x <= 0 hold the fixed end
    backend::OpenMP omp;
    if (options.threads > 0) omp.thread_count = options.threads;
    Simulation<double, backend::OpenMP> sim(c, omp);
    const int bar = sim.add_material({"bar", "fixed_corotated", rho, ElasticModuli::from_E_nu(E, 0)});
    const double h = dx / per_cell;
    sim.add_particles(bar, fill_box(c.domain_min, dx, per_cell, {0, 0, 0}, {L, dx, dx}), {0, 0, 0}, h * h * h);
    sim.enable(Attribute::x0);
    sim.prepare();
    ParticleView<double> pv = sim.particles();
    for (std::size_t p = 0; p < pv.n; ++p) pv.v[0][p] = v0 * std::sin(beta * pv.x0[0][p]);

    const auto t0 = std::chrono::steady_clock::now();
    double error = 0;
    while (sim.time() < period * (1 - 1e-12)) {
      sim.step(std::min(sim.next_dt(), period - sim.time()));
      pv = sim.particles();
      const double exact_end = amplitude * std::sin(w * sim.time());
      for (std::size_t p = 0; p < pv.n; ++p)
        if (pv.x0[0][p] > L - h) {  // the free end's layer of particles
          const double u = pv.x[0][p] - pv.x0[0][p];
          error = std::max(error, std::abs(u - exact_end * std::sin(beta * pv.x0[0][p])) / amplitude);
        }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double bound = finest_bound * double(1 << (levels - 1 - level));
    rows.push_back({"vibrating_bar", level, dx, per_cell, sim.steps(), error, bound, seconds});
  }
  return rows;
}

}  // namespace firn

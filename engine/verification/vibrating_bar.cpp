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
// bound at level l is 1% (the requirement at level 2) times dx / dx_2.
#include <algorithm>
#include <chrono>
#include <cmath>

#include "engine/backend_dispatch.hpp"
#include "engine/simulation.hpp"
#include "engine/verification/verification.hpp"

namespace firn {
namespace {

constexpr double kL = 25, kE = 100, kRho = 1, kV0 = 0.1;
constexpr double kFinestBound = 0.01;  // 1% of the amplitude at level 2
constexpr int kPerCell = 2;

template <class T, class Backend>
VerificationCase run_bar(int level, const VerificationMethod& method, const Backend& backend) {
  const double beta = M_PI / (2 * kL), w = beta * std::sqrt(kE / kRho), amplitude = kV0 / w, period = 2 * M_PI / w;
  const double dx = kL / (50 << level);
  SimulationConfig c;
  c.domain_min = {-2 * dx, -2 * dx, -2 * dx};
  c.domain_max = {kL + 4 * dx, 3 * dx, 3 * dx};
  c.dx = dx;
  c.gravity = {0, 0, 0};
  c.cfl = 0.4;
  c.dt_max = period;
  c.transfer = method.transfer;
  c.shape = method.shape;
  for (auto& wall : c.walls) wall = {WallType::none, 0, 0};
  c.walls[0] = {WallType::sticky, 3, 0};  // nodes at x <= 0 hold the fixed end
  Simulation<T, Backend> sim(c, backend);
  const int bar = sim.add_material({"bar", "fixed_corotated", kRho, ElasticModuli::from_E_nu(kE, 0)});
  const double h = dx / kPerCell;
  sim.add_particles(bar, fill_box(c.domain_min, dx, kPerCell, {0, 0, 0}, {kL, dx, dx}), {0, 0, 0}, h * h * h);
  sim.enable(Attribute::x0);
  sim.prepare();
  ParticleView<T> pv = sim.particles();
  for (std::size_t p = 0; p < pv.n; ++p) pv.v[0][p] = T(kV0 * std::sin(beta * pv.x0[0][p]));

  const auto t0 = std::chrono::steady_clock::now();
  double error = 0;
  while (sim.time() < period * (1 - 1e-12)) {
    sim.step(std::min(sim.next_dt(), period - sim.time()));
    pv = sim.particles();
    const double exact_end = amplitude * std::sin(w * sim.time());
    for (std::size_t p = 0; p < pv.n; ++p)
      if (pv.x0[0][p] > kL - h) {  // the free end's layer of particles
        const double u = double(pv.x[0][p]) - double(pv.x0[0][p]);
        error = std::max(error, std::abs(u - exact_end * std::sin(beta * pv.x0[0][p])) / amplitude);
      }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {dx, kPerCell, sim.particle_count(), sim.steps(), error, seconds};
}

}  // namespace

VerificationCase vibrating_bar_case(int level, const VerificationMethod& method, const VerificationOptions& options) {
  return with_precision(method, [&](auto scalar) {
    return with_backend(options.backend, options.threads, [&](const auto& backend) {
      return run_bar<decltype(scalar)>(level, method, backend);
    });
  });
}

std::vector<VerificationRow> verify_vibrating_bar(const VerificationOptions& options) {
  std::vector<VerificationRow> rows;
  for (int level = 0; level < 3; ++level) {
    const VerificationCase r = vibrating_bar_case(level, {}, options);
    const double bound = kFinestBound * double(1 << (2 - level));
    rows.push_back({"vibrating_bar", level, r.dx, r.particles_per_cell, r.steps, r.error, bound, r.seconds, r.particles});
  }
  return rows;
}

}  // namespace firn

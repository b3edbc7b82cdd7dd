// Axially vibrating bar (Bardenhagen 2002; Tielen et al. 2017; DESIGN.md section 6, problem 1):
// a bar of length L = 25 fixed at x = 0 and free at x = L, E = 100, rho = 1, in its first mode
// v(x, 0) = v0 sin(beta x) with v0 = 0.1, beta = pi / (2L). Exact solution
//   u(x, t) = v0 / w sin(w t) sin(beta x),  w = beta sqrt(E / rho).
// With nu = 0 the fixed-corotated model is exactly linear in nominal stress for uniaxial motion
// (P = E (F - 1)), so the exact solution is that of the linear wave equation in the reference
// configuration and any error is the method's. The error is the largest deviation of the free end's
// displacement from the exact one over one period, relative to the amplitude v0 / w.
// The fixed end is a clamped mirror plane (kernels/step/mirror_walls.hpp): the nodes beyond it carry
// the odd image of the bar's velocity, which for this uniaxial motion is the bar reflected, so the
// particles next to the end keep their whole B-spline support. With the plain sticky wall, whose
// nodes miss the particles beyond the end, the end's stress (the largest in the bar) cost an O(dx)
// error: 1.1% and 0.55% of the amplitude at levels 1 and 2. With the mirror (`firn study accuracy
// --problems vibrating_bar`, APIC, double, levels 0-3): 0.092%, 0.041%, 0.028%, 0.026% with
// quadratic B-splines, which stop converging at about 0.026%, and 0.088%, 0.023%, 0.0053%,
// 0.0016% with cubic ones (order 2). The quadratic floor is the particles' quadrature, not the end:
// with 4 particles per cell per axis instead of 2 it falls to 0.0068% and 0.0043% at levels 2
// and 3 (same command, kPerCell changed). The bounds are the measured errors with a margin; level
// 2's is issue 19's requirement, 0.05% of the amplitude.
#include <algorithm>
#include <chrono>
#include <cmath>

#include "engine/backend_dispatch.hpp"
#include "engine/simulation.hpp"
#include "engine/verification/verification.hpp"

namespace firn {
namespace {

constexpr double kL = 25, kE = 100, kRho = 1, kV0 = 0.1;
constexpr double kBounds[3] = {0.0012, 0.0006, 0.0005};  // per level, of the amplitude
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
  c.walls[0] = {WallType::sticky, 3, 0, true};  // the fixed end: a clamped mirror plane at x = 0
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
    rows.push_back(
        {"vibrating_bar", level, r.dx, r.particles_per_cell, r.steps, r.error, kBounds[level], r.seconds, r.particles});
  }
  return rows;
}

}  // namespace firn

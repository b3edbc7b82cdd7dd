// A small two-material problem for comparing backends: a nearly incompressible neo-Hookean jelly
// slab (so that the F-bar volume averaging runs too) hit by a fixed-corotated ball, 25 adaptive steps. Outcome: the state hash and positions by particle id.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/simulation.hpp"

namespace firn {

struct TwoBodiesOutcome {
  std::uint64_t hash;
  std::vector<float> positions;  // by particle id
};

template <class Backend>
TwoBodiesOutcome run_two_bodies(Backend backend, Transfer transfer, Shape shape) {
  SimulationConfig c;
  c.dx = 0.02;
  c.transfer = transfer;
  c.shape = shape;
  c.cfl = 0.5;
  Simulation<float, Backend> sim(c, backend);
  const double h = c.dx / 2, vol = h * h * h;
  const int jelly = sim.add_material({"jelly", "neo_hookean", 1000, ElasticModuli::from_E_nu(2e4, 0.49)});
  const int ball = sim.add_material({"ball", "fixed_corotated", 500, ElasticModuli::from_E_nu(5e4, 0.25)});
  sim.add_particles(jelly, fill_box(c.domain_min, c.dx, 2, {0.3, 0.08, 0.3}, {0.7, 0.3, 0.7}), {0, -0.5, 0}, vol);
  sim.add_particles(ball, fill_sphere(c.domain_min, c.dx, 2, {0.5, 0.5, 0.5}, 0.12), {0.5, -3, 0.2}, vol);
  for (int s = 0; s < 25; ++s) sim.step();
  const ParticleView<float> pv = sim.particles();
  TwoBodiesOutcome out{sim.state_hash(), std::vector<float>(3 * pv.n)};
  for (std::size_t p = 0; p < pv.n; ++p)
    for (int d = 0; d < 3; ++d) out.positions[3 * pv.id[p] + d] = pv.x[d][p];
  return out;
}

// The OpenMP backend's outcome at two threads (tests/test_backends.cpp), the reference of every
// other backend.
TwoBodiesOutcome openmp_two_bodies(Transfer transfer, Shape shape);

}  // namespace firn

// The reference speed problem `cube_drop` (DESIGN.md section 6): the unit cube with dx = 0.01,
// 2x2x2 particles per cell, a neo-Hookean cube of side 0.4 (E = 1e5 Pa, nu = 0.3,
// rho = 1000 kg/m^3) with lower corner (0.3, 0.05, 0.3) falling at 1 m/s under gravity 9.8 m/s^2,
// fixed dt = 1e-4 s, MLS/APIC with quadratic B-splines. The walls act on the nodes within 3 cells
// of each face and remove the velocity component into the wall, exactly as the yardstick
// (shared/bench/baseline_mpm.cpp) does, so both run the same physics.
// `domain_scale` enlarges the domain (same particles) to show that cost follows the particles;
// `material` replaces the cube's neo-Hookean solid (e.g. by a plastic snow, whose particles yield
// as the cube lands, to time the plastic path).
#pragma once

#include "engine/materials.hpp"
#include "engine/simulation.hpp"

namespace firn {

inline SimulationConfig cube_drop_config(double domain_scale = 1) {
  SimulationConfig c;
  c.domain_min = {0, 0, 0};
  c.domain_max = {domain_scale, domain_scale, domain_scale};
  c.dx = 0.01;
  c.gravity = {0, -9.8, 0};
  c.fixed_dt = 1e-4;
  c.transfer = Transfer::apic;
  c.shape = Shape::quadratic;
  for (auto& w : c.walls) w = {WallType::separate, 3, 0};
  return c;
}

inline MaterialInfo cube_drop_material() { return {"cube", "neo_hookean", 1000, ElasticModuli::from_E_nu(1e5, 0.3)}; }

template <class T, class Backend>
void add_cube_drop_particles(Simulation<T, Backend>& sim, const MaterialInfo& material = cube_drop_material()) {
  const double dx = sim.config().dx;
  const int m = sim.add_material(material);
  sim.add_particles(m, fill_box(sim.config().domain_min, dx, 2, {0.3, 0.05, 0.3}, {0.7, 0.45, 0.7}), {0, -1, 0},
                    dx * dx * dx / 8);
}

}  // namespace firn

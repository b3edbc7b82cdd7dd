// Randomised scenes for the stability study's bulk run: each a small, valid scene file (a few
// thousand particles, 50-300 steps) drawn from a seed, so that any scene can be made again from
// (seed, index) alone. Ranges (all physical):
//   grid        dx 2.5-5 mm, 20-32 cells per axis, 1 or 8 particles per cell, cfl 0.2-1,
//               transfer apic/pic/flip, quadratic or cubic B-splines, float (double one time in 8)
//   bodies      1-3 spheres, boxes or cylinders (any axis), 3-12 cells across, kept apart, at most
//               6,000 particles in all; speed 0-20 m/s in any direction, spin 0-50 rad/s
//   materials   one per body: neo_hookean, fixed_corotated, mooney_rivlin (G2 0-0.5 G),
//               hyperelastic_plastic (sigma_y0 50 Pa-10 kPa, K_h 0-20, n 0.02-1) or snow_stomakhin
//               (theta_c 0.01-0.05, theta_s 0.0025-0.01, xi 5-15); density 200-2000 kg/m^3,
//               E 1e4-1e7 Pa (log-uniform; snows 3e4-3e5), nu 0-0.49
//   colliders   0-2: a floor plane, a tilted plane, a fixed box or a spinning cylinder, sticky, slip
//               or separate, Coulomb friction 0-1
//   gravity     9.81 m/s^2 down, or 0-20 m/s^2 in a random direction (one time in 4)
#pragma once

#include <cstdint>
#include <string>

namespace firn::study {

struct RandomScene {
  std::string toml;
  long particles_estimate = 0;  // from the bodies' volumes
  long steps_estimate = 0;      // end_time / the first time step
  std::string summary;          // one line: bodies, materials, colliders
};

// The scene for (seed, index): the same text for the same pair on any machine (a SplitMix64
// stream, no std:: distributions, whose output the standard leaves to the library).
RandomScene random_scene(std::uint64_t seed, int index);

}  // namespace firn::study

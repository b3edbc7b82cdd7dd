// Parameters of the snow surface reconstruction. Lengths are relative: the sampling spacing h is
// the simulation's dx divided by grid_refinement, and the other lengths are multiples of h (or of a
// particle's spacing), so one set of defaults serves every scene resolution.
#pragma once

#include <cstdint>

namespace firn::surface {

enum class Smoothing { none, uniform_laplacian, taubin };

struct SurfaceParams {
  // Field (Zhu and Bridson 2005; thesis Eq. 4.10-4.14).
  double simulation_dx = 0;       // the simulation grid spacing (m); must be set
  double grid_refinement = 2;     // h = simulation_dx / grid_refinement (the thesis: twice as fine)
  double kernel_radius = 2;       // R in units of max(h, largest particle spacing cbrt(vol0)), so the
                                  // kernel always spans a few particles; capped at 6h (the sparse
                                  // grid's block size bounds it)
  double particle_radius = 0.5;   // r_i in units of the particle's rest spacing cbrt(vol0_i): half
                                  // of it, the radius of a particle that fills its own cell

  // Smoothing (thesis section 5.3: three iterations of uniform smoothing; Taubin 1995 as an option).
  Smoothing smoothing = Smoothing::uniform_laplacian;
  int smoothing_iterations = 3;
  double smoothing_lambda = 0.5;  // x <- x + lambda L(x), L the uniform Laplacian
  double taubin_mu = -0.53;       // the second, inflating Taubin step x <- x + mu L(x)

  // Vertex noise along the normal, seeded by the vertex's material coordinates.
  double noise_amplitude = 0.12;  // in units of h
  double noise_feature = 3;       // wavelength of the first octave, in units of h (each further octave halves it)
  int noise_octaves = 2;

  // Hexagonal surface hoar crystals on material-space sites (a jittered lattice of spacing
  // crystal_spacing h; a site carries a crystal with probability crystal_probability).
  bool crystals = true;
  double crystal_spacing = 1.5;     // in units of h
  double crystal_probability = 0.5;
  double crystal_radius = 0.35;     // largest hexagon circumradius, in units of h
  double crystal_height = 0.12;     // largest prism height, in units of h
  double crystal_tilt = 0.5;        // largest tilt of the prism axis from the normal (radians)

  std::uint32_t seed = 0x5eed;      // varies noise and crystals as a whole
};

}  // namespace firn::surface

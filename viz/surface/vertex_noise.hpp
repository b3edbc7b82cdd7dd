// Vertex noise (thesis section 5.3) anchored to material coordinates: every vertex moves along its
// normal by  amplitude * fractal_noise(x0_vertex / wavelength), where x0_vertex is the vertex's
// rest position (the kernel-weighted average of the nearby particles' x0, Eq. 4.11 applied to x0).
// A rigid motion of the particles leaves x0 unchanged, so it moves the grains with the snow
// instead of re-rolling them every frame.
#pragma once

#include <cstddef>

#include "viz/surface/material_noise.hpp"
#include "viz/surface/surface_mesh.hpp"
#include "viz/surface/surface_params.hpp"

namespace firn::surface {

// Needs mesh.normals; h is the sampling spacing (m).
template <class Backend>
void displace_by_material_noise(SurfaceMesh& mesh, const SurfaceParams& params, double h, const Backend& backend) {
  const float amplitude = float(params.noise_amplitude * h), inv_wavelength = float(1 / (params.noise_feature * h));
  backend.parallel_for("surface_noise", mesh.positions.size(), [&](std::size_t v) {
    const float offset = amplitude * fractal_noise(inv_wavelength * mesh.rest_positions[v], params.noise_octaves, params.seed);
    mesh.positions[v] = mesh.positions[v] + offset * mesh.normals[v];
  });
}

}  // namespace firn::surface

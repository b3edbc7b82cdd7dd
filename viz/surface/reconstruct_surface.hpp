// The snow surface of a set of particles, the entry point of viz/surface:
//   field (Zhu and Bridson, thesis Eq. 4.10-4.14) -> marching tetrahedra -> smoothing ->
//   vertex noise -> normals -> hoar crystals,
// reading the particles straight from engine memory (a const ParticleView) and running every
// parallel stage on the engine's backend. Deterministic: the same particles give the same mesh,
// bit for bit, for any thread count.
//
//   sim.enable(firn::Attribute::x0);   // once, before the first step: x0 = the rest positions
//   ...
//   firn::surface::SurfaceParams params;
//   params.simulation_dx = sim.config().dx;
//   const SurfaceMesh mesh = firn::surface::reconstruct_surface(sim.particles(), params, backend);
//   firn::surface::write_ply("meshes/00012.ply", mesh);
//
// Without x0 the current positions stand in for the material coordinates: the mesh is the same,
// but the noise and the crystals then swim through the snow as it moves.
#pragma once

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "kernels/particle_attributes.hpp"
#include "viz/surface/hoar_crystals.hpp"
#include "viz/surface/marching_tetrahedra.hpp"
#include "viz/surface/mesh_smoothing.hpp"
#include "viz/surface/scalar_field.hpp"
#include "viz/surface/surface_mesh.hpp"
#include "viz/surface/surface_params.hpp"
#include "viz/surface/vertex_fans.hpp"
#include "viz/surface/vertex_noise.hpp"

namespace firn::surface {

// Wall time of each stage of one reconstruction (s).
struct SurfaceTimings {
  double field = 0;      // bounds, binning, Eq. 4.10-4.14 on the sparse grid
  double marching = 0;   // marching tetrahedra
  double smoothing = 0;  // adjacency and smoothing
  double detail = 0;     // normals, vertex noise, normals again
  double crystals = 0;   // hoar crystal placement
  double total() const { return field + marching + smoothing + detail + crystals; }
};

template <class T, class Backend>
SurfaceMesh reconstruct_surface(const ParticleView<T>& particles, const SurfaceParams& params, const Backend& backend,
                                SurfaceTimings* timings = nullptr) {
  if (!(params.simulation_dx > 0 && params.grid_refinement > 0))
    throw std::invalid_argument("surface: simulation_dx and grid_refinement must be positive");
  const double h = params.simulation_dx / params.grid_refinement;
  SurfaceTimings local;
  SurfaceTimings& time = timings ? *timings : local;
  auto clock = std::chrono::steady_clock::now();
  auto lap = [&clock](double& seconds) {
    const auto now = std::chrono::steady_clock::now();
    seconds = std::chrono::duration<double>(now - clock).count();
    clock = now;
  };

  SurfaceMesh mesh;
  {
    const double kernel_radius = std::min(params.kernel_radius * std::max(h, largest_particle_spacing(particles, backend)),
                                          kMaxKernelRadius * h);
    const FieldGrid grid = compute_scalar_field(particles, h, kernel_radius, params.particle_radius, backend);
    lap(time.field);
    extract_isosurface(grid, mesh, backend);
  }  // the field grid is released here
  lap(time.marching);
  const VertexFans fans = build_vertex_fans(mesh.triangles, mesh.vertex_count());
  smooth_surface(mesh, fans, params, backend);
  lap(time.smoothing);
  compute_vertex_normals(mesh, fans, backend);
  if (params.noise_amplitude != 0 && params.noise_octaves > 0) {
    displace_by_material_noise(mesh, params, h, backend);
    compute_vertex_normals(mesh, fans, backend);
  }
  lap(time.detail);
  mesh.crystals = place_hoar_crystals(mesh, params, h);
  lap(time.crystals);
  return mesh;
}

}  // namespace firn::surface

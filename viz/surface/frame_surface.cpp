#include "viz/surface/frame_surface.hpp"

#include "viz/surface/reconstruct_surface.hpp"

namespace firn::surface {

SurfaceParams scene_surface_params(const SceneSpec& scene) {
  SurfaceParams params;
  params.simulation_dx = scene.config.dx;
  // Three spacings instead of the library's two: the lattice terraces of freshly filled bodies
  // (README, "Snow surfaces", known limits) are gone from frames and PLYs, at twice the field's cost.
  params.kernel_radius = 3;
  return params;
}

SurfaceMesh frame_surface(const FrameDescription& f, const SurfaceParams& params, const backend::OpenMP& omp) {
  return f.particles_float ? reconstruct_surface(*f.particles_float, params, omp)
                           : reconstruct_surface(*f.particles_double, params, omp);
}

}  // namespace firn::surface

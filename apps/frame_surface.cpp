#include "apps/frame_surface.hpp"

#include "viz/surface/reconstruct_surface.hpp"

namespace firn::app {

surface::SurfaceParams scene_surface_params(const SceneSpec& scene) {
  surface::SurfaceParams params;
  params.simulation_dx = scene.config.dx;
  // Three spacings instead of the library's two: the lattice terraces of freshly filled bodies
  // (README, "Snow surfaces", known limits) are gone from frames and PLYs, at twice the field's cost.
  params.kernel_radius = 3;
  return params;
}

surface::SurfaceMesh frame_surface(const FrameDescription& f, const surface::SurfaceParams& params,
                                   const backend::OpenMP& omp) {
  return f.particles_float ? surface::reconstruct_surface(*f.particles_float, params, omp)
                           : surface::reconstruct_surface(*f.particles_double, params, omp);
}

}  // namespace firn::app

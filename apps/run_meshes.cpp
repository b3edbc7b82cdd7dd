#include "apps/run_meshes.hpp"

#include <cstdio>

#include "engine/output/atomic_file.hpp"
#include "kernels/backend/openmp.hpp"
#include "viz/surface/ply_writer.hpp"
#include "viz/surface/reconstruct_surface.hpp"

namespace firn::app {

std::function<void(const FrameDescription&)> start_run_meshes(const SceneSpec& scene, const std::string& out_dir,
                                                              int threads) {
  make_directories(out_dir + "/meshes");
  surface::SurfaceParams params;
  params.simulation_dx = scene.config.dx;
  backend::OpenMP omp;
  if (threads > 0) omp.thread_count = threads;
  const std::string dir = out_dir + "/meshes/";
  return [params, omp, dir](const FrameDescription& f) {
    char name[32];
    std::snprintf(name, sizeof name, "%05d.ply", f.frame);
    const surface::SurfaceMesh mesh = f.particles_float ? surface::reconstruct_surface(*f.particles_float, params, omp)
                                                        : surface::reconstruct_surface(*f.particles_double, params, omp);
    surface::write_ply(dir + name, mesh);
  };
}

}  // namespace firn::app

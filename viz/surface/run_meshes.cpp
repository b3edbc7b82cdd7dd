#include "viz/surface/run_meshes.hpp"

#include <cstdio>

#include "engine/output/atomic_file.hpp"
#include "viz/surface/frame_surface.hpp"
#include "viz/surface/ply_writer.hpp"

namespace firn::surface {

std::function<void(const FrameDescription&)> start_run_meshes(const SceneSpec& scene, const std::string& out_dir,
                                                              int threads) {
  make_directories(out_dir + "/meshes");
  const SurfaceParams params = scene_surface_params(scene);
  const backend::OpenMP omp(threads);
  const std::string dir = out_dir + "/meshes/";
  return [params, omp, dir](const FrameDescription& f) {
    char name[32];
    std::snprintf(name, sizeof name, "%05d.ply", f.frame);
    write_ply(dir + name, frame_surface(f, params, omp));
  };
}

}  // namespace firn::surface

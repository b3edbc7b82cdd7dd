#include "viz/rerender_run.hpp"

#include <dirent.h>

#include <algorithm>

#include "engine/output/atomic_file.hpp"
#include "engine/output/frame_files.hpp"
#include "kernels/backend/openmp.hpp"
#include "viz/frame_pipeline.hpp"
#include "viz/scene_render_settings.hpp"
#include "viz/surface/frame_surface.hpp"
#include "viz/surface/reconstruct_surface.hpp"
#include "viz/vtp_frame.hpp"

namespace firn::viz {

std::vector<std::pair<int, std::string>> particle_files(const std::string& dir) {
  std::vector<std::pair<int, std::string>> files;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (const dirent* e = ::readdir(d)) {
      const std::string name = e->d_name;
      if (const int frame = particle_frame_number(name); frame >= 0) files.emplace_back(frame, dir + "/" + name);
    }
    ::closedir(d);
  }
  std::sort(files.begin(), files.end());
  return files;
}

RerenderResult rerender_run(const SceneSpec& scene, const std::vector<std::pair<int, std::string>>& files,
                            const RerenderOptions& options) {
  make_directories(options.dir + "/frames");
  FramePipeline pipeline(scene_render_settings(scene), parse_gl_api(options.gl),
                         {options.dir + "/frames", options.video ? options.dir + "/video.mp4" : "", scene.render.fps});
  const surface::SurfaceParams params = surface::scene_surface_params(scene);
  const backend::OpenMP omp;
  const VtpRestPositions rest =
      options.draw_surface ? read_vtp_rest_positions(files.front().second) : VtpRestPositions{};
  for (const auto& [frame, path] : files) {
    const VtpFrame particles(path, frame, scene, options.draw_surface ? &rest : nullptr);
    RenderFrame r = particles.render_frame();
    surface::SurfaceMesh mesh;
    if (options.draw_surface) {
      mesh = surface::reconstruct_surface(particles.particle_view(), params, omp);
      r.surface = &mesh;
    }
    pipeline.add(r);
  }
  pipeline.finish();
  return {files.size(), pipeline.gl_description()};
}

}  // namespace firn::viz

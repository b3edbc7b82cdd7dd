#include "apps/run_rendering.hpp"

#include <memory>

#include "apps/frame_surface.hpp"
#include "engine/output/atomic_file.hpp"
#include "viz/engine_frame.hpp"
#include "viz/frame_pipeline.hpp"
#include "viz/scene_render_settings.hpp"

namespace firn::app {

RunRendering start_run_rendering(const SceneSpec& scene, const std::string& out_dir, bool video, const std::string& gl,
                                 bool draw_surface, int threads) {
  make_directories(out_dir + "/frames");
  viz::FrameOutputs outputs{out_dir + "/frames", video ? out_dir + "/video.mp4" : "", scene.render.fps};
  auto pipeline = std::make_shared<viz::FramePipeline>(viz::scene_render_settings(scene), viz::parse_gl_api(gl), outputs);
  auto field = std::make_shared<std::vector<float>>();
  const std::string color_by = scene.render.color_by;
  RunRendering r;
  const surface::SurfaceParams params = scene_surface_params(scene);
  const backend::OpenMP omp(threads);
  r.on_frame = [pipeline, field, color_by, draw_surface, params, omp](const FrameDescription& f) {
    viz::RenderFrame frame = viz::engine_frame(f, color_by, *field);
    surface::SurfaceMesh mesh;
    if (draw_surface) {
      mesh = frame_surface(f, params, omp);
      frame.surface = &mesh;
    }
    pipeline->add(frame);
  };
  r.finish = [pipeline] { pipeline->finish(); };
  r.description = pipeline->gl_description();
  return r;
}

}  // namespace firn::app

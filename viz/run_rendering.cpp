#include "viz/run_rendering.hpp"

#include <memory>

#include "engine/output/atomic_file.hpp"
#include "viz/engine_frame.hpp"
#include "viz/frame_pipeline.hpp"
#include "viz/scene_render_settings.hpp"
#include "viz/surface/frame_surface.hpp"

namespace firn::viz {

RunRendering start_run_rendering(const SceneSpec& scene, const std::string& out_dir, bool video, const std::string& gl,
                                 bool draw_surface, int threads) {
  make_directories(out_dir + "/frames");
  FrameOutputs outputs{out_dir + "/frames", video ? out_dir + "/video.mp4" : "", scene.render.fps};
  auto pipeline = std::make_shared<FramePipeline>(scene_render_settings(scene), parse_gl_api(gl), outputs);
  auto field = std::make_shared<std::vector<float>>();
  const std::string color_by = scene.render.color_by;
  RunRendering r;
  const surface::SurfaceParams params = surface::scene_surface_params(scene);
  const backend::OpenMP omp(threads);
  r.on_frame = [pipeline, field, color_by, draw_surface, params, omp](const FrameDescription& f) {
    RenderFrame frame = engine_frame(f, color_by, *field);
    surface::SurfaceMesh mesh;
    if (draw_surface) {
      mesh = surface::frame_surface(f, params, omp);
      frame.surface = &mesh;
    }
    pipeline->add(frame);
  };
  r.finish = [pipeline] { pipeline->finish(); };
  r.description = pipeline->gl_description();
  return r;
}

}  // namespace firn::viz

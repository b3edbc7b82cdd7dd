#include "apps/run_rendering.hpp"

#include <memory>

#include "engine/output/atomic_file.hpp"
#include "viz/engine_frame.hpp"
#include "viz/frame_pipeline.hpp"
#include "viz/scene_render_settings.hpp"

namespace firn::app {

RunRendering start_run_rendering(const SceneSpec& scene, const std::string& out_dir, bool video, const std::string& gl) {
  make_directories(out_dir + "/frames");
  viz::FrameOutputs outputs{out_dir + "/frames", video ? out_dir + "/video.mp4" : "", scene.render.fps};
  auto pipeline = std::make_shared<viz::FramePipeline>(viz::scene_render_settings(scene), viz::parse_gl_api(gl), outputs);
  auto field = std::make_shared<std::vector<float>>();
  const std::string color_by = scene.render.color_by;
  RunRendering r;
  r.on_frame = [pipeline, field, color_by](const FrameDescription& f) {
    pipeline->add(viz::engine_frame(f, color_by, *field));
  };
  r.finish = [pipeline] { pipeline->finish(); };
  r.description = pipeline->gl_description();
  return r;
}

}  // namespace firn::app

// The renderer as `firn run` uses it: a frame hook for the run and a finish step, or an error
// when no OpenGL context can be made. A build without the renderer (no viz/ library) has a stand-in
// that says so (apps/render_unavailable.cpp).
#pragma once

#include <functional>
#include <string>

#include "engine/scene/frame_description.hpp"
#include "engine/scene/scene.hpp"

namespace firn::viz {

struct RunRendering {
  std::function<void(const FrameDescription&)> on_frame;
  std::function<void()> finish;  // waits for the PNG writer and closes the video
  std::string description;       // the OpenGL context, e.g. "egl surfaceless: OpenGL 4.5 ..."
};

// Frames go to OUT_DIR/frames/NNNNN.png, and with `video` to OUT_DIR/video.mp4. `gl`: "egl",
// "osmesa" or "" (EGL, falling back to OSMesa). With `draw_surface` each frame's snow surface is
// reconstructed (viz/surface/frame_surface.hpp, `threads` as for the run) and drawn instead of the
// particles. Throws std::runtime_error.
RunRendering start_run_rendering(const SceneSpec& scene, const std::string& out_dir, bool video, const std::string& gl,
                                 bool draw_surface, int threads);

}  // namespace firn::viz

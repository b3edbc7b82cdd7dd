// `firn render`: a finished run drawn again from its particle files (OUT_DIR/particles/NNNNN.vtp)
// with its scene's [render] settings, into OUT_DIR/frames/NNNNN.png (and OUT_DIR/video.mp4).
// Surfaces anchor their noise and crystals to the first frame's positions (vtp_frame.hpp).
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "engine/scene/scene.hpp"

namespace firn::viz {

// The NNNNN.vtp files of a folder, as (frame, path), in frame order.
std::vector<std::pair<int, std::string>> particle_files(const std::string& dir);

struct RerenderOptions {
  std::string dir;            // the run's output folder
  bool draw_surface = false;  // the reconstructed snow surface instead of the particles
  bool video = false;         // also encode OUT_DIR/video.mp4
  std::string gl;             // "egl", "osmesa" or "" (EGL, falling back to OSMesa)
};

struct RerenderResult {
  std::size_t frames = 0;
  std::string description;  // the OpenGL context
};

// Draws every file of `files` (particle_files of DIR/particles). Throws std::runtime_error.
RerenderResult rerender_run(const SceneSpec& scene, const std::vector<std::pair<int, std::string>>& files,
                            const RerenderOptions& options);

}  // namespace firn::viz

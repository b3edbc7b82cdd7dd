// `firn run --mesh`: the snow surface of every output frame reconstructed from the particles
// (thesis Eq. 4.10-4.14, marching tetrahedra, smoothing, noise and hoar crystals anchored to the
// rest positions) and written to OUT_DIR/meshes/NNNNN.ply.
#pragma once

#include <functional>
#include <string>

#include "engine/scene/frame_description.hpp"
#include "engine/scene/scene.hpp"

namespace firn::surface {

// A frame hook that writes the meshes; `threads` as for the run (0: all cores).
std::function<void(const FrameDescription&)> start_run_meshes(const SceneSpec& scene, const std::string& out_dir,
                                                              int threads);

}  // namespace firn::surface

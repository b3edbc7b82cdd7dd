// The snow surface of one output frame of a run, for `firn run --mesh` and `--render surface`:
// reconstructed from the engine's own particle columns, noise and crystals anchored to the rest
// positions x0 when the run keeps them (RunOptions::rest_positions).
#pragma once

#include "engine/scene/frame_description.hpp"
#include "engine/scene/scene.hpp"
#include "kernels/backend/openmp.hpp"
#include "viz/surface/surface_mesh.hpp"
#include "viz/surface/surface_params.hpp"

namespace firn::surface {

// The reconstruction's defaults at the scene's resolution, with kernel_radius = 3.
SurfaceParams scene_surface_params(const SceneSpec& scene);

SurfaceMesh frame_surface(const FrameDescription& f, const SurfaceParams& params, const backend::OpenMP& omp);

}  // namespace firn::surface

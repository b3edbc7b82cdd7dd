// One frame as the renderer takes it, from a running simulation (viz/engine_frame.hpp) or from a
// finished run's .vtp files (viz/vtp_frame.hpp), with its snow surface when drawn as one.
#pragma once

#include <vector>

#include "engine/scene/frame_description.hpp"
#include "viz/frame_renderer.hpp"
#include "viz/collider_sdf.hpp"

namespace firn::viz {

struct RenderFrame {
  int frame = 0;
  double time = 0;
  PositionColumns positions;
  std::vector<MaterialSpan> materials;  // consecutive particles of one material
  const float* field = nullptr;         // the colour field, one value per particle; null: by material
  std::vector<ColliderSolid> colliders;
  const surface::SurfaceMesh* surface = nullptr;  // drawn instead of the particles when set
};

}  // namespace firn::viz

// Draws one frame (DESIGN.md section 7): a shadow-map pass from the key light, then spheres,
// the snow surface, collider meshes and the ground into a floating-point framebuffer, then a full-screen pass that
// adds ambient occlusion and the background and writes 8-bit sRGB, read back top row first.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "viz/camera.hpp"
#include "viz/gl_context.hpp"
#include "engine/output/image.hpp"
#include "viz/render_settings.hpp"
#include "viz/sdf_mesh.hpp"
#include "viz/surface/surface_mesh.hpp"

namespace firn::viz {

// Particle positions as the engine stores them: three columns of float or double.
struct PositionColumns {
  const void* x[3] = {nullptr, nullptr, nullptr};
  bool doubles = false;
  std::size_t count = 0;
};

// A run of consecutive particles drawn in one colour (one material).
struct ColorRange {
  std::size_t begin, end;
  Rgb color;
};

// A collider's triangles and its material: the default matte grey-blue, dark rubber for a tire,
// asphalt for a ground plane (the road under the snow).
struct ColliderMesh {
  TriangleMesh mesh;
  Rgb color = {0.55f, 0.57f, 0.62f};
  float gloss = 0.04f;  // weight of the specular highlight
};

struct FrameScene {
  PositionColumns positions;
  std::vector<ColorRange> ranges;  // colour by material: used when `scalar` is null
  const float* scalar = nullptr;   // colour field, one value per particle
  double scalar_min = 0, scalar_max = 1;
  std::vector<ColliderMesh> colliders;
  // The snow surface with its hoar crystals, drawn in the snow material; null: none.
  const surface::SurfaceMesh* snow = nullptr;
};

class FrameRenderer {
 public:
  FrameRenderer(const GlContext& context, const RenderSettings& settings);
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;

  Image render(const FrameScene& scene, const Camera& camera);

 private:
  struct Resources;
  const Gl& gl_;
  RenderSettings settings_;
  std::unique_ptr<Resources> r_;
};

}  // namespace firn::viz

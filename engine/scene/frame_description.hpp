// What a run shows a frame hook (RunOptions::on_frame) at every output frame: const views of the
// particle columns, which particles belong to which material, the time and the colliders. It
// lets viz/ draw a run without scene_run depending on viz/.
#pragma once

#include <cstddef>
#include <vector>

#include "kernels/colliders.hpp"
#include "kernels/particle_attributes.hpp"

namespace firn {

struct MaterialSpan {
  std::size_t begin, end;  // particles [begin, end) at physical index
  int material;            // index into SceneSpec::materials
};

struct FrameDescription {
  int frame;
  double time;
  // Exactly one is set, by the run's precision. The columns are the engine's own arrays; they
  // stay valid until the hook returns.
  const ParticleView<float>* particles_float = nullptr;
  const ParticleView<double>* particles_double = nullptr;
  std::vector<MaterialSpan> materials;
  const std::vector<Collider<double>>* colliders = nullptr;
};

}  // namespace firn

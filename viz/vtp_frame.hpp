// A finished run's frame, read back from its particles/NNNNN.vtp, as the renderer takes it
// (for `firn render`): positions split into columns and sorted by material (the file is in
// particle-id order), the colour field from the file's arrays, the scene's colliders at the
// frame's time, and for a surface the particles with rest positions.
#pragma once

#include <string>
#include <vector>

#include "engine/scene/scene.hpp"
#include "kernels/particle_attributes.hpp"
#include "viz/render_frame.hpp"

namespace firn::viz {

// The .vtp files carry no rest positions, so a re-rendered surface anchors its noise and crystals
// to the run's first frame: the position of each particle id there. For a scene whose particles
// all exist from the start (no conveyor) these are the rest positions x0 the run itself would
// use; a particle missing from the first frame anchors to its current position.
struct VtpRestPositions {
  std::vector<double> x[3];  // by particle id
  std::vector<bool> known;   // by particle id
};
VtpRestPositions read_vtp_rest_positions(const std::string& first_frame_path);

class VtpFrame {
 public:
  // Throws std::runtime_error when the file cannot be read or lacks the colour field. With
  // `rest`, particle_view() carries rest positions.
  VtpFrame(const std::string& path, int frame, const SceneSpec& scene, const VtpRestPositions* rest = nullptr);
  // Valid while this object lives.
  RenderFrame render_frame() const;
  // The particles as viz/surface reads them: positions, rest positions (with `rest`; else null)
  // and rest volumes (the fill lattice's cell, (dx / per_axis)^3). Valid while this object lives.
  ParticleView<double> particle_view() const;

 private:
  std::vector<double> x_[3], x0_[3], vol0_;
  std::vector<float> field_;
  std::vector<MaterialSpan> materials_;
  int frame_;
  double time_;
  const SceneSpec& scene_;
};

}  // namespace firn::viz

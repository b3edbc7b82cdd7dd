// A finished run's frame, read back from its particles/NNNNN.vtp, as the renderer takes it
// (for `firn render`): positions split into columns and sorted by material (the file is in
// particle-id order), the colour field from the file's arrays, and the scene's colliders at the
// frame's time.
#pragma once

#include <string>
#include <vector>

#include "engine/scene/scene.hpp"
#include "viz/render_frame.hpp"

namespace firn::viz {

class VtpFrame {
 public:
  // Throws std::runtime_error when the file cannot be read or lacks the colour field.
  VtpFrame(const std::string& path, int frame, const SceneSpec& scene);
  // Valid while this object lives.
  RenderFrame render_frame() const;

 private:
  std::vector<double> x_[3];
  std::vector<float> field_;
  std::vector<MaterialSpan> materials_;
  int frame_;
  double time_;
  const SceneSpec& scene_;
};

}  // namespace firn::viz

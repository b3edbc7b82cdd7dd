// Renders a sequence of frames and hands them to the frame writer: the camera rig's view of each
// frame (viz/camera.hpp: following the particles and bounded colliders smoothly, or fixed), a colour
// range that only widens, collider meshes from their signed distances, the snow surface where the
// frame has one, the legend, then PNG and video off this thread.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "viz/camera.hpp"
#include "viz/frame_renderer.hpp"
#include "viz/frame_writer.hpp"
#include "viz/gl_context.hpp"
#include "viz/render_frame.hpp"
#include "viz/render_settings.hpp"

namespace firn::viz {

struct FrameOutputs {
  std::string png_dir;     // frames/NNNNN.png go here; "" for none
  std::string video_path;  // "" for no video
  int fps = 30;
};

class FramePipeline {
 public:
  // Creates the GL context (throws std::runtime_error when none can be made) and starts ffmpeg.
  FramePipeline(const RenderSettings& settings, GlApi api, const FrameOutputs& outputs);
  ~FramePipeline();

  void add(const RenderFrame& frame);
  // Waits for the writer and closes the video; throws if writing failed.
  void finish();
  std::string gl_description() const { return context_->description(); }

 private:
  RenderSettings settings_;
  std::unique_ptr<GlContext> context_;
  std::unique_ptr<FrameRenderer> renderer_;
  std::unique_ptr<FrameWriter> writer_;
  CameraRig camera_rig_;
  std::vector<std::optional<TriangleMesh>> body_meshes_;  // per collider, in its own frame (made once)
  double field_min_ = 0, field_max_ = 0;
  bool field_seen_ = false;
};

// The bounding box of the particle positions.
Bounds position_bounds(const PositionColumns& positions);

}  // namespace firn::viz

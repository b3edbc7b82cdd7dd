// The view of a run: a perspective camera from a preset ([render] camera) or from explicit
// settings, framing the particles and the bounded colliders, and following them from frame to frame
// without jumping; and the orthographic light camera of the shadow map.
#pragma once

#include <functional>
#include <optional>

#include "viz/mat4.hpp"
#include "viz/render_settings.hpp"

namespace firn::viz {

struct Bounds {
  Vec3 lo = {1e300, 1e300, 1e300}, hi = {-1e300, -1e300, -1e300};
  bool empty() const { return lo[0] > hi[0]; }
  void add(const Vec3& p) {
    for (std::size_t d = 0; d < 3; ++d) lo[d] = std::min(lo[d], p[d]), hi[d] = std::max(hi[d], p[d]);
  }
  void add_box(const Bounds& b) {
    if (!b.empty()) add(b.lo), add(b.hi);
  }
};

struct Camera {
  Vec3 eye, target, up = {0, 1, 0};
  double fov, aspect, near, far;
  double radius;  // of the region of interest around target
  Vec3 light_direction;  // the direction the key light travels
  Mat4 view() const { return look_at(eye, target, up); }
  Mat4 projection() const { return perspective(fov, aspect, near, far); }
};

// "auto", "side", "three_quarter", "contact" or "top"; throws std::invalid_argument otherwise.
CameraPreset parse_camera_preset(const std::string& name);

// What a frame shows: `subject`, the box of the particles and of the bounded colliders; `focus`,
// the first bounded collider's box (the contact preset looks at its lowest point); `solid`, whether
// a point lies inside a collider (the automatic preset turns so none blocks its line of sight).
struct FrameSubject {
  Bounds subject;
  std::optional<Bounds> focus;
  std::function<bool(const Vec3&)> solid;
};

// One camera for one frame: the preset's view of the subject (or settings.camera_position and
// camera_target where given), far enough that the region's sphere fits the narrower field of view
// with a margin.
Camera frame_camera(const RenderSettings& settings, const Bounds& subject,
                    const std::function<bool(const Vec3&)>& solid = nullptr);

// The cameras of a sequence of frames. Without camera_follow the first frame's camera stays. With
// it, the region of interest moves a third of the way to each new frame's (so the view glides), but
// never leaves any of the new region outside: it widens at once and narrows slowly. The preset's
// direction is chosen on the first frame and kept.
class CameraRig {
 public:
  explicit CameraRig(const RenderSettings& settings) : settings_(settings) {}
  Camera next(const FrameSubject& frame);

 private:
  RenderSettings settings_;
  std::optional<Vec3> direction_;    // from the target to the eye, unit
  std::optional<Vec3> centre_;       // of the region of interest
  double radius_ = 0;
  std::optional<Camera> first_;
};

struct LightCamera {
  Mat4 view, projection;
  double half_width;  // of the square the shadow map covers (m)
};

// An orthographic camera along the camera's light direction that covers the camera's region.
LightCamera light_camera(const Camera& camera);

}  // namespace firn::viz

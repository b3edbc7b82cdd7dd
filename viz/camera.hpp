// The view of a run: a perspective camera from the settings or framed automatically around a
// bounding box, and the orthographic light camera of the shadow map.
#pragma once

#include <functional>

#include "viz/mat4.hpp"
#include "viz/render_settings.hpp"

namespace firn::viz {

struct Bounds {
  Vec3 lo = {1e300, 1e300, 1e300}, hi = {-1e300, -1e300, -1e300};
  bool empty() const { return lo[0] > hi[0]; }
  void add(const Vec3& p) {
    for (std::size_t d = 0; d < 3; ++d) lo[d] = std::min(lo[d], p[d]), hi[d] = std::max(hi[d], p[d]);
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

// Looks at settings.camera_target (default: the centre of `bounds`) from settings.camera_position
// (default: above and to one side, far enough that the bounds' sphere fits the narrower field of
// view with a margin: in front and to the right, or the first of the mirrored directions whose
// line of sight `solid` (a point inside a collider) does not block). `bounds` is the particles'
// box when the run starts.
Camera frame_camera(const RenderSettings& settings, const Bounds& bounds,
                    const std::function<bool(const Vec3&)>& solid = nullptr);

struct LightCamera {
  Mat4 view, projection;
  double half_width;  // of the square the shadow map covers (m)
};

// An orthographic camera along the camera's light direction that covers the camera's region.
LightCamera light_camera(const Camera& camera);

}  // namespace firn::viz

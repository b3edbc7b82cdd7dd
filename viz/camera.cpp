#include "viz/camera.hpp"

#include <algorithm>
#include <cmath>

namespace firn::viz {

Camera frame_camera(const RenderSettings& s, const Bounds& bounds, const std::function<bool(const Vec3&)>& solid) {
  Camera c;
  const Bounds b = bounds.empty() ? Bounds{s.domain_min, s.domain_max} : bounds;
  const Vec3 centre = 0.5 * (b.lo + b.hi);
  const double box_radius = std::max(0.5 * length(b.hi - b.lo), 1e-6);
  c.target = s.camera_target.value_or(centre);
  c.fov = s.fov;
  c.aspect = double(s.width) / s.height;
  const double narrow = std::min(s.fov, 2 * std::atan(std::tan(s.fov / 2) * c.aspect));
  if (s.camera_position) {
    c.eye = *s.camera_position;
  } else {
    const double distance = 1.15 * box_radius / std::sin(narrow / 2);
    auto clear = [&](const Vec3& eye) {
      for (int i = 1; solid && i <= 32; ++i)
        if (solid(c.target + (i / 32.0) * (eye - c.target))) return false;
      return true;
    };
    const Vec3 directions[] = {{0.35, 0.42, 1}, {-0.35, 0.42, 1}, {0.35, 0.42, -1}, {-0.35, 0.42, -1},
                               {1, 0.42, 0.35}, {-1, 0.42, 0.35}, {1, 0.42, -0.35}, {-1, 0.42, -0.35}};
    c.eye = c.target + distance * normalize(directions[0]);
    for (const Vec3& d : directions)
      if (clear(c.target + distance * normalize(d))) {
        c.eye = c.target + distance * normalize(d);
        break;
      }
  }
  if (std::abs(dot(normalize(c.target - c.eye), c.up)) > 0.999) c.up = {0, 0, -1};
  // By default the light comes from above, over the camera's shoulder (on its side of the target
  // along x and z), so what the camera sees is lit.
  const Vec3 side = c.eye - c.target;
  c.light_direction = s.light_direction.value_or(Vec3{side[0] >= 0 ? -0.45 : 0.45, -1.0, side[2] >= 0 ? -0.55 : 0.55});
  c.radius = box_radius;
  const double distance = length(c.eye - c.target);
  c.near = std::max(0.02 * distance, distance - 3 * box_radius);
  c.far = distance + 40 * box_radius;
  return c;
}

LightCamera light_camera(const Camera& c) {
  const Vec3 towards_light = -1.0 * normalize(c.light_direction);
  const double r = 1.5 * c.radius;
  Vec3 up = {0, 1, 0};
  if (std::abs(dot(towards_light, up)) > 0.99) up = {0, 0, 1};
  LightCamera l;
  l.view = look_at(c.target + 4 * r * towards_light, c.target, up);
  l.projection = orthographic(-r, r, -r, r, 0.5 * r, 8 * r);
  l.half_width = r;
  return l;
}

}  // namespace firn::viz

#include "viz/camera.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace firn::viz {
namespace {

struct Region {
  Vec3 centre;
  double radius;
};

// The sphere around the subject, or around the focus's lowest point for the contact preset (a
// third of the focus's height: the contact patch and the tread entering the snow).
Region region_of(const RenderSettings& s, const FrameSubject& f) {
  if (s.camera == CameraPreset::contact && f.focus) {
    const Bounds& b = *f.focus;
    const double height = b.hi[1] - b.lo[1];
    return {{0.5 * (b.lo[0] + b.hi[0]), b.lo[1] + 0.1 * height, 0.5 * (b.lo[2] + b.hi[2])}, 0.35 * height};
  }
  const Bounds b = f.subject.empty() ? Bounds{s.domain_min, s.domain_max} : f.subject;
  return {0.5 * (b.lo + b.hi), std::max(0.5 * length(b.hi - b.lo), 1e-6)};
}

// From the target toward the eye, per preset. The automatic one: in front and to the right, above,
// or the first of the mirrored directions whose line of sight no collider blocks. The contact one
// looks from +x, the side a tire rolls toward over a conveyor's snow (engine/scene/conveyor.hpp).
Vec3 preset_direction(const RenderSettings& s, const Region& r, const std::function<bool(const Vec3&)>& solid,
                      double distance) {
  switch (s.camera) {
    case CameraPreset::side: return normalize(Vec3{0, 0.12, 1});
    case CameraPreset::three_quarter: return normalize(Vec3{0.8, 0.5, 1});
    case CameraPreset::contact: return normalize(Vec3{1, 0.3, 0.55});
    case CameraPreset::top: return Vec3{0, 1, 0};
    case CameraPreset::automatic: break;
  }
  const Vec3 target = s.camera_target.value_or(r.centre);
  auto clear = [&](const Vec3& d) {
    for (int i = 1; solid && i <= 32; ++i)
      if (solid(target + (i / 32.0 * distance) * d)) return false;
    return true;
  };
  const Vec3 directions[] = {{0.35, 0.42, 1}, {-0.35, 0.42, 1}, {0.35, 0.42, -1}, {-0.35, 0.42, -1},
                             {1, 0.42, 0.35}, {-1, 0.42, 0.35}, {1, 0.42, -0.35}, {-1, 0.42, -0.35}};
  for (const Vec3& d : directions)
    if (clear(normalize(d))) return normalize(d);
  return normalize(directions[0]);
}

double framing_distance(const RenderSettings& s, double radius) {
  const double aspect = double(s.width) / s.height;
  const double narrow = std::min(s.fov, 2 * std::atan(std::tan(s.fov / 2) * aspect));
  return 1.15 * radius / std::sin(narrow / 2);
}

Camera place_camera(const RenderSettings& s, const Region& r, const Vec3& direction) {
  Camera c;
  c.target = s.camera_target.value_or(r.centre);
  c.fov = s.fov;
  c.aspect = double(s.width) / s.height;
  c.eye = s.camera_position.value_or(c.target + framing_distance(s, r.radius) * direction);
  if (std::abs(dot(normalize(c.target - c.eye), c.up)) > 0.999) c.up = {0, 0, -1};  // looking down: -z is up
  // By default the light comes from above, over the camera's shoulder (on its side of the target
  // along x and z), so what the camera sees is lit.
  const Vec3 side = c.eye - c.target;
  c.light_direction = s.light_direction.value_or(Vec3{side[0] >= 0 ? -0.45 : 0.45, -1.0, side[2] >= 0 ? -0.55 : 0.55});
  c.radius = r.radius;
  const double distance = length(c.eye - c.target);
  c.near = std::max(0.02 * distance, distance - 3 * r.radius);
  c.far = distance + 40 * r.radius;
  return c;
}

}  // namespace

CameraPreset parse_camera_preset(const std::string& name) {
  if (name == "auto") return CameraPreset::automatic;
  if (name == "side") return CameraPreset::side;
  if (name == "three_quarter") return CameraPreset::three_quarter;
  if (name == "contact") return CameraPreset::contact;
  if (name == "top") return CameraPreset::top;
  throw std::invalid_argument("unknown camera preset \"" + name + "\" (auto, side, three_quarter, contact or top)");
}

Camera frame_camera(const RenderSettings& s, const Bounds& subject, const std::function<bool(const Vec3&)>& solid) {
  const FrameSubject f{subject, std::nullopt, solid};
  const Region r = region_of(s, f);
  return place_camera(s, r, preset_direction(s, r, solid, framing_distance(s, r.radius)));
}

Camera CameraRig::next(const FrameSubject& f) {
  const RenderSettings& s = settings_;
  const Region want = region_of(s, f);
  if (!direction_) direction_ = preset_direction(s, want, f.solid, framing_distance(s, want.radius));
  if (!s.camera_follow || (s.camera_position && s.camera_target)) {
    if (!first_) first_ = place_camera(s, want, *direction_);
    return *first_;
  }
  if (!centre_) {
    centre_ = want.centre, radius_ = want.radius;
  } else {
    constexpr double kGlide = 1.0 / 3;
    *centre_ = *centre_ + kGlide * (want.centre - *centre_);
    radius_ = std::max(radius_ + kGlide * (want.radius - radius_), length(want.centre - *centre_) + want.radius);
  }
  return place_camera(s, {*centre_, radius_}, *direction_);
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

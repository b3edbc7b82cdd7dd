#include "engine/scene/scene_builder.hpp"

#include <cmath>

#include "engine/pressure_surface.hpp"
#include "engine/splitmix64.hpp"
#include "engine/tread_patterns.hpp"

namespace firn {
namespace {

// A rotation whose body y axis is the unit vector n (the other two axes complete a right-handed frame).
void frame_with_y_axis(const Point& n, double r[9]) {
  const Vec3<double> y = {{n[0], n[1], n[2]}};
  const Vec3<double> a = std::fabs(n[0]) < 0.9 ? Vec3<double>{{1, 0, 0}} : Vec3<double>{{0, 0, 1}};
  const Vec3<double> c = cross(a, y), x = (1 / norm(c)) * c, z = cross(x, y);
  for (int i = 0; i < 3; ++i) {
    r[3 * i + 0] = x[i];
    r[3 * i + 1] = y[i];
    r[3 * i + 2] = z[i];
  }
}

}  // namespace

ColliderBody collider_body(const ColliderSpec& c) {
  Collider<double> k;
  k.boundary = c.boundary;
  k.friction = c.friction;
  k.contact = c.contact;
  for (int d = 0; d < 3; ++d) {
    k.velocity[d] = c.velocity[d];
    k.angular_velocity[d] = c.angular_velocity[d];
  }
  switch (c.kind) {
    case ColliderSpec::Kind::plane:
      k.shape = ColliderShape::plane;
      for (int d = 0; d < 3; ++d) k.center[d] = c.point[d];
      frame_with_y_axis(c.normal, k.rotation);
      break;
    case ColliderSpec::Kind::box:
      k.shape = ColliderShape::box;
      for (int d = 0; d < 3; ++d) {
        k.center[d] = 0.5 * (c.min[d] + c.max[d]);
        k.half[d] = 0.5 * (c.max[d] - c.min[d]);
      }
      break;
    case ColliderSpec::Kind::cylinder: {
      k.shape = ColliderShape::cylinder;
      for (int d = 0; d < 3; ++d) k.center[d] = c.center[d];
      k.radius = c.radius;
      k.half[2] = 0.5 * c.length;
      // Body axes (x, y, z) = a cyclic permutation of the world axes ending with the cylinder's axis.
      for (int i = 0; i < 9; ++i) k.rotation[i] = 0;
      for (int b = 0; b < 3; ++b) k.rotation[3 * ((c.axis + 1 + b) % 3) + b] = 1;
      break;
    }
  }
  ColliderBody body(k);
  body.penalty_stiffness = c.penalty_stiffness;
  return body;
}

Collider<double> tire_solid(const TireSpec& t) {
  Collider<double> k;
  k.shape = ColliderShape::tire;
  k.boundary = t.boundary;
  k.friction = t.friction;
  k.tire = make_tire_shape(t.tread, t.radius, t.width, t.tread_depth, t.pitches);
  k.tire.shoulder = t.shoulder;
  for (int d = 0; d < 3; ++d) k.center[d] = t.center[d];
  k.angular_velocity[2] = -t.speed / t.radius;  // the tread at the bottom moves toward -x
  return k;
}

ColliderBody tire_body(const TireSpec& t) {
  Collider<double> k = tire_solid(t);
  if (t.rubber) {  // the rim under the carcass: a sticky cylinder along z, turning as the tire
    k.shape = ColliderShape::cylinder;
    k.radius = t.rim_radius;
    k.half[2] = 0.5 * t.width;
    k.boundary = WallType::sticky;
  } else {
    k.contact = t.contact;
  }
  ColliderBody body(k);
  body.penalty_stiffness = t.penalty_stiffness;
  if (t.loaded) {
    body.motion = ColliderBody::Motion::loaded_axle;
    body.mass = t.mass;
    body.load = t.load;
  }
  if (t.free_spin) {
    body.free_spin = true;
    body.inertia = t.inertia;
  }
  return body;
}

ColliderBody ground_body(const ConveyorSpec& c, double dx) {
  Collider<double> k;  // a plane with body axes = world axes: the solid y <= ground + dx / 2
  k.boundary = c.boundary;
  k.friction = Friction<double>{FrictionLaw::coulomb, c.friction};
  k.center[1] = c.ground + dx / 2;
  k.velocity[0] = -c.speed;
  return ColliderBody(k);
}

std::vector<Collider<double>> scene_colliders_at(const SceneSpec& scene, double time) {
  std::vector<ColliderBody> bodies;
  for (const ColliderSpec& c : scene.colliders) bodies.push_back(collider_body(c));
  if (scene.tire) bodies.push_back(tire_body(*scene.tire));
  if (scene.conveyor) bodies.push_back(ground_body(*scene.conveyor, scene.config.dx));
  std::vector<Collider<double>> out;
  for (ColliderBody& b : bodies) {
    b.motion = ColliderBody::Motion::prescribed;
    b.free_spin = false;
    b.advance(time);  // one step of constant motion is exact
    out.push_back(b.collider);
  }
  return out;
}

RubberTireFill fill_rubber_tire(const SceneSpec& scene) {
  const TireSpec& t = *scene.tire;
  const Collider<double> solid = tire_solid(t);
  const double wall_z = 0.5 * t.width - t.sidewall;  // a cavity's inner faces, |z - centre| = wall_z
  const bool cavity = t.rim_radius < t.carcass_radius;
  auto radius_at = [&](const Point& p) { return std::hypot(p[0] - t.center[0], p[1] - t.center[1]); };
  const Point lo = {t.center[0] - t.radius, t.center[1] - t.radius, t.center[2] - 0.5 * t.width};
  const Point hi = {t.center[0] + t.radius, t.center[1] + t.radius, t.center[2] + 0.5 * t.width};
  RubberTireFill out;
  out.positions = fill_lattice(scene.config.domain_min, scene.config.dx, scene.per_axis(), lo, hi, [&](const Point& p) {
    double n[3];
    if (!(solid.distance(p.data(), n) < 0)) return false;
    const double r = radius_at(p);
    if (r >= t.carcass_radius) return true;  // tread and carcass
    return cavity && r >= t.rim_radius && std::fabs(p[2] - t.center[2]) >= wall_z;  // a sidewall
  });
  if (out.positions.empty())
    throw SceneError(scene.path + ": [tire] the rubber tire has no particles (finer dx needed)");
  const std::size_t n = out.positions.size();
  const double w = solid.angular_velocity[2];
  out.velocities.resize(n);
  out.part.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Point& p = out.positions[i];
    out.velocities[i] = {-w * (p[1] - t.center[1]), w * (p[0] - t.center[0]), 0};
    const double r = radius_at(p);
    out.part[i] = r < t.carcass_radius                   ? TirePart::sidewall
                  : r < t.radius - t.tread_depth ? TirePart::carcass
                                                 : TirePart::tread;
  }
  if (!(t.pressure > 0)) {
    out.areas.assign(n, Point{0, 0, 0});
    return out;
  }
  out.areas = inner_cylinder_areas(out.positions, t.center, t.carcass_radius, wall_z, scene.config.dx / scene.per_axis());
  if (out.areas.empty()) throw SceneError(scene.path + ": [tire] the air cavity has no surface particles (finer dx needed)");
  return out;
}

void fill_body(const SceneSpec& scene, std::size_t index, std::vector<Point>& positions, std::vector<Point>& velocities) {
  const BodySpec& body = scene.bodies[index];
  Point lo, hi;
  body.shape.bounds(lo, hi);
  positions = fill_lattice(scene.config.domain_min, scene.config.dx, scene.per_axis(), lo, hi, [&](const Point& p) {
    if (!body.shape.contains(p)) return false;
    for (std::size_t e = 0; e < index; ++e)
      if (scene.bodies[e].shape.contains(p)) return false;
    return true;
  });
  if (positions.empty())
    throw SceneError(body.location + ": body '" + body.name +
                     "' has no particles (smaller than the particle spacing, or inside earlier bodies)");
  if (body.jitter > 0) {
    SplitMix64 rng{body.seed};
    const double amplitude = body.jitter * scene.config.dx / scene.per_axis();
    for (Point& p : positions)
      for (int d = 0; d < 3; ++d) p[d] += amplitude * (rng.uniform() - 0.5);
  }
  Point c = {0, 0, 0};
  for (const Point& p : positions)
    for (int d = 0; d < 3; ++d) c[d] += p[d] / double(positions.size());
  const Point& w = body.angular_velocity;
  velocities.resize(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Point r = {positions[i][0] - c[0], positions[i][1] - c[1], positions[i][2] - c[2]};
    velocities[i] = {body.velocity[0] + w[1] * r[2] - w[2] * r[1], body.velocity[1] + w[2] * r[0] - w[0] * r[2],
                     body.velocity[2] + w[0] * r[1] - w[1] * r[0]};
  }
}

}  // namespace firn

// Turns a validated scene into a Simulation: materials, bodies filled on the particle lattice in
// file order (a body never takes a lattice site inside an earlier body), colliders and loads.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/scene/scene.hpp"
#include "engine/scene/scene_reader.hpp"
#include "engine/simulation.hpp"

namespace firn {

// Lattice sites of body `index` of the scene, with their initial velocities (translation plus
// rotation about the body's centre of mass) and the optional seeded jitter. Throws SceneError
// for a body that gets no particles.
void fill_body(const SceneSpec& scene, std::size_t index, std::vector<Point>& positions, std::vector<Point>& velocities);

// Rest volume of one particle: the lattice cell (dx / per_axis)^3.
inline double particle_volume(const SceneSpec& scene) {
  const double h = scene.config.dx / scene.per_axis();
  return h * h * h;
}

// The engine's collider for a scene's [[colliders]] entry.
template <class T>
Collider<T> make_collider(const ColliderSpec& c) {
  Collider<T> k;
  k.shape = c.kind == ColliderSpec::Kind::plane ? ColliderShape::plane : ColliderShape::box;
  k.boundary = c.boundary;
  k.friction = T(c.friction);
  for (int d = 0; d < 3; ++d) {
    k.point[d] = T(c.point[d]);
    k.normal[d] = T(c.normal[d]);
    k.min[d] = T(c.min[d]);
    k.max[d] = T(c.max[d]);
    k.velocity[d] = T(c.velocity[d]);
  }
  return k;
}

template <class T, class Backend>
void build_scene(const SceneSpec& scene, Simulation<T, Backend>& sim) {
  for (const MaterialInfo& m : scene.materials) sim.add_material(m);
  std::vector<Point> positions, velocities;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    fill_body(scene, b, positions, velocities);
    sim.add_particles(scene.bodies[b].material, positions, velocities, particle_volume(scene));
  }
  for (const ColliderSpec& c : scene.colliders) sim.add_collider(make_collider<T>(c));
  for (const LoadSpec& l : scene.loads) sim.add_load(l.region_min, l.region_max, l.force, l.ramp_time);
}

}  // namespace firn

// Turns a validated scene into a Simulation: materials, bodies filled on the particle lattice in
// file order (a body never takes a lattice site inside an earlier body), colliders, the tire, the
// conveyor's ground and snow bed, and loads.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "engine/collider_body.hpp"
#include "engine/scene/conveyor.hpp"
#include "engine/scene/scene.hpp"
#include "engine/scene/scene_materials.hpp"
#include "engine/scene/scene_reader.hpp"
#include "engine/simulation.hpp"

namespace firn {

// Lattice sites of body `index` of the scene, with their initial velocities (translation plus
// rotation about the body's centre of mass) and the optional seeded jitter. Throws SceneError
// for a body that gets no particles.
void fill_body(const SceneSpec& scene, std::size_t index, std::vector<Point>& positions, std::vector<Point>& velocities);

// The lattice sites of a rubber tire (inside its tread's solid, outside its rim; with an air cavity,
// the tread and carcass above it and the two sidewalls beside it) with their velocities, turning
// with the tire at its starting rate.
enum class TirePart : char { tread, carcass, sidewall };
struct RubberTireFill {
  std::vector<Point> positions, velocities;
  std::vector<TirePart> part;  // which part of the tire each site is
  std::vector<Point> areas;   // rest area vector N dA on the carcass's inner surface (inflated), else 0
};
RubberTireFill fill_rubber_tire(const SceneSpec& scene);

// The engine's colliders for a scene's [[colliders]] entry, its [tire] and its [conveyor] ground.
ColliderBody collider_body(const ColliderSpec& spec);
// The tire's solid (its tread's signed distance) at its starting pose, turning at its starting
// rate; its collider when rigid, the rubber's extent when rubber (whose collider is the rim).
Collider<double> tire_solid(const TireSpec& spec);
ColliderBody tire_body(const TireSpec& spec);
// The belt's plane lies half a cell above `ground`, so that the node row nearest the bed's lowest
// particles is the belt's whatever the ground's height: a node on a collider's surface is outside
// (kernels/colliders.hpp), and through the row a cell further down the belt would hold the bed by
// a weight of 0 to 0.03 per particle, and the bed would sink and drag (tests/test_conveyor.cpp).
ColliderBody ground_body(const ConveyorSpec& spec, double dx);

// Every collider of the scene (its [[colliders]], the tire, the conveyor's ground) where it is at
// `time`: exact for prescribed motion; a loaded axle is shown at its starting height, a free spin
// turning at its starting rate.
std::vector<Collider<double>> scene_colliders_at(const SceneSpec& scene, double time);

// Which of the simulation's colliders the scene's tire (a rubber tire's rim), conveyor ground and a
// rubber tire's road are (-1: none), and the engine materials of a rubber tire's parts.
struct BuiltScene {
  int tire = -1;
  int ground = -1;
  std::pair<int, int> rubber{0, 0};    // a rubber tire's tread (with parts of its material): first material, count
  std::pair<int, int> carcass{0, 0};   // its carcass band when of another material (count 0: none)
  std::pair<int, int> sidewall{0, 0};  // its sidewalls when of a material of neither (count 0: none)
  int road = -1;  // a rubber tire's road: the first plane among [[colliders]] (-1: none)
};

// Rest volume of one particle: the lattice cell (dx / per_axis)^3.
inline double particle_volume(const SceneSpec& scene) {
  const double h = scene.config.dx / scene.per_axis();
  return h * h * h;
}

template <class T, class Backend>
BuiltScene build_scene(const SceneSpec& scene, Simulation<T, Backend>& sim) {
  const SceneMaterials materials(scene);
  for (const MaterialInfo& m : materials.engine()) sim.add_material(m);
  for (std::size_t t = 0; t < scene.contact_groups.size(); ++t)
    for (int m = 0; m < materials.count(int(t)) && scene.contact_groups[t] != 0; ++m)
      sim.set_contact_group(materials.first(int(t)) + m, scene.contact_groups[t], scene.contact_friction);
  if (scene.tire) sim.enable(Attribute::x0);  // the displaced-snow metric compares with it
  std::vector<Point> positions, velocities;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    fill_body(scene, b, positions, velocities);
    add_table_particles(sim, materials, scene.bodies[b].material, positions, positions, velocities,
                        particle_volume(scene));
  }
  BuiltScene built;
  if (scene.tire && scene.tire->rubber) {
    const TireSpec& t = *scene.tire;
    const RubberTireFill fill = fill_rubber_tire(scene);
    std::vector<Point> areas;  // of the particles in the order they are added
    // Adds the particles `take` picks as particles of `table`.
    auto add_part = [&](int table, auto take) {
      std::vector<Point> x, v, a;
      for (std::size_t i = 0; i < fill.positions.size(); ++i)
        if (take(i)) {
          x.push_back(fill.positions[i]);
          v.push_back(fill.velocities[i]);
          a.push_back(fill.areas[i]);
        }
      for (const std::size_t k : add_table_particles(sim, materials, table, x, x, v, particle_volume(scene)))
        areas.push_back(a[k]);
    };
    // The parts' tables, indexed by TirePart; each table's particles are added at once, in this order.
    const int table_of[3] = {t.material, t.carcass_material, t.sidewall_material};
    const auto range = [&](int table) { return std::pair<int, int>{materials.first(table), materials.count(table)}; };
    for (int part = 0; part < 3; ++part)
      if (std::find(table_of, table_of + part, table_of[part]) == table_of + part)
        add_part(table_of[part], [&](std::size_t i) { return table_of[int(fill.part[i])] == table_of[part]; });
    if (t.pressure > 0) {
      sim.add_pressure_surface(sim.particle_count() - areas.size(), areas);
      sim.set_pressure(t.pressure, t.pressure_ramp);
    }
    built.rubber = range(t.material);
    if (t.carcass_material != t.material) built.carcass = range(t.carcass_material);
    if (t.sidewall_material != t.material && t.sidewall_material != t.carcass_material)
      built.sidewall = range(t.sidewall_material);
    for (const std::pair<int, int>& part : {built.rubber, built.carcass, built.sidewall})
      for (int m = 0; m < part.second; ++m) sim.set_contact_group(part.first + m, 1, t.friction);
  }
  for (const ColliderSpec& c : scene.colliders) {
    const int index = sim.add_collider(collider_body(c));
    if (scene.tire && scene.tire->rubber && built.road < 0 && c.kind == ColliderSpec::Kind::plane) built.road = index;
  }
  if (scene.tire) built.tire = sim.add_collider(tire_body(*scene.tire));
  if (scene.conveyor) {
    const ConveyorSpec& c = *scene.conveyor;
    built.ground = sim.add_collider(ground_body(c, scene.config.dx));
    std::vector<Point> bed = Conveyor(scene, c).initial_bed();
    if (scene.tire) {  // the tire starts pressed into the snow: no particles inside it
      const Collider<double> tire = tire_solid(*scene.tire);
      // A penalty tire pushes a particle from half a spacing off (kernels/step/penalty_contact.hpp):
      // none starts within that, which would start the run with the spring compressed.
      const double clear =
          scene.tire->contact == ColliderContact::penalty ? 0.5 * scene.config.dx / scene.per_axis() : 0.0;
      bed.erase(std::remove_if(bed.begin(), bed.end(),
                               [&](const Point& p) {
                                 double n[3];
                                 return tire.distance(p.data(), n) <= clear;
                               }),
                bed.end());
    }
    add_table_particles(sim, materials, c.material, bed, bed, std::vector<Point>(bed.size(), Point{-c.speed, 0, 0}),
                        particle_volume(scene));
  }
  for (const LoadSpec& l : scene.loads) sim.add_load(l.region_min, l.region_max, l.force, l.ramp_time);
  return built;
}

}  // namespace firn

// A validated scene (DESIGN.md section 5) in SI units, as the scene reader produces it and the
// scene builder turns it into a Simulation. Every field has been range-checked already.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/materials.hpp"
#include "engine/scene/body_shape.hpp"
#include "engine/scene/material_variation.hpp"
#include "engine/simulation.hpp"

namespace firn {

struct BodySpec {
  std::string name;
  std::string location;  // "FILE:LINE:COLUMN: bodies[i]" for messages
  int material;  // index into SceneSpec::materials
  BodyShape shape;
  Point velocity = {0, 0, 0};
  Point angular_velocity = {0, 0, 0};  // rad/s about the body's centre of mass
  double jitter = 0;                   // fraction of the lattice spacing, uniform in [-j/2, j/2]
  std::uint64_t seed = 0;
};

struct ColliderSpec {
  enum class Kind { plane, box, cylinder };
  std::string name;
  Kind kind = Kind::plane;
  Point point = {0, 0, 0}, normal = {0, 1, 0};  // plane: a point on it, the normal out of the solid
  Point min = {0, 0, 0}, max = {0, 0, 0};       // box
  Point center = {0, 0, 0};                     // cylinder
  double radius = 0, length = 0;                // cylinder
  int axis = 2;                                 // cylinder: 0 x, 1 y, 2 z
  Point velocity = {0, 0, 0};
  Point angular_velocity = {0, 0, 0};  // about the shape's centre (plane: its point)
  WallType boundary = WallType::sticky;
  Friction<double> friction{};
  ColliderContact contact = ColliderContact::nodes;
  double penalty_stiffness = 1;  // contact = penalty: omega = penalty_stiffness c / dx
};

// The tire of the thesis' experiment (issue 5): a rigid tire collider with a tread pattern on an
// axle along z at `center`, turning so that its tread at the ground moves toward -x at `speed`
// (the tire rolls toward +x over ground that moves toward -x). A free spin (issue 16) starts at
// the ground's speed and then turns under the snow's torque alone.
// An inflated rubber tire's default rim radius, as a fraction of its radius (a 16-inch rim in a
// 650 mm passenger tire is 0.62 of it).
constexpr double kDefaultRimFraction = 0.6;

struct TireSpec {
  std::string tread = "angled_footstep";
  Point center = {0, 0, 0};
  double radius = 0, width = 0, tread_depth = 0;
  int pitches = 0;
  double shoulder = 0;  // a slick tire's shoulder radius (0: square)
  double speed = 0;  // surface speed (m/s); a free spin's at t = 0: the conveyor's speed (0 without one)
  bool loaded = false;
  double load = 0, mass = 0;  // loaded axle; the mass also for a free spin
  bool free_spin = false;
  double inertia = 0;  // free spin: moment of inertia about the axle (kg m^2)
  WallType boundary = WallType::separate;
  Friction<double> friction{};
  ColliderContact contact = ColliderContact::nodes;  // nodes or penalty (a rigid tire's)
  double penalty_stiffness = 1;
  bool rubber = false;      // body = "rubber": particles of `material` on a rigid rim
  int material = -1;        // rubber: its [materials.NAME] table (the tread's)
  int carcass_material = -1;  // rubber: the carcass band's table (default: material's)
  int sidewall_material = -1;  // rubber: the sidewalls' table (default: material's)
  double carcass_radius = 0;  // rubber: the carcass's inner radius, radius - tread_depth - carcass
  double rim_radius = 0;      // rubber: carcass_radius, or below it with an air cavity
  double sidewall = 0;        // rubber with a cavity: thickness of the two sidewalls closing it
  double pressure = 0, pressure_ramp = 0;  // rubber: inflation pressure (Pa) on the cavity, its ramp (s)
};

// A conveyor snow bed (issue 5): the ground y <= `ground` moves toward -x at `speed` carrying a
// layer of snow `depth` deep over z in [z_min, z_max]; snow enters at x = inflow on the ground's
// particle lattice and is removed beyond x = outflow (or when it nears the domain's boundary).
struct ConveyorSpec {
  int material = 0;  // index into SceneSpec::materials
  double speed = 0, ground = 0, depth = 0, z_min = 0, z_max = 0, inflow = 0, outflow = 0;
  WallType boundary = WallType::sticky;
  double friction = 0;
};

struct MetricsSpec {
  double displaced_distance = 0.01;  // a particle this far from its undisturbed place is displaced
  bool footprint = true;             // the tire's contact pressure map per frame
  bool fragments = false;            // count the particles' connected clusters per frame
  double fragment_link_cells = 1.5;  // particles closer than this many cells are connected
  int fragment_min_particles = 10;   // smaller clusters are spray, not fragments
};

struct OutputSpec {
  bool particles = true;  // particles/NNNNN.vtp every frame
};

struct LoadSpec {
  Point region_min = {0, 0, 0}, region_max = {0, 0, 0};  // particles inside at t = 0 carry the load
  Point force = {0, 0, 0};                               // total force (N), shared by mass
  double ramp_time = 0;                                  // linear ramp from zero; 0: constant
};

struct RenderSpec {
  std::string style = "spheres";
  std::string color_by = "material";
  int width = 1280, height = 720;
  int fps = 30;
  std::string color_map = "auto";  // auto: diverging for J, viridis otherwise
  std::optional<double> color_min, color_max;
  std::string camera = "auto";  // auto, side, three_quarter, contact or top (viz/camera.hpp)
  bool camera_follow = true;    // presets reframe every frame, smoothly
  std::optional<Point> camera_position, camera_target;  // override the preset where given
  double fov = 0.6108652381980153;                      // vertical, rad (35 degrees)
  std::optional<Point> light_direction;  // default: from above, over the camera's shoulder
  bool shadows = true, ambient_occlusion = true, ground = true, legend = true, cutaway = false;
  std::optional<double> ground_height;  // default: the domain's floor
  double sphere_scale = 1.2;            // sphere diameter in particle spacings
  bool subsurface = true;               // snow surfaces: the subsurface scattering term
  double snow_grain = 0.001;            // snow surfaces: grain size (m)
  std::vector<std::optional<Point>> material_colors;  // per material ([materials.NAME] color)
};

struct SceneSpec {
  std::string name;  // file stem, the default output folder's name
  std::string path;
  SimulationConfig config;
  int particles_per_cell = 8;  // total per cell: 1, 8, 27 or 64
  double end_time = 0;
  double frame_interval = 0;
  std::string precision = "float";
  std::vector<MaterialInfo> materials;                // one per [materials.NAME] table, in name order
  std::vector<MaterialVariation> material_variations;  // per table: its `vary` (none: uniform)
  std::vector<int> contact_groups;                     // per table: its contact_group (0 or 1)
  Friction<double> contact_friction{};                 // [contact]
  std::vector<BodySpec> bodies;
  std::vector<ColliderSpec> colliders;
  std::vector<LoadSpec> loads;
  std::optional<TireSpec> tire;
  std::optional<ConveyorSpec> conveyor;
  MetricsSpec metrics;
  OutputSpec output;
  RenderSpec render;
  int per_axis() const;  // cube root of particles_per_cell
};

}  // namespace firn

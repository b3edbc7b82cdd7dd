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
  enum class Kind { plane, box };
  std::string name;
  Kind kind = Kind::plane;
  Point point = {0, 0, 0}, normal = {0, 1, 0};  // plane: a point on it, the normal out of the solid
  Point min = {0, 0, 0}, max = {0, 0, 0};       // box
  Point velocity = {0, 0, 0};
  WallType boundary = WallType::sticky;
  double friction = 0;
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
  std::optional<Point> camera_position, camera_target;  // automatic framing where absent
  double fov = 0.6108652381980153;                      // vertical, rad (35 degrees)
  std::optional<Point> light_direction;  // default: from above, over the camera's shoulder
  bool shadows = true, ambient_occlusion = true, ground = true, legend = true, cutaway = false;
  std::optional<double> ground_height;  // default: the domain's floor
  double sphere_scale = 1.2;            // sphere diameter in particle spacings
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
  std::vector<MaterialInfo> materials;
  std::vector<BodySpec> bodies;
  std::vector<ColliderSpec> colliders;
  std::vector<LoadSpec> loads;
  RenderSpec render;
  int per_axis() const;  // cube root of particles_per_cell
};

}  // namespace firn

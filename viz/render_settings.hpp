// How a frame is drawn: the scene's [render] section in the renderer's terms (viz/ knows nothing
// of the scene file), plus the domain box and particle spacing it needs.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "viz/color_map.hpp"
#include "viz/mat4.hpp"

namespace firn::viz {

// Where the camera looks from (viz/camera.hpp); [render] camera in the scene.
enum class CameraPreset { automatic, side, three_quarter, contact, top };

struct RenderSettings {
  int width = 1280, height = 720;
  CameraPreset camera = CameraPreset::automatic;
  bool camera_follow = true;                            // reframe every frame (viz/camera.hpp)
  std::optional<Vec3> camera_position, camera_target;  // override the preset where given
  double fov = 0.61;                                    // vertical field of view (rad)
  std::optional<Vec3> light_direction;                  // the direction the light travels
  bool shadows = true, ambient_occlusion = true, ground = true, legend = true, cutaway = false;
  bool subsurface = true;     // the snow surface's subsurface term (viz/shaders.cpp); off: Lambertian snow
  double snow_grain = 0.001;  // m, the size of the grains the snow surface is shaded with
  std::optional<double> ground_height;  // default: the domain's floor
  Rgb background_top = {0.80f, 0.85f, 0.91f}, background_bottom = {0.97f, 0.97f, 0.96f};
  double particle_spacing = 0.001;  // m, of the fill lattice: dx / particles per cell per axis
  double sphere_radius = 0.0006;    // m
  Vec3 domain_min = {0, 0, 0}, domain_max = {1, 1, 1};
  std::string color_by = "material";  // material, or a field name shown in the legend
  ColorMap color_map = ColorMap::viridis;
  std::optional<double> color_min, color_max;  // default: the frame's range
  std::vector<std::string> material_names;
  std::vector<Rgb> material_colors;  // per material
};

}  // namespace firn::viz

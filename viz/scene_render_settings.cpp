#include "viz/scene_render_settings.hpp"

#include "viz/camera.hpp"

namespace firn::viz {

RenderSettings scene_render_settings(const SceneSpec& scene) {
  const RenderSpec& r = scene.render;
  RenderSettings s;
  s.width = r.width;
  s.height = r.height;
  s.camera = parse_camera_preset(r.camera);
  s.camera_follow = r.camera_follow;
  s.camera_position = r.camera_position;
  s.camera_target = r.camera_target;
  s.fov = r.fov;
  s.light_direction = r.light_direction;
  s.shadows = r.shadows;
  s.ambient_occlusion = r.ambient_occlusion;
  s.ground = r.ground;
  s.ground_height = r.ground_height;
  s.legend = r.legend;
  s.cutaway = r.cutaway;
  s.subsurface = r.subsurface;
  s.snow_grain = r.snow_grain;
  // Radius from the particle spacing: particles sit dx / per_axis apart on the fill lattice.
  s.particle_spacing = scene.config.dx / scene.per_axis();
  s.sphere_radius = 0.5 * r.sphere_scale * s.particle_spacing;
  for (std::size_t d = 0; d < 3; ++d) {
    s.domain_min[d] = scene.config.domain_min[d];
    s.domain_max[d] = scene.config.domain_max[d];
  }
  s.color_by = r.color_by;
  s.color_map = r.color_map == "auto" ? (r.color_by == "J" ? ColorMap::diverging : ColorMap::viridis)
                                      : parse_color_map(r.color_map);
  s.color_min = r.color_min;
  s.color_max = r.color_max;
  for (std::size_t m = 0; m < scene.materials.size(); ++m) {
    s.material_names.push_back(scene.materials[m].name);
    const auto& c = m < r.material_colors.size() ? r.material_colors[m] : std::nullopt;
    s.material_colors.push_back(c ? Rgb{float((*c)[0]), float((*c)[1]), float((*c)[2])}
                                   : default_material_color(int(m)));
  }
  return s;
}

}  // namespace firn::viz

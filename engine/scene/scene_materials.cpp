#include "engine/scene/scene_materials.hpp"

namespace firn {

SceneMaterials::SceneMaterials(const SceneSpec& scene) {
  for (std::size_t t = 0; t < scene.materials.size(); ++t) {
    const MaterialInfo& nominal = scene.materials[t];
    const MaterialVariation* v = t < scene.material_variations.size() && scene.material_variations[t].varied()
                                     ? &scene.material_variations[t]
                                     : nullptr;
    first_.push_back(int(engine_.size()));
    count_.push_back(v ? v->levels : 1);
    if (v) {
      noise_.emplace_back(NoiseField(v->scale, v->seed));
      for (int l = 0; l < v->levels; ++l) engine_.push_back(material_level(nominal, *v, l));
    } else {
      noise_.emplace_back();
      engine_.push_back(nominal);
    }
    table_of_.resize(engine_.size(), int(t));
  }
}

std::vector<int> SceneMaterials::materials_at(int table, const std::vector<Point>& rest) const {
  const std::size_t t = std::size_t(table);
  std::vector<int> m(rest.size(), first_[t]);
  if (noise_[t])
    for (std::size_t i = 0; i < rest.size(); ++i) m[i] += noise_level((*noise_[t])(rest[i]), count_[t]);
  return m;
}

}  // namespace firn

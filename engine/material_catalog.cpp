#include "engine/material_catalog.hpp"

namespace firn {

const std::vector<MaterialModelSpec>& material_model_specs() {
  static const std::vector<MaterialModelSpec> specs = {
      {"neo_hookean", "compressible neo-Hookean, tau = mu (B - I) + lambda ln(J) I", true, {}},
      {"fixed_corotated", "fixed-corotated, tau = 2 mu (F - R) F^T + lambda (J - 1) J I", true, {}},
  };
  return specs;
}

const MaterialModelSpec* find_material_model(const std::string& name) {
  for (const auto& s : material_model_specs())
    if (s.name == name) return &s;
  return nullptr;
}

const std::vector<MaterialPreset>& material_presets() {
  static const std::vector<MaterialPreset> presets = {};
  return presets;
}

const MaterialPreset* find_material_preset(const std::string& name) {
  for (const auto& p : material_presets())
    if (p.name == name) return &p;
  return nullptr;
}

}  // namespace firn

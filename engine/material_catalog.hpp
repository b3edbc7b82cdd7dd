// What a scene may say about a material (DESIGN.md sections 4 and 5): for each constitutive model
// the parameters it reads beyond density and elastic moduli, and the named parameter presets
// (the thesis' tables). The scene validator, the resolved-scene writer, docs/scenes.md and the
// material factory all read these tables, so they cannot disagree.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "engine/scene/units.hpp"

namespace firn {

struct MaterialParameter {
  std::string key;                     // key in [materials.NAME]
  Quantity quantity;                   // what a unit string must measure
  std::optional<double> default_value;  // none: the scene must give it
  double min, max;                     // accepted closed range, in SI
  std::string doc;
  std::vector<std::string> choices = {};  // non-empty: a string value, stored as its index
};

struct MaterialModelSpec {
  std::string name;  // the model's kName
  std::string doc;
  bool elastic_moduli;  // reads two of E, nu, K, G
  std::vector<MaterialParameter> parameters;
};

// A named set of values for a model, e.g. "thesis_hard_snow". `values` holds density, any two of
// E, nu, K, G and model parameters, keyed as in a scene; a scene's own keys override them.
struct MaterialPreset {
  std::string name;
  std::string model;
  std::string doc;  // where the numbers come from
  std::map<std::string, double> values;
};

const std::vector<MaterialModelSpec>& material_model_specs();
const MaterialModelSpec* find_material_model(const std::string& name);

const std::vector<MaterialPreset>& material_presets();
const MaterialPreset* find_material_preset(const std::string& name);

}  // namespace firn

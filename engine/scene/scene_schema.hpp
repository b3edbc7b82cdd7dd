// The scene format's one table of keys (DESIGN.md section 5): for every section its keys, their
// kind, physical quantity, default, accepted range and meaning. The scene reader validates
// against it and docs/scenes.md is generated from it (`firn help scene-keys`), so the two cannot
// disagree. Material model parameters come from engine/material_catalog.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "engine/scene/units.hpp"

namespace firn {

enum class ValueKind { number, integer, vector3, choice, text, boolean, table, tables };

struct KeySpec {
  std::string key;
  ValueKind kind;
  Quantity quantity;
  std::string default_toml;  // a TOML value used when the key is absent; "" with `required` unset: optional
  bool required;
  std::string doc;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;
  std::vector<std::string> choices = {};
  std::string applies_to = {};  // only for this shape / model ("" for all)
  bool max_exclusive = false;
};

struct SectionSpec {
  std::string name;  // "simulation", "materials.NAME", "bodies", ...
  bool array;        // [[name]]: an array of tables
  std::string doc;
  std::vector<KeySpec> keys;
};

const std::vector<SectionSpec>& scene_schema();
const SectionSpec& scene_section(const std::string& name);

// docs/scenes.md: every section and key with unit, default and meaning, and the presets.
std::string scene_reference_markdown();

}  // namespace firn

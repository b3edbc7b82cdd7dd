// Heterogeneous materials (issue 16, item 6; the thesis' future work): `vary` in a
// [materials.NAME] table makes the parameters it lists vary in space,
//   value(x) = nominal * (1 + amplitude * n(x)),
// with n the table's noise field (engine/noise_field.hpp, in [-1, 1], correlation length
// `scale`), one field per table, shared by all its varied parameters (with positive amplitudes,
// denser snow is also stiffer and stronger). The kernels keep one parameter set per material
// (DESIGN.md section 2, rule 5), so n is quantised into `levels` equal bins of [-1, 1] and a varied
// table becomes one engine material per bin, its parameters at the bin's centre value of n
// (engine/scene/scene_materials.hpp puts each particle in the bin of n at its rest position).
//
// Among the elastic moduli, a varied one keeps its partner nominal (E keeps nu, nu keeps E, K keeps
// G, G keeps K) and two varied ones are varied together; at most two of E, nu, K, G may vary.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>

#include "engine/materials.hpp"

namespace firn {

struct MaterialVariation {
  std::map<std::string, double> amplitudes;  // parameter key -> relative amplitude in (-1, 1); empty: uniform
  double scale = 0;                          // correlation length of the noise (m)
  std::uint64_t seed = 0;
  int levels = 0;  // quantisation bins of the noise
  bool varied() const { return !amplitudes.empty(); }
};

// A varied material that is not physical at some level; `key` is the vary key to blame.
struct VariationError : std::invalid_argument {
  VariationError(std::string key, const std::string& what) : std::invalid_argument(what), key(std::move(key)) {}
  std::string key;
};

// The bin of a noise value n in [-1, 1] among `levels` equal bins (0 for n = -1, levels - 1 for 1).
int noise_level(double n, int levels);
// The noise value at the centre of bin `level`: -1 + (2 level + 1) / levels.
double level_centre(int level, int levels);

// The engine material of bin `level` of a varied table: `nominal` with each varied parameter
// scaled by (1 + amplitude * level_centre), named NAME~LEVEL. Throws VariationError for a value
// outside the parameter's range (material_catalog.cpp) or non-physical moduli.
MaterialInfo material_level(const MaterialInfo& nominal, const MaterialVariation& variation, int level);

}  // namespace firn

// The closed list of materials (DESIGN.md section 2, rule 5) and the one factory that maps a
// model name to its type. Each model is a plain struct from kernels/constitutive/ with the FIRN_HD
// interface described in kernels/constitutive/plastic_state.hpp; the engine launches one
// single-type kernel per material range, so no kernel switches on the material per particle.
// Adding a material: its header in kernels/constitutive/, its parameters in material_catalog.cpp,
// one entry in MaterialModel and one in make_material_model.
#pragma once

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <variant>

#include "engine/elastic_moduli.hpp"
#include "kernels/constitutive/fixed_corotated.hpp"
#include "kernels/constitutive/neo_hookean.hpp"

namespace firn {

template <class T>
using MaterialModel = std::variant<NeoHookean<T>, FixedCorotated<T>>;

struct MaterialInfo {
  std::string name;
  std::string model;
  double density;  // rest density (kg/m^3)
  ElasticModuli moduli;
  // Model parameters by key (MaterialModelSpec::parameters), in SI; a choice is its index.
  std::map<std::string, double> params = {};
  // Elastic P-wave speed sqrt((K + 4G/3) / rho) before any hardening (DESIGN.md section 3).
  double wave_speed() const { return std::sqrt(moduli.p_wave() / density); }
  double param(const std::string& key) const {
    const auto it = params.find(key);
    if (it == params.end()) throw std::invalid_argument("material '" + name + "' has no parameter '" + key + "'");
    return it->second;
  }
};

template <class T>
MaterialModel<T> make_material_model(const MaterialInfo& info) {
  const ElasticModuli& m = info.moduli;
  if (info.model == NeoHookean<T>::kName) return NeoHookean<T>{T(m.mu()), T(m.lambda())};
  if (info.model == FixedCorotated<T>::kName) return FixedCorotated<T>{T(m.mu()), T(m.lambda())};
  throw std::invalid_argument("unknown material model '" + info.model + "'");
}

}  // namespace firn

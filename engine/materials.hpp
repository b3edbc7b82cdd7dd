// The closed list of materials (DESIGN.md section 2, rule 5) and the one factory that maps a
// model name to its type. Each model is a plain struct from kernels/constitutive/ with FIRN_HD
// kirchhoff() and energy_density(); the engine launches one single-type kernel per material range.
// Adding a material: its header in kernels/constitutive/, one entry in MaterialModel and one in
// make_material_model.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>

#include "engine/elastic_moduli.hpp"
#include "kernels/constitutive/fixed_corotated.hpp"
#include "kernels/constitutive/neo_hookean.hpp"

namespace firn {

template <class T>
using MaterialModel = std::variant<NeoHookean<T>, FixedCorotated<T>>;

template <class T>
MaterialModel<T> make_material_model(const std::string& model, const ElasticModuli& m) {
  if (model == NeoHookean<T>::kName) return NeoHookean<T>{T(m.mu()), T(m.lambda())};
  if (model == FixedCorotated<T>::kName) return FixedCorotated<T>{T(m.mu()), T(m.lambda())};
  throw std::invalid_argument("unknown material model '" + model + "' (known: neo_hookean, fixed_corotated)");
}

struct MaterialInfo {
  std::string name;
  std::string model;
  double density;  // rest density (kg/m^3)
  ElasticModuli moduli;
  // Elastic P-wave speed sqrt((K + 4G/3) / rho) for the CFL time step (DESIGN.md section 3).
  double wave_speed() const { return std::sqrt(moduli.p_wave() / density); }
};

}  // namespace firn

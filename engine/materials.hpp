// The closed list of materials (DESIGN.md section 2, rule 5) and the one factory that maps a
// model name to its type. Each model is a plain struct from kernels/constitutive/ with the FIRN_HD
// interface described in kernels/constitutive/plastic_state.hpp; the engine launches one
// single-type kernel per material range, so no kernel switches on the material per particle.
// Adding a material: its header in kernels/constitutive/, its parameters in material_catalog.cpp,
// one entry in MaterialModel and one in make_material_model.
#pragma once

#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>

#include "engine/elastic_moduli.hpp"
#include "engine/material_catalog.hpp"
#include "kernels/constitutive/bimodular.hpp"
#include "kernels/constitutive/fixed_corotated.hpp"
#include "kernels/constitutive/hyperelastic_plastic.hpp"
#include "kernels/constitutive/mooney_rivlin.hpp"
#include "kernels/constitutive/neo_hookean.hpp"
#include "kernels/constitutive/snow_cam_clay.hpp"
#include "kernels/constitutive/snow_stomakhin.hpp"

namespace firn {

template <class T>
using MaterialModel =
    std::variant<NeoHookean<T>, FixedCorotated<T>, MooneyRivlin<T>, HyperelasticPlastic<T>, SnowStomakhin<T>,
                 SnowCamClay<T>, Bimodular<T>>;

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

// A model parameter: the material's own value, else the catalog's default (material_catalog.cpp).
inline double material_param(const MaterialInfo& info, const std::string& key) {
  if (info.params.count(key)) return info.params.at(key);
  if (const MaterialModelSpec* spec = find_material_model(info.model))
    for (const MaterialParameter& p : spec->parameters)
      if (p.key == key && p.default_value) return *p.default_value;
  return info.param(key);  // throws, naming the key
}

// The MaterialInfo of a catalog preset (material_catalog.cpp) as it stands, with `overrides` put
// over its values; the moduli from any two of E, nu, K and G. Throws for an unknown preset.
inline MaterialInfo preset_material_info(const std::string& name, std::map<std::string, double> overrides = {}) {
  const MaterialPreset* preset = find_material_preset(name);
  if (!preset) throw std::invalid_argument("no material preset '" + name + "'");
  std::map<std::string, double> v = preset->values;
  for (const auto& [k, x] : overrides) v[k] = x;
  const auto get = [&](const char* key) -> std::optional<double> {
    const auto it = v.find(key);
    return it == v.end() ? std::nullopt : std::optional<double>(it->second);
  };
  MaterialInfo info{
      name, preset->model, v.at("density"), ElasticModuli::from_any_two(get("E"), get("nu"), get("K"), get("G")), {}};
  for (const auto& [k, x] : v)
    if (k != "density" && k != "E" && k != "nu" && k != "K" && k != "G") info.params[k] = x;
  return info;
}

// Nearly incompressible hyperelastic solids (rubber) get the F-bar volume averaging of
// kernels/step/volume_average.hpp above this Poisson's ratio (issue 19: a smooth pressure at
// nu 0.499); below it, and for the plastic snow models, nothing changes.
constexpr double kVolumeAveragingNu = 0.45;
inline bool uses_volume_averaging(const MaterialInfo& info) {
  return (info.model == NeoHookean<double>::kName || info.model == MooneyRivlin<double>::kName) &&
         info.moduli.nu > kVolumeAveragingNu;
}

template <class T>
MaterialModel<T> make_material_model(const MaterialInfo& info) {
  const ElasticModuli& m = info.moduli;
  const auto param = [&](const char* key) { return T(material_param(info, key)); };
  if (info.model == NeoHookean<T>::kName) return NeoHookean<T>{T(m.mu()), T(m.lambda())};
  if (info.model == FixedCorotated<T>::kName) return FixedCorotated<T>{T(m.mu()), T(m.lambda())};
  if (info.model == Bimodular<T>::kName) return Bimodular<T>{T(m.mu()), T(m.lambda()), param("compression_ratio")};
  if (info.model == MooneyRivlin<T>::kName || info.model == HyperelasticPlastic<T>::kName) {
    // G from the elastic moduli is the small-strain shear modulus G1 + G2.
    const double G2 = material_param(info, "G2");
    if (!(G2 < m.G)) throw std::invalid_argument("material '" + info.name + "': G2 must be below the shear modulus G");
    const MooneyRivlin<T> elastic{T(m.K), T(m.G - G2), T(G2)};
    if (info.model == MooneyRivlin<T>::kName) return elastic;
    const J2Hardening<T> hardening{HardeningLaw(int(material_param(info, "hardening"))),
                                   param("sigma_y0"),
                                   param("E_p"),
                                   param("K_h"),
                                   param("n"),
                                   param("sigma_y_min")};
    return HyperelasticPlastic<T>{elastic, hardening};
  }
  if (info.model == SnowStomakhin<T>::kName)
    return SnowStomakhin<T>{T(m.mu()),        T(m.lambda()),   param("xi"),    param("theta_c"),
                            param("theta_s"), param("Jp_min"), param("Jp_max")};
  if (info.model == SnowCamClay<T>::kName)
    return SnowCamClay<T>{MooneyRivlin<T>{T(m.K), T(m.G), T(0)},
                          param("M"),
                          param("beta"),
                          CamClayHardening<T>{param("p0"), T(info.density), param("hardening_density"),
                                              param("softening_strain")}};
  throw std::invalid_argument("unknown material model '" + info.model + "'");
}

}  // namespace firn

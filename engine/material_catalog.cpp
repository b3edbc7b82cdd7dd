#include "engine/material_catalog.hpp"

#include <limits>

namespace firn {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Mooney G2 (thesis Eq. 4.1); G1 = G - G2, so G stays the small-strain shear modulus.
MaterialParameter g2_parameter() {
  return {"G2", Quantity::pressure, 0.0, 0, kInf, "Mooney I2bar coefficient (thesis Eq. 4.1); G1 = G - G2, below G"};
}

}  // namespace

const std::vector<MaterialModelSpec>& material_model_specs() {
  static const std::vector<MaterialModelSpec> specs = {
      {"neo_hookean", "compressible neo-Hookean, tau = mu (B - I) + lambda ln(J) I", true, {}},
      {"fixed_corotated", "fixed-corotated, tau = 2 mu (F - R) F^T + lambda (J - 1) J I", true, {}},
      {"bimodular",
       "bimodular Hencky elasticity, stiff in tension and soft in compression like cords in rubber (Bert 1977): "
       "tau_i = 2 mu s(e_i) e_i + lambda s(ln J) ln J along the principal log stretches e_i, s(x) = 1 for x > 0, "
       "else compression_ratio",
       true,
       {{"compression_ratio", Quantity::dimensionless, std::nullopt, 0, 1,
         "the moduli in compression over those in tension (0: tension only; e.g. 0.05 for rubber between cords "
         "20 times stiffer)"}}},
      {"mooney_rivlin",
       "compressible Mooney-Rivlin, W = K/2 (1/2 (J^2 - 1) - ln J) + G1/2 (I1bar - 3) + G2/2 (I2bar - 3) "
       "(thesis Eq. 4.1-4.4)",
       true,
       {g2_parameter()}},
      {"hyperelastic_plastic",
       "Mooney-Rivlin elasticity of b_e with J2 plasticity, radial return (thesis Eq. 4.1-4.5; NairnMPM HEIsotropic)",
       true,
       {
           {"hardening",
            Quantity::dimensionless,
            1.0,
            0,
            1,
            "isotropic hardening law: linear sigma_y0 + E_p alpha, or nonlinear sigma_y0 (1 + K_h alpha)^n "
            "(thesis Eq. 4.5)",
            {"linear", "nonlinear"}},
           {"sigma_y0", Quantity::pressure, std::nullopt, 0, kInf, "initial yield stress"},
           {"E_p", Quantity::pressure, 0.0, -kInf, kInf, "linear law: plastic modulus; negative softens"},
           {"K_h", Quantity::dimensionless, 0.0, -kInf, kInf,
            "nonlinear law: hardening coefficient K (thesis Eq. 4.5); negative softens"},
           {"n", Quantity::dimensionless, 1.0, 0, 10, "nonlinear law: exponent n (thesis Eq. 4.5)"},
           {"sigma_y_min", Quantity::pressure, 0.0, 0, kInf, "floor of the yield stress under softening"},
           g2_parameter(),
       }},
      {"snow_stomakhin",
       "fixed-corotated with moduli scaled by exp(xi (1 - J_P)), singular values of F_E clamped to "
       "[1 - theta_c, 1 + theta_s] (Stomakhin et al. 2013; thesis Eq. 4.6)",
       true,
       {
           {"xi", Quantity::dimensionless, 10.0, 0, 100, "hardening coefficient"},
           {"theta_c", Quantity::dimensionless, 2.5e-2, 0, 0.999, "critical compression"},
           {"theta_s", Quantity::dimensionless, 7.5e-3, 0, kInf, "critical stretch"},
           {"Jp_min", Quantity::dimensionless, 0.0, 0, kInf, "lower clamp of J_P (0: none)"},
           {"Jp_max", Quantity::dimensionless, kInf, 0, kInf, "upper clamp of J_P (inf: none)"},
       }},
      {"snow_cam_clay",
       "Mooney-Rivlin elasticity (G2 = 0) of b_e with modified Cam-clay plasticity, yield (1 + 2 beta) q^2 + "
       "M^2 (p + beta p0)(p - p0) <= 0, non-associative return (Gaume et al. 2018; Wolper et al. 2019), p0 "
       "hardening with compaction and softening with dilation",
       true,
       {
           {"M", Quantity::dimensionless, std::nullopt, 1e-6, 10, "slope of the critical state line"},
           {"beta", Quantity::dimensionless, std::nullopt, 0, 10, "cohesion: the tensile strength is beta p0"},
           {"p0", Quantity::pressure, std::nullopt, 0, kInf,
            "consolidation pressure (compressive strength) at the rest density"},
           {"hardening_density", Quantity::density, std::nullopt, 1e-6, kInf,
            "compaction hardening scale: p0 = p0(rest) exp((rho_P - density) / hardening_density), rho_P the "
            "plastically compacted density"},
           {"softening_strain", Quantity::dimensionless, std::nullopt, 1e-9, 10,
            "plastic dilation ln J_P over which p0, and the cohesion beta p0, fall linearly to zero"},
       }},
  };
  return specs;
}

const MaterialModelSpec* find_material_model(const std::string& name) {
  for (const auto& s : material_model_specs())
    if (s.name == name) return &s;
  return nullptr;
}

const std::vector<MaterialPreset>& material_presets() {
  // Thesis Table 4.2 (snowball layers) and 4.3 (hard = shell, soft = core), MPa and g/cm^3 there.
  const auto snow = [](const char* name, const char* doc, double rho, double K, double G, double K_h) {
    return MaterialPreset{
        name,
        "hyperelastic_plastic",
        doc,
        {{"density", rho}, {"K", K}, {"G", G}, {"hardening", 1}, {"K_h", K_h}, {"n", 0.02}, {"sigma_y0", 100}}};
  };
  const auto cam_clay = [](const char* name, const char* doc, double rho, double E, double beta, double p0) {
    return MaterialPreset{name,
                          "snow_cam_clay",
                          doc,
                          {{"density", rho},
                           {"E", E},
                           {"nu", 0.2},
                           {"M", 1.722},
                           {"beta", beta},
                           {"p0", p0},
                           {"hardening_density", 83.06},
                           {"softening_strain", 0.01}}};
  };
  static const std::vector<MaterialPreset> presets = {
      {"thesis_stomakhin_snow",
       "snow_stomakhin",
       "thesis Table 4.1 (Stomakhin et al. 2013)",
       {{"density", 400}, {"E", 1.4e5}, {"nu", 0.2}, {"xi", 10}, {"theta_c", 2.5e-2}, {"theta_s", 7.5e-3}}},
      snow("thesis_shell", "thesis Table 4.2, shell", 400, 78e3, 58.3e3, 15),
      snow("thesis_middle", "thesis Table 4.2, middle", 360, 51e3, 32.5e3, 12),
      snow("thesis_core", "thesis Table 4.2, core", 330, 26.7e3, 20e3, 10),
      snow("thesis_hard_snow", "thesis Table 4.3, hard snow", 400, 78e3, 58.3e3, 15),
      snow("thesis_soft_snow", "thesis Table 4.3, soft snow", 330, 26.7e3, 20e3, 10),
      // Cam-clay snow calibrated on laboratory data only: data/snow/fit_cam_clay.py prints these
      // lines (E: Scapozza 2004; hardening_density and, in confined compression, p0: CRREL Report
      // 95-7; beta with p0: Sigrist 2006's tensile strength; M: the angle of repose of granular
      // snow; docs/snow.md). packed_snow is at the thesis' hard snow density (Table 4.3).
      cam_clay("fresh_snow", "fresh snow, 220 kg/m^3 (data/snow/fit_cam_clay.py)", 220, 4.968e+06, 2.175, 6283),
      cam_clay("soft_cam_clay_snow", "the thesis' soft snow density, 330 kg/m^3 (data/snow/fit_cam_clay.py)", 330,
               2.558e+07, 1.366, 1.898e+04),
      cam_clay("packed_snow", "packed snow, 400 kg/m^3 (data/snow/fit_cam_clay.py)", 400, 7.26e+07, 0.6922, 3.887e+04),
      {"thesis_tire_rubber",
       "mooney_rivlin",
       "thesis sec. 4.1.2: E = 1e7 Pa, nu = 0.49, 0.93 g/cm^3 (its ref. 25)",
       {{"density", 930}, {"E", 1e7}, {"nu", 0.49}}},
  };
  return presets;
}

const MaterialPreset* find_material_preset(const std::string& name) {
  for (const auto& p : material_presets())
    if (p.name == name) return &p;
  return nullptr;
}

}  // namespace firn

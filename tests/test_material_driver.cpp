// The material-point driver (engine/verification/material_driver.hpp) and the material catalog
// entries of the thesis models: presets carry the thesis' tables, the factory builds each model, the
// driver composes increments exactly and solves uniaxial stress.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/materials.hpp"
#include "engine/verification/material_driver.hpp"

namespace firn {
namespace {

TEST(MaterialCatalog, ThesisPresetsMatchTables) {
  // Table 4.2 (MPa, g/cm^3 there) and 4.3: hard snow = shell, soft snow = core.
  struct Row {
    const char* name;
    double rho, K, G, K_h;
  };
  for (const Row& r : {Row{"thesis_shell", 400, 78e3, 58.3e3, 15}, Row{"thesis_middle", 360, 51e3, 32.5e3, 12},
                       Row{"thesis_core", 330, 26.7e3, 20e3, 10}, Row{"thesis_hard_snow", 400, 78e3, 58.3e3, 15},
                       Row{"thesis_soft_snow", 330, 26.7e3, 20e3, 10}}) {
    const MaterialInfo info = preset_material_info(r.name);
    EXPECT_EQ(info.model, "hyperelastic_plastic");
    EXPECT_DOUBLE_EQ(info.density, r.rho);
    EXPECT_DOUBLE_EQ(info.moduli.K, r.K);
    EXPECT_DOUBLE_EQ(info.moduli.G, r.G);
    EXPECT_DOUBLE_EQ(info.params.at("K_h"), r.K_h);
    EXPECT_DOUBLE_EQ(info.params.at("n"), 0.02);
    EXPECT_DOUBLE_EQ(info.params.at("sigma_y0"), 100);
    const auto model = make_material_model<double>(info);
    const auto& hp = std::get<HyperelasticPlastic<double>>(model);
    EXPECT_EQ(hp.hardening.law, HardeningLaw::nonlinear);
    EXPECT_DOUBLE_EQ(hp.elastic.G2, 0);  // default
  }
  const MaterialInfo snow = preset_material_info("thesis_stomakhin_snow");
  const MaterialModel<double> snow_model = make_material_model<double>(snow);
  const auto& sm = std::get<SnowStomakhin<double>>(snow_model);
  EXPECT_DOUBLE_EQ(snow.moduli.E, 1.4e5);
  EXPECT_DOUBLE_EQ(sm.xi, 10);
  EXPECT_DOUBLE_EQ(sm.theta_c, 2.5e-2);
  EXPECT_DOUBLE_EQ(sm.theta_s, 7.5e-3);
  EXPECT_TRUE(std::isinf(sm.Jp_max));
  const MaterialInfo rubber = preset_material_info("thesis_tire_rubber");
  EXPECT_DOUBLE_EQ(rubber.moduli.nu, 0.49);
  EXPECT_DOUBLE_EQ(rubber.density, 930);
  EXPECT_TRUE(std::holds_alternative<MooneyRivlin<double>>(make_material_model<double>(rubber)));
}

TEST(MaterialCatalog, EveryParameterDefaultIsInRange) {
  for (const char* name : {"hyperelastic_plastic", "snow_stomakhin", "mooney_rivlin"}) {
    const MaterialModelSpec* spec = find_material_model(name);
    ASSERT_NE(spec, nullptr) << name;
    for (const MaterialParameter& p : spec->parameters)
      if (p.default_value) {
        EXPECT_GE(*p.default_value, p.min) << name << "." << p.key;
        EXPECT_LE(*p.default_value, p.max) << name << "." << p.key;
      }
  }
}

TEST(MaterialFactory, RejectsG2NotBelowG) {
  MaterialInfo info = preset_material_info("thesis_tire_rubber");
  info.params["G2"] = info.moduli.G;
  EXPECT_THROW(make_material_model<double>(info), std::invalid_argument);
}

TEST(MaterialDriver, ElasticPathComposesIncrementsExactly) {
  // For an elastic model the increments must compose to F(t): tau equals kirchhoff(F(t)).
  const MaterialModel<double> model = make_material_model<double>(preset_material_info("thesis_tire_rubber"));
  const auto& mr = std::get<MooneyRivlin<double>>(model);
  const DriverHistory h =
      drive_material(model, paths::rotated(paths::compress_and_shear(0.6, 1.5), {{0, 1, 1}}, 2.0), 50);
  ASSERT_EQ(h.F.size(), 51u);
  for (std::size_t k = 0; k < h.F.size(); ++k) {
    for (int q = 0; q < 9; ++q) EXPECT_NEAR(h.F_E[k].m[q], h.F[k].m[q], 1e-12);
    const Mat3<double> tau = mr.kirchhoff(h.F[k]);
    for (int q = 0; q < 9; ++q) EXPECT_NEAR(h.tau[k].m[q], tau.m[q], 1e-9 * mr.K);
  }
  EXPECT_NEAR(determinant(h.F.back()), 0.6, 1e-12);
}

TEST(MaterialDriver, HydrostaticCycleReturnsToIdentity) {
  const MaterialModel<double> model = make_material_model<double>(preset_material_info("thesis_core"));
  const DriverHistory h = drive_material(model, paths::hydrostatic_cycle(0.3), 100);
  EXPECT_NEAR(determinant(h.F[50]), 0.3, 1e-12);
  for (int q = 0; q < 9; ++q) EXPECT_NEAR(h.F_E.back().m[q], q % 4 == 0 ? 1 : 0, 1e-12);
  EXPECT_EQ(h.state.back().alpha, 0);
}

TEST(MaterialDriver, UniaxialStressHasNoLateralStress) {
  const MaterialModel<double> model = make_material_model<double>(preset_material_info("thesis_shell"));
  const DriverHistory h = drive_uniaxial_stress(model, -0.1, 50);  // well into the plastic range
  EXPECT_GT(h.state.back().alpha, 0);
  for (const auto& tau : h.tau) {
    EXPECT_LE(std::abs(tau(1, 1)), 1e-10 * std::abs(tau(0, 0)) + 1e-12);
    EXPECT_LE(std::abs(tau(2, 2)), 1e-10 * std::abs(tau(0, 0)) + 1e-12);
  }
  // Compression: negative axial stress, lateral expansion.
  EXPECT_LT(h.tau.back()(0, 0), 0);
  EXPECT_GT(h.F.back()(1, 1), 1);
}

TEST(MaterialDriver, CyclicLoadingAccumulatesPlasticStrain) {
  const MaterialModel<double> model = make_material_model<double>(preset_material_info("thesis_shell"));
  const DriverHistory h = drive_material(model, paths::cyclic_uniaxial_strain(0.02, 2), 200);
  for (std::size_t k = 1; k < h.state.size(); ++k) EXPECT_GE(h.state[k].alpha, h.state[k - 1].alpha);
  EXPECT_GT(h.state[100].alpha, h.state[50].alpha);  // the second half-cycle yields again
}

}  // namespace
}  // namespace firn

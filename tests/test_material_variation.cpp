// Heterogeneous materials (`vary` in [materials.NAME]; engine/scene/material_variation.hpp and
// scene_materials.hpp): the quantisation, the per-level parameters, the split of a body's
// particles among the levels, determinism across thread counts, the conveyor's injected snow,
// and the reader's messages for a bad `vary`.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <string>

#include "engine/scene/scene_materials.hpp"
#include "engine/scene/scene_reader.hpp"
#include "engine/scene/scene_stepper.hpp"
#include "kernels/backend/openmp.hpp"
#include "kernels/backend/serial.hpp"

namespace firn {
namespace {

// A packed-snow box of 20 x 20 x 20 cells (64,000 particles), its material varied by `vary`.
std::string scene_text(const std::string& vary, const std::string& body = "shape = \"box\"\nmin = [0.05, 0.05, 0.05]\n"
                                                                          "max = [0.25, 0.25, 0.25]\n") {
  return "[simulation]\ndomain_min = [0, 0, 0]\ndomain_max = [0.3, 0.3, 0.3]\ndx = \"10 mm\"\nend_time = \"1 ms\"\n"
         "[materials.snow]\npreset = \"packed_snow\"\n" +
         (vary.empty() ? "" : "vary = " + vary + "\n") + "[[bodies]]\nmaterial = \"snow\"\nvelocity = [2, 0, 0]\n" +
         body;
}

SceneSpec load(const std::string& text) { return load_scene_text(text, "vary.toml", {}).spec; }

std::string error_of(const std::string& text) {
  try {
    load(text);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(MaterialVariation, QuantisesMinusOneToOneIntoEqualBins) {
  EXPECT_EQ(noise_level(-1, 8), 0);
  EXPECT_EQ(noise_level(-0.76, 8), 0);
  EXPECT_EQ(noise_level(-0.74, 8), 1);
  EXPECT_EQ(noise_level(0.0, 8), 4);
  EXPECT_EQ(noise_level(1, 8), 7);
  EXPECT_DOUBLE_EQ(level_centre(0, 8), -0.875);
  EXPECT_DOUBLE_EQ(level_centre(7, 8), 0.875);
  for (int l = 0; l < 5; ++l) EXPECT_EQ(noise_level(level_centre(l, 5), 5), l);
}

TEST(MaterialVariation, ScalesTheListedParametersAtTheLevelsCentre) {
  const SceneSpec s = load(scene_text("{ density = 0.15, p0 = 0.3, E = 0.2, scale = \"15 mm\", seed = 1 }"));
  const MaterialInfo& nominal = s.materials[0];
  const MaterialVariation& v = s.material_variations[0];
  EXPECT_EQ(v.levels, 8);
  EXPECT_DOUBLE_EQ(v.scale, 0.015);
  const MaterialInfo top = material_level(nominal, v, 7);  // n = 0.875
  EXPECT_EQ(top.name, "snow~7");
  EXPECT_DOUBLE_EQ(top.density, nominal.density * (1 + 0.15 * 0.875));
  EXPECT_DOUBLE_EQ(top.param("p0"), nominal.param("p0") * (1 + 0.3 * 0.875));
  EXPECT_DOUBLE_EQ(top.param("beta"), nominal.param("beta"));  // not listed: nominal
  EXPECT_NEAR(top.moduli.E, nominal.moduli.E * (1 + 0.2 * 0.875), 1e-6 * nominal.moduli.E);
  EXPECT_NEAR(top.moduli.nu, nominal.moduli.nu, 1e-12);  // E keeps nu
  // K keeps G.
  const SceneSpec k = load(scene_text("{ K = -0.2, scale = \"15 mm\" }"));
  const MaterialInfo low = material_level(k.materials[0], k.material_variations[0], 0);  // n = -0.875
  EXPECT_NEAR(low.moduli.K, k.materials[0].moduli.K * (1 + 0.2 * 0.875), 1e-6 * low.moduli.K);
  EXPECT_NEAR(low.moduli.G, k.materials[0].moduli.G, 1e-6 * low.moduli.G);
}

// A varied body's particles spread over the levels; their mean mass is the nominal one.
TEST(MaterialVariation, SplitsABodyAmongLevelsWithTheNominalMeanMass) {
  const SceneSpec s = load(scene_text("{ density = 0.15, p0 = 0.3, scale = \"15 mm\", seed = 1 }"));
  SceneStepper<double, backend::Serial> stepper(s, backend::Serial{});
  Simulation<double, backend::Serial>& sim = stepper.sim();
  ASSERT_EQ(sim.material_count(), 8u);
  const ParticleView<double> pv = sim.particles();
  const double nominal = s.materials[0].density * particle_volume(s);
  std::set<double> masses;
  double sum = 0;
  for (std::size_t p = 0; p < pv.n; ++p) {
    masses.insert(pv.mass[p]);
    sum += pv.mass[p];
    EXPECT_NEAR(pv.mass[p] / nominal, 1, 0.15);
  }
  EXPECT_GE(masses.size(), 6u);
  EXPECT_NEAR(sum / double(pv.n) / nominal, 1, 0.005);
  // Each particle is in the level of the noise at its place, and the levels are contiguous.
  const SceneMaterials materials(s);
  for (int m = 0; m < 8; ++m) {
    const ParticleRange r = sim.material_range(m);
    std::vector<Point> x;
    for (std::size_t p = r.begin; p < r.end; ++p) x.push_back({pv.x[0][p], pv.x[1][p], pv.x[2][p]});
    for (int got : materials.materials_at(0, x)) EXPECT_EQ(got, m);
    EXPECT_EQ(materials.table_of(m), 0);
  }
}

TEST(MaterialVariation, AUniformSceneKeepsItsTables) {
  const SceneSpec s = load(scene_text(""));
  const SceneMaterials materials(s);
  ASSERT_EQ(materials.engine().size(), 1u);
  EXPECT_EQ(materials.engine()[0].name, "snow");
  EXPECT_FALSE(materials.varied(0));
}

TEST(MaterialVariation, BitwiseTheSameOnOneAndTwoThreads) {
  const SceneSpec s = load(scene_text("{ density = 0.15, p0 = 0.3, scale = \"15 mm\", seed = 3 }",
                                      "shape = \"sphere\"\ncenter = [0.12, 0.15, 0.15]\nradius = \"50 mm\"\n"));
  std::uint64_t hashes[2];
  for (int threads : {1, 2}) {
    SceneStepper<float, backend::OpenMP> stepper(s, backend::OpenMP(threads));
    for (int i = 0; i < 30; ++i) stepper.step_toward(1);
    hashes[threads - 1] = stepper.sim().state_hash();
  }
  EXPECT_EQ(hashes[0], hashes[1]);
}

TEST(MaterialVariation, TheResolvedSceneKeepsVary) {
  const LoadedScene a = load_scene_text(scene_text("{ p0 = 0.3, scale = \"15 mm\", seed = 1 }"), "vary.toml", {});
  const LoadedScene b = load_scene_text(a.resolved_toml, "vary.toml", {});
  EXPECT_EQ(a.resolved_toml, b.resolved_toml);
  EXPECT_EQ(b.spec.material_variations[0].amplitudes, a.spec.material_variations[0].amplitudes);
  EXPECT_EQ(b.spec.material_variations[0].levels, 8);
}

// Snow a conveyor injects goes to the level of the noise where the ground carried it from
// (its x0), so the field moves with the bed.
TEST(MaterialVariation, TheConveyorInjectsSnowInTheLevelOfItsRestPosition) {
  const SceneSpec s = load(
      "[simulation]\ndomain_min = [0, 0, 0]\ndomain_max = [0.4, 0.2, 0.14]\ndx = \"10 mm\"\nend_time = \"1 s\"\n"
      "particles_per_cell = 1\n[materials.snow]\npreset = \"fresh_snow\"\n"
      "vary = { density = 0.2, scale = \"20 mm\", seed = 5 }\n"
      "[conveyor]\nmaterial = \"snow\"\nspeed = 5\nground = 0.05\ndepth = 0.04\nz_min = 0.04\nz_max = 0.08\n");
  SceneStepperOptions<double, backend::Serial> options;
  options.rest_positions = true;
  SceneStepper<double, backend::Serial> stepper(s, backend::Serial{}, options);
  while (stepper.conveyor()->injected() < 200) stepper.step_toward(1);
  Simulation<double, backend::Serial>& sim = stepper.sim();
  sim.prepare();
  const ParticleView<double> pv = sim.particles();
  const SceneMaterials materials(s);
  for (int m = 0; m < int(sim.material_count()); ++m) {
    const ParticleRange r = sim.material_range(m);
    std::vector<Point> rest;
    for (std::size_t p = r.begin; p < r.end; ++p) rest.push_back({pv.x0[0][p], pv.x0[1][p], pv.x0[2][p]});
    for (int got : materials.materials_at(0, rest)) EXPECT_EQ(got, m);
  }
}

TEST(MaterialVariation, BadVaryKeysAreNamed) {
  const auto expect = [](const std::string& vary, const std::string& message) {
    const std::string e = error_of(scene_text(vary));
    EXPECT_NE(e.find(message), std::string::npos) << vary << "\n" << e;
  };
  expect("{ densty = 0.1, scale = 0.01 }", "materials.snow.vary.densty: unknown key (did you mean 'density'?)");
  expect("{ sigma_y0 = 0.1, scale = 0.01 }", "materials.snow.vary.sigma_y0: does not apply to 'snow_cam_clay'");
  expect("{ p0 = 1, scale = 0.01 }", "materials.snow.vary.p0: must be in (-1, 1) (got 1)");
  expect("{ p0 = -1.5, scale = 0.01 }", "materials.snow.vary.p0: must be in (-1, 1) (got -1.5)");
  expect("{ p0 = 0.1, scale = 0 }", "materials.snow.vary.scale: must be > 0 (got 0)");
  expect("{ p0 = 0.1 }", "materials.snow.vary.scale: missing (required)");
  expect("{ p0 = 0.1, scale = 0.01, levels = 1 }", "materials.snow.vary.levels: must be in [2, 64] (got 1)");
  expect("{ scale = 0.01 }", "materials.snow.vary: names no parameter");
  expect("0.1", "materials.snow.vary: expected a table, got a number");
  // A level outside the parameter's range: nu = 0.3 (1 + 0.9 * 0.875) = 0.54 at the top level.
  std::string text = scene_text("{ nu = 0.9, scale = 0.01 }");
  text.replace(text.find("preset"), 0, "E = 7e7\nnu = 0.3\n");
  EXPECT_NE(error_of(text).find("materials.snow.vary.nu: at n = 0.875: Poisson's ratio"), std::string::npos)
      << error_of(text);
  expect("{ E = 0.1, K = 0.1, G = 0.1, scale = 0.01 }", "materials.snow.vary.G: at most two of E, nu, K, G may vary");
  expect("{ M = 0.9, scale = 0.01, levels = 2 }", "accepted");
  expect("{ beta = 0.9, scale = 0.01 }", "accepted");
}

}  // namespace
}  // namespace firn

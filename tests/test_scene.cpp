// Scene format: unit conversion, validation messages, --set overrides, presets, layered bodies,
// the resolved scene, and the colliders and loads a scene adds to the engine.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "engine/scene/scene_builder.hpp"
#include "engine/scene/scene_reader.hpp"
#include "engine/scene/units.hpp"
#include "kernels/backend/serial.hpp"

namespace firn {
namespace {

const std::string kScenes = FIRN_SOURCE_DIR "/scenes/";

TEST(Units, ConvertsTheThesisSpellings) {
  EXPECT_DOUBLE_EQ(parse_quantity("70 mm", Quantity::length), 0.07);
  EXPECT_DOUBLE_EQ(parse_quantity("0.4 g/cm^3", Quantity::density), 400);
  EXPECT_DOUBLE_EQ(parse_quantity("0.078 MPa", Quantity::pressure), 78000);
  EXPECT_DOUBLE_EQ(parse_quantity("6000 mm/s", Quantity::velocity), 6);
  EXPECT_DOUBLE_EQ(parse_quantity("10 mph", Quantity::velocity), 4.4704);
  EXPECT_DOUBLE_EQ(parse_quantity("0.5 ms", Quantity::time), 5e-4);
  EXPECT_DOUBLE_EQ(parse_quantity("30 deg", Quantity::angle), M_PI / 6);
  EXPECT_DOUBLE_EQ(parse_quantity("  2.5  ", Quantity::length), 2.5);
  EXPECT_DOUBLE_EQ(parse_quantity("1.4 kg m^2", Quantity::moment_of_inertia), 1.4);
}

TEST(Units, RejectsAUnitOfAnotherQuantityOrAnUnknownOne) {
  try {
    parse_quantity("5 kg", Quantity::length);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("measures mass, expected length"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_quantity("5 parsecs", Quantity::length), std::invalid_argument);
  EXPECT_THROW(parse_quantity("mm", Quantity::length), std::invalid_argument);
}

// Fuzzer findings (tests/fuzz): strtod reads "nan" and "inf", TOML has nan and inf literals.
TEST(Units, RejectsNonFiniteNumbers) {
  for (const char* text : {"nan", "inf mm", "-infinity m/s", "NAN Pa"})
    EXPECT_THROW(parse_quantity(text, Quantity::length), std::invalid_argument) << text;
}

TEST(SceneReader, RefusesNonFiniteVectorComponents) {
  for (const char* set : {"simulation.gravity=[0, nan, 0]", "bodies.0.velocity=[0, inf, 0]",
                          "simulation.domain_max=[1, 1, inf]", "bodies.0.center=[\"nan m\", 0.3, 0.5]"}) {
    SceneOptions o;
    o.overrides = {set};
    try {
      load_scene(kScenes + "two_spheres.toml", o);
      ADD_FAILURE() << set << " was accepted";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("finite"), std::string::npos) << e.what();
    }
  }
}

TEST(SceneReader, ReadsSnowballPairWithPresetsAndUnits) {
  const SceneSpec s = load_scene(kScenes + "snowball_pair.toml", {}).spec;
  EXPECT_DOUBLE_EQ(s.config.dx, 0.002);
  EXPECT_DOUBLE_EQ(s.end_time, 0.01);
  ASSERT_EQ(s.materials.size(), 3u);
  const MaterialInfo& core = s.materials[0];  // tables are read in name order: core, middle, shell
  EXPECT_EQ(core.name, "core");
  EXPECT_EQ(core.model, "hyperelastic_plastic");
  EXPECT_DOUBLE_EQ(core.density, 330);
  EXPECT_DOUBLE_EQ(core.moduli.K, 26700);
  EXPECT_DOUBLE_EQ(core.moduli.G, 20000);
  EXPECT_DOUBLE_EQ(core.param("K_h"), 10);
  EXPECT_DOUBLE_EQ(s.bodies[0].velocity[0], 6);
}

TEST(SceneReader, OverridesAnyKeyIncludingUnquotedStringsAndArrayElements) {
  SceneOptions o;
  o.overrides = {"simulation.dx=0.004", "bodies.1.velocity=[1, 2, 3]", "materials.core.preset=thesis_stomakhin_snow",
                 "materials.middle.K_h=20", "render.style=surface", "simulation.end_time=3 ms"};
  const SceneSpec s = load_scene(kScenes + "snowball_pair.toml", o).spec;
  EXPECT_DOUBLE_EQ(s.config.dx, 0.004);
  EXPECT_DOUBLE_EQ(s.bodies[1].velocity[2], 3);
  EXPECT_EQ(s.materials[0].model, "snow_stomakhin");
  EXPECT_DOUBLE_EQ(s.materials[1].param("K_h"), 20);
  EXPECT_DOUBLE_EQ(s.materials[1].param("sigma_y0"), 100);  // the rest of the preset stays
  EXPECT_EQ(s.render.style, "surface");
  EXPECT_DOUBLE_EQ(s.end_time, 0.003);
}

TEST(SceneReader, AnOverrideIsValidatedAndNamedInTheMessage) {
  SceneOptions o;
  o.overrides = {"simulation.cfl=7"};
  try {
    load_scene(kScenes + "snowball_pair.toml", o);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "--set simulation.cfl=7: simulation.cfl: must be in (0, 1] (got 7)");
  }
}

TEST(SceneReader, PreviewDoublesDxAndThinsParticles) {
  SceneOptions o;
  o.preview = true;
  const SceneSpec s = load_scene(kScenes + "snowball_pair.toml", o).spec;
  EXPECT_DOUBLE_EQ(s.config.dx, 0.004);
  EXPECT_EQ(s.particles_per_cell, 1);
}

TEST(SceneReader, TheResolvedSceneReadsBackToTheSameValues) {
  const LoadedScene a = load_scene(kScenes + "snowball_pair.toml", {});
  const std::string path = testing::TempDir() + "/resolved.toml";
  std::ofstream(path) << a.resolved_toml;
  const LoadedScene b = load_scene(path, {});
  EXPECT_EQ(a.resolved_toml.substr(a.resolved_toml.find('\n')), b.resolved_toml.substr(b.resolved_toml.find('\n')));
  EXPECT_EQ(a.spec.config.dx, b.spec.config.dx);
  EXPECT_EQ(a.spec.materials[2].moduli.E, b.spec.materials[2].moduli.E);
  EXPECT_EQ(a.spec.bodies[3].shape.center, b.spec.bodies[3].shape.center);
  std::remove(path.c_str());
}

// Concentric layers take disjoint lattice sites whose union is the outer sphere's.
TEST(SceneBuilder, LayeredSpheresPartitionTheOuterSphere) {
  SceneSpec s = load_scene(kScenes + "snowball_pair.toml", {}).spec;
  std::vector<Point> x, v;
  std::size_t layers = 0;
  for (std::size_t b = 0; b < 3; ++b) {
    fill_body(s, b, x, v);
    layers += x.size();
  }
  s.bodies.resize(1);
  s.bodies[0].shape.radius = 0.035;
  fill_body(s, 0, x, v);
  EXPECT_EQ(layers, x.size());
  EXPECT_GT(layers, 150000u);
}

TEST(SceneBuilder, AngularVelocitySpinsAboutTheCentreOfMass) {
  SceneSpec s = load_scene(kScenes + "snowball_pair.toml", {}).spec;
  s.bodies[0].velocity = {0, 0, 0};
  s.bodies[0].angular_velocity = {0, 0, 10};
  std::vector<Point> x, v;
  fill_body(s, 0, x, v);
  double p[3] = {0, 0, 0}, L = 0, I = 0;
  Point c = {0, 0, 0};  // centre of mass of the particles
  for (const Point& q : x)
    for (int d = 0; d < 3; ++d) c[d] += q[d] / double(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (int d = 0; d < 3; ++d) p[d] += v[i][d];
    const double rx = x[i][0] - c[0], ry = x[i][1] - c[1];
    L += rx * v[i][1] - ry * v[i][0];
    I += rx * rx + ry * ry;
  }
  const double round_off = 1e-13 * double(x.size());  // sums of ~0.1 m/s terms
  EXPECT_NEAR(p[0], 0, round_off);
  EXPECT_NEAR(p[1], 0, round_off);
  EXPECT_NEAR(L / I, 10, 1e-9);
}

// A rubber tire's tread, carcass band and sidewalls go to their own materials' tables, each part
// where the tire's geometry puts it; a part of another part's table joins that table.
TEST(SceneBuilder, RubberTirePartsTakeTheirMaterials) {
  const std::string text = R"(
[simulation]
domain_min = ["-220 mm", "-20 mm", "-80 mm"]
domain_max = ["220 mm", "420 mm", "80 mm"]
dx = "8 mm"
particles_per_cell = 8
end_time = "1 ms"
[materials.tread]
preset = "thesis_tire_rubber"
[materials.cord]
model = "neo_hookean"
density = 1100
E = "200 MPa"
nu = 0.3
[materials.side]
model = "bimodular"
density = 1100
E = "200 MPa"
nu = 0.0
compression_ratio = 0.05
[tire]
body = "rubber"
material = "tread"
carcass_material = "cord"
sidewall_material = "side"
carcass = "8 mm"
tread = "slick"
pressure = "200 kPa"
center = ["0 mm", "202 mm", "0 mm"]
speed = 0.0
)";
  const double radius = 0.2, tread_base = radius - 0.012, carcass_inner = tread_base - 0.008;
  for (const bool own_sidewall : {true, false}) {
    SceneOptions o;
    if (!own_sidewall) o.overrides = {"tire.sidewall_material=cord"};
    const SceneSpec s = load_scene_text(text, "tire_parts.toml", o).spec;
    Simulation<double, backend::Serial> sim(s.config);
    const BuiltScene built = build_scene(s, sim);
    sim.prepare();
    ASSERT_EQ(sim.material_count(), 3u);
    ASSERT_EQ(built.rubber.second, 1);
    ASSERT_EQ(built.carcass.second, 1);
    ASSERT_EQ(built.sidewall.second, own_sidewall ? 1 : 0);
    const ParticleView<double> pv = sim.particles();
    // Each part's particles lie where its radius about the axle says: the tread above the carcass,
    // the sidewalls below it, the carcass band between (with the sidewalls when they share its table).
    const auto radii_within = [&](std::pair<int, int> part, double lo, double hi) {
      const ParticleRange r = sim.material_range(part.first);
      for (std::size_t p = r.begin; p < r.end; ++p) {
        const double radial = std::hypot(pv.x[0][p], pv.x[1][p] - 0.202);
        EXPECT_TRUE(radial >= lo && radial < hi) << "radius " << radial << " outside [" << lo << ", " << hi << ")";
      }
      return r.end - r.begin;
    };
    const std::size_t tread = radii_within(built.rubber, tread_base, radius);
    const std::size_t carcass = radii_within(built.carcass, own_sidewall ? carcass_inner : 0.0, tread_base);
    const std::size_t sidewall = own_sidewall ? radii_within(built.sidewall, 0.0, carcass_inner) : 0;
    EXPECT_GT(tread, 0u);
    EXPECT_GT(carcass, 0u);
    EXPECT_EQ(sidewall > 0, own_sidewall);
    EXPECT_EQ(tread + carcass + sidewall, fill_rubber_tire(s).positions.size());
  }
}

// A load spreads its total force over the particles in its region: sum m a = F, ramped.
TEST(Loads, TotalForceIsSharedByMassAndRamped) {
  SimulationConfig c;
  c.gravity = {0, 0, 0};
  Simulation<double, backend::Serial> sim(c);
  sim.add_material({"snow", "neo_hookean", 400, ElasticModuli::from_E_nu(1e5, 0.2)});
  sim.add_particles(0, fill_box({0, 0, 0}, 0.01, 2, {0.3, 0.3, 0.3}, {0.5, 0.4, 0.4}), {0, 0, 0}, 1.25e-7);
  sim.add_load({0.45, 0.3, 0.3}, {0.5, 0.4, 0.4}, {0.01, 0, 0}, 1e-3);
  auto total = [&] {
    const ParticleView<double> pv = sim.particles();
    double f = 0;
    for (std::size_t p = 0; p < pv.n; ++p) f += pv.mass[p] * pv.body_accel[0][p];
    return f;
  };
  sim.step(2.5e-4);
  EXPECT_NEAR(total(), 0.01 * 0.25, 1e-15);
  sim.advance_to(2e-3);
  EXPECT_NEAR(total(), 0.01, 1e-15);
}

}  // namespace
}  // namespace firn

// The stability guard stops a run on NaN/Inf, J <= 0, a particle moving more than one cell in a
// step and a particle leaving the grid, naming step, particle and material.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "engine/simulation.hpp"
#include "kernels/backend/serial.hpp"
#include "kernels/guard_summary.hpp"

namespace firn {
namespace {

struct GuardCase {
  SimulationConfig config;
  Simulation<float, backend::Serial> sim{config};
  int material;
  GuardCase() {
    material = sim.add_material({"snow", "neo_hookean", 400, ElasticModuli::from_E_nu(1.4e5, 0.2)});
    sim.add_particles(material, fill_box(config.domain_min, config.dx, 2, {0.4, 0.4, 0.4}, {0.5, 0.5, 0.5}),
                      {0, 0, 0}, 1e-7);
    sim.prepare();
  }
  // Index of the particle with the given id.
  std::size_t find(std::uint32_t id) {
    const ParticleView<float> pv = sim.particles();
    for (std::size_t p = 0; p < pv.n; ++p)
      if (pv.id[p] == id) return p;
    return 0;
  }
  std::string error_of_next_steps() {
    try {
      for (int s = 0; s < 3; ++s) sim.step();
    } catch (const StabilityError& e) {
      return e.what();
    }
    return "";
  }
};

TEST(StabilityGuard, CatchesNaNVelocity) {
  GuardCase c;
  c.sim.step();
  c.sim.particles().v[0][c.find(17)] = std::numeric_limits<float>::quiet_NaN();
  // P2G spreads the NaN to the neighbours; the lowest-index victim is named.
  const std::string msg = c.error_of_next_steps();
  EXPECT_NE(msg.find("NaN"), std::string::npos) << msg;
  EXPECT_NE(msg.find("material 'snow'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("step 1,"), std::string::npos) << msg;
}

TEST(StabilityGuard, NamesTheParticleWhoseStressIsNaN) {
  GuardCase c;
  c.sim.particles().F[4][c.find(17)] = std::numeric_limits<float>::quiet_NaN();
  const std::string msg = c.error_of_next_steps();
  EXPECT_NE(msg.find("NaN"), std::string::npos) << msg;
  EXPECT_NE(msg.find("particle 17 "), std::string::npos) << msg;
  EXPECT_NE(msg.find("step 0,"), std::string::npos) << msg;
}

TEST(StabilityGuard, CatchesInversion) {
  GuardCase c;
  ParticleView<float> pv = c.sim.particles();
  const std::size_t p = c.find(5);
  pv.F[0][p] = -1;  // det F = -1
  const std::string msg = c.error_of_next_steps();
  EXPECT_NE(msg.find("J <= 0"), std::string::npos) << msg;
  EXPECT_NE(msg.find("particle 5 "), std::string::npos) << msg;
}

TEST(StabilityGuard, CatchesTooLargeStep) {
  GuardCase c;
  const ParticleView<float> pv = c.sim.particles();
  for (std::size_t p = 0; p < pv.n; ++p) pv.v[1][p] = 50;  // 50 m/s for 1 ms is 5 cells
  std::string msg;
  try {
    c.sim.step(1e-3);
  } catch (const StabilityError& e) {
    msg = e.what();
  }
  EXPECT_NE(msg.find("more than one cell"), std::string::npos) << msg;
}

TEST(StabilityGuard, CatchesParticleLeavingTheGrid) {
  GuardCase c;
  c.sim.particles().x[2][c.find(3)] = 7.0f;  // far outside the unit domain
  const std::string msg = c.error_of_next_steps();
  EXPECT_NE(msg.find("left the grid"), std::string::npos) << msg;
  EXPECT_NE(msg.find("particle 3 "), std::string::npos) << msg;
}

// Of several particles outside (one of them not finite), the binning names the first in memory.
TEST(StabilityGuard, NamesTheFirstOfSeveralParticlesLeavingTheGrid) {
  GuardCase c;
  const std::size_t a = c.find(11), b = c.find(3), d = c.find(20);
  c.sim.particles().x[0][a] = std::numeric_limits<float>::quiet_NaN();
  c.sim.particles().x[1][b] = -3.0f;
  c.sim.particles().x[2][d] = 7.0f;
  const std::size_t first = std::min({a, b, d});
  const std::uint32_t id = first == a ? 11 : first == b ? 3 : 20;
  const std::string msg = c.error_of_next_steps();
  EXPECT_NE(msg.find("left the grid"), std::string::npos) << msg;
  EXPECT_NE(msg.find("particle " + std::to_string(id) + " "), std::string::npos) << msg;
  EXPECT_NE(msg.find("step 0,"), std::string::npos) << msg;
}

TEST(StabilityGuard, QuietOnAHealthyRun) {
  GuardCase c;
  EXPECT_EQ(c.error_of_next_steps(), "");
}

// GuardSummary::add classifies one particle's check: every reason, its boundaries (J = 0 is
// inverted, a move of exactly a cell is not too fast), a sum of finite values that overflows, and
// the lowest offender winning in either order of arrival.
TEST(GuardSummary, ClassifiesEachCheck) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const float big = std::numeric_limits<float>::max(), cell = 0.01f;
  struct Case {
    float speed, J, moved;
    GuardReason reason;
  };
  const Case cases[] = {
      {1.0f, 1.0f, 0.005f, GuardReason::none},       {1.0f, 1.0f, cell, GuardReason::none},
      {1.0f, 1.0f, 0.0101f, GuardReason::too_fast},  {1.0f, 0.0f, 0.005f, GuardReason::inverted},
      {1.0f, -0.5f, 0.005f, GuardReason::inverted},  {nan, 1.0f, 0.005f, GuardReason::not_finite},
      {inf, 1.0f, 0.005f, GuardReason::not_finite},  {1.0f, -inf, 0.005f, GuardReason::not_finite},
      {1.0f, nan, 0.005f, GuardReason::not_finite},  {1.0f, 1.0f, inf, GuardReason::not_finite},
      {1.0f, inf, 0.005f, GuardReason::not_finite},
      {big, 1.0f, big, GuardReason::too_fast},       {big, big, 0.005f, GuardReason::none},
  };
  for (const Case& k : cases) {
    GuardSummary<float> g;
    g.add(7, k.speed, k.J, k.moved, cell);
    EXPECT_EQ(g.reason, k.reason) << k.speed << " " << k.J << " " << k.moved;
    EXPECT_EQ(g.offender, k.reason == GuardReason::none ? kNoParticle : std::size_t(7));
    if (k.reason == GuardReason::none) {  // the largest speed and smallest J count every particle
      EXPECT_EQ(g.max_speed, k.speed);
      EXPECT_EQ(g.min_J, k.J);
    }
  }
  GuardSummary<float> a, b;
  a.add(9, 1.0f, -1.0f, 0.0f, cell);
  a.add(4, 1.0f, 1.0f, 0.5f, cell);
  b.add(4, 1.0f, 1.0f, 0.5f, cell);
  b.add(9, 1.0f, -1.0f, 0.0f, cell);
  for (const GuardSummary<float>& g : {a, b}) {
    EXPECT_EQ(g.offender, 4u);
    EXPECT_EQ(g.reason, GuardReason::too_fast);
    EXPECT_EQ(g.J, 1.0f);
    EXPECT_EQ(g.moved, 0.5f);
    EXPECT_EQ(g.min_J, -1.0f);
  }
}

}  // namespace
}  // namespace firn

// Mirror walls (kernels/step/mirror_walls.hpp): half of a body that is symmetric about the plane
// x = 0, against a mirror wall on that plane, must move as the same half of the whole body does
// without any wall, to round-off:
//   - a slip mirror (symmetry plane) for any motion that is mirror-symmetric, v_x odd in x and v_y,
//     v_z even, here a nonlinear neo-Hookean block squeezed toward the plane, with a body force
//     toward the plane on both sides (the fold's gravity correction) and gravity along it;
//   - a clamped (sticky) mirror for a bar in uniaxial motion along x (nu = 0), v_x odd in x.
// The plain sticky wall, which cuts the B-spline support at the wall, misses the second case by
// far more than round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "engine/particle_fill.hpp"
#include "engine/simulation.hpp"
#include "kernels/backend/openmp.hpp"

namespace firn {
namespace {

constexpr double kDx = 0.05, kHalfWidth = 0.2, kDt = 1e-4;
constexpr double kPull = 5;  // body force toward the plane, m/s^2
constexpr int kSteps = 300;

enum class Case { symmetric_block, clamped_bar };

// Reference position x0 and state (position, velocity) of one particle.
struct Sample {
  std::array<double, 3> x0, x, v;
};

// The particles with x0 > 0 after kSteps, ordered by reference position.
std::vector<Sample> run(Case which, bool half, bool mirror, Transfer transfer, Shape shape) {
  const bool block = which == Case::symmetric_block;
  SimulationConfig c;
  c.dx = kDx;
  c.domain_min = {half ? -2 * kDx : -0.5, 0, 0};
  c.domain_max = {0.5, 0.6, 0.6};
  c.fixed_dt = kDt;
  c.transfer = transfer;
  c.shape = shape;
  c.gravity = {half && block ? -kPull : 0, block ? -9.81 : 0, 0};
  for (auto& w : c.walls) w = {WallType::none, 3, 0};
  if (half) c.walls[0] = {block ? WallType::slip : WallType::sticky, 3, 0, mirror};
  Simulation<double, backend::OpenMP> sim(c);
  const int m = sim.add_material({"body", block ? "neo_hookean" : "fixed_corotated", 1000,
                                  ElasticModuli::from_E_nu(1e5, block ? 0.3 : 0.0)});
  const double x_lo = half ? 0 : -kHalfWidth;
  sim.add_particles(m, fill_box(c.domain_min, kDx, 2, {x_lo, 0.2, 0.2}, {kHalfWidth, 0.4, 0.35}), {0, 0, 0},
                    std::pow(kDx / 2, 3));
  sim.enable(Attribute::x0);
  if (block && !half) sim.enable(Attribute::body_accel);
  sim.prepare();
  ParticleView<double> pv = sim.particles();
  for (std::size_t p = 0; p < pv.n; ++p) {
    const double x = pv.x[0][p], y = pv.x[1][p];
    pv.v[0][p] = -3 * x + (block ? 4 * x * x * x : 0);  // odd in x
    pv.v[1][p] = block ? 0.5 * x * x + 0.4 * (y - 0.3) : 0;    // even in x
    pv.v[2][p] = block ? 0.3 * x * x : 0;
    if (block && !half) pv.body_accel[0][p] = x > 0 ? -kPull : kPull;
  }
  for (int s = 0; s < kSteps; ++s) sim.step();
  pv = sim.particles();
  std::vector<Sample> out;
  for (std::size_t p = 0; p < pv.n; ++p)
    if (pv.x0[0][p] > 0)
      out.push_back({{pv.x0[0][p], pv.x0[1][p], pv.x0[2][p]},
                     {pv.x[0][p], pv.x[1][p], pv.x[2][p]},
                     {pv.v[0][p], pv.v[1][p], pv.v[2][p]}});
  // The two runs' lattices are the same up to the rounding of their origins: order by the lattice
  // point, in micrometres.
  auto key = [](const Sample& s) {
    return std::array<long long, 3>{std::llround(s.x0[0] * 1e6), std::llround(s.x0[1] * 1e6), std::llround(s.x0[2] * 1e6)};
  };
  std::sort(out.begin(), out.end(), [&](const Sample& a, const Sample& b) { return key(a) < key(b); });
  return out;
}

// Largest difference in position (m) and velocity (m/s) between the same particles of two runs.
std::array<double, 2> largest_difference(const std::vector<Sample>& a, const std::vector<Sample>& b) {
  EXPECT_EQ(a.size(), b.size());
  std::array<double, 2> worst = {0, 0};
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    for (int d = 0; d < 3; ++d) {
      EXPECT_NEAR(a[i].x0[d], b[i].x0[d], 1e-12);
      worst[0] = std::max(worst[0], std::fabs(a[i].x[d] - b[i].x[d]));
      worst[1] = std::max(worst[1], std::fabs(a[i].v[d] - b[i].v[d]));
    }
  return worst;
}

class MirrorWall : public ::testing::TestWithParam<std::tuple<Transfer, Shape>> {};

TEST_P(MirrorWall, SlipMirrorMovesHalfABodyAsTheWholeSymmetricBody) {
  const auto [transfer, shape] = GetParam();
  const std::vector<Sample> whole = run(Case::symmetric_block, false, false, transfer, shape);
  const std::vector<Sample> half = run(Case::symmetric_block, true, true, transfer, shape);
  const std::array<double, 2> d = largest_difference(whole, half);
  // The block moves by centimetres at about 1 m/s; different summation orders only.
  EXPECT_LT(d[0], 1e-12);
  EXPECT_LT(d[1], 1e-10);
}

TEST_P(MirrorWall, ClampedMirrorHoldsABarAsTheWholeOddBar) {
  const auto [transfer, shape] = GetParam();
  const std::vector<Sample> whole = run(Case::clamped_bar, false, false, transfer, shape);
  const std::array<double, 2> mirrored = largest_difference(whole, run(Case::clamped_bar, true, true, transfer, shape));
  const std::array<double, 2> plain = largest_difference(whole, run(Case::clamped_bar, true, false, transfer, shape));
  EXPECT_LT(mirrored[0], 1e-12);
  EXPECT_LT(mirrored[1], 1e-10);
  EXPECT_GT(plain[1], 1e-3);  // the cut support: a visible error
}

INSTANTIATE_TEST_SUITE_P(TransfersAndShapes, MirrorWall,
                         ::testing::Combine(::testing::Values(Transfer::apic, Transfer::flip),
                                            ::testing::Values(Shape::quadratic, Shape::cubic)));

TEST(MirrorWall, RejectsWhatAMirrorCannotImpose) {
  auto make = [](Wall<double> wall) {
    SimulationConfig c;
    c.walls[1] = wall;
    Simulation<double, backend::OpenMP> sim(c);
  };
  EXPECT_THROW(make({WallType::separate, 3, 0, true}), std::invalid_argument);
  EXPECT_THROW(make({WallType::slip, 3, 0.3, true}), std::invalid_argument);
  EXPECT_THROW(make({WallType::sticky, 1, 0, true}), std::invalid_argument);
  EXPECT_NO_THROW(make({WallType::sticky, 2, 0, true}));
  EXPECT_NO_THROW(make({WallType::slip, 3, 0, true}));
}

}  // namespace
}  // namespace firn

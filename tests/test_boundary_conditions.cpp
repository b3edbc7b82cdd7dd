// Wall velocity conditions: sticky, slip and separate, with Coulomb friction.
#include <gtest/gtest.h>

#include "kernels/boundary_conditions.hpp"

namespace firn {
namespace {

const double kUp[3] = {0, 1, 0};  // floor normal, pointing into the material

TEST(Walls, StickyStops) {
  double v[3] = {1, -2, 3};
  apply_wall(v, kUp, WallType::sticky, 0.0);
  EXPECT_EQ(v[0], 0);
  EXPECT_EQ(v[1], 0);
  EXPECT_EQ(v[2], 0);
}

TEST(Walls, SlipRemovesNormalBothWays) {
  double in[3] = {1, -2, 3}, out[3] = {1, 2, 3};
  apply_wall(in, kUp, WallType::slip, 0.0);
  apply_wall(out, kUp, WallType::slip, 0.0);
  EXPECT_EQ(in[1], 0);
  EXPECT_EQ(out[1], 0);
  EXPECT_EQ(in[0], 1);
  EXPECT_EQ(out[2], 3);
}

TEST(Walls, SeparateLetsGo) {
  double leaving[3] = {1, 2, 3}, arriving[3] = {1, -2, 3};
  apply_wall(leaving, kUp, WallType::separate, 0.5);
  apply_wall(arriving, kUp, WallType::separate, 0.0);
  EXPECT_EQ(leaving[1], 2);
  EXPECT_EQ(leaving[0], 1);  // no friction when separating
  EXPECT_EQ(arriving[1], 0);
  EXPECT_EQ(arriving[0], 1);
}

TEST(Walls, CoulombFrictionReducesSlip) {
  // |v_t| = 5, |v_n| = 2, mu = 0.5: v_t shrinks by mu |v_n| = 1 to 4.
  double v[3] = {3, -2, 4};
  apply_wall(v, kUp, WallType::separate, 0.5);
  EXPECT_NEAR(v[0], 3 * 0.8, 1e-15);
  EXPECT_NEAR(v[2], 4 * 0.8, 1e-15);
  EXPECT_EQ(v[1], 0);
  // Friction large enough to stop the slip entirely, never to reverse it.
  double w[3] = {3, -2, 4};
  apply_wall(w, kUp, WallType::slip, 10.0);
  EXPECT_EQ(w[0], 0);
  EXPECT_EQ(w[2], 0);
}

TEST(Walls, NoneLeavesVelocity) {
  double v[3] = {1, -2, 3};
  apply_wall(v, kUp, WallType::none, 1.0);
  EXPECT_EQ(v[1], -2);
}

}  // namespace
}  // namespace firn

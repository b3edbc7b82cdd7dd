// Colliders on the grid: shapes, rigid motion, boundary conditions, friction laws, and the
// reaction force and torque they feel.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/collider_body.hpp"
#include "kernels/backend/serial.hpp"
#include "engine/simulation.hpp"
#include "kernels/colliders.hpp"
#include "kernels/friction.hpp"
#include "kernels/grid_update.hpp"

namespace firn {
namespace {

TEST(Colliders, BoxDistanceAndNormalAreExact) {
  Collider<double> box;
  box.shape = ColliderShape::box;
  box.center[0] = 1.5, box.center[1] = box.center[2] = 0.5;  // spans [1, 2] x [0, 1] x [0, 1]
  for (double& h : box.half) h = 0.5;
  double n[3];
  const double outside[3] = {3, 0.5, 0.5}, corner[3] = {3, 2, 0.5}, inside[3] = {1.9, 0.5, 0.5};
  EXPECT_DOUBLE_EQ(box.distance(outside, n), 1);
  EXPECT_DOUBLE_EQ(n[0], 1);
  EXPECT_DOUBLE_EQ(box.distance(corner, n), std::sqrt(2.0));
  EXPECT_NEAR(box.distance(inside, n), -0.1, 1e-12);
  EXPECT_DOUBLE_EQ(n[0], 1);
}

TEST(Colliders, ARotatedBoxIsMeasuredInItsOwnFrame) {
  Collider<double> box;  // a unit cube turned 90 degrees about z: its body x axis is world y
  box.shape = ColliderShape::box;
  box.half[0] = 2, box.half[1] = 0.5, box.half[2] = 0.5;
  const double r[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
  for (int i = 0; i < 9; ++i) box.rotation[i] = r[i];
  double n[3];
  const double above[3] = {0, 3, 0}, beside[3] = {1, 0, 0};
  EXPECT_NEAR(box.distance(above, n), 1, 1e-12);  // 2 long along world y
  EXPECT_NEAR(n[1], 1, 1e-12);
  EXPECT_NEAR(box.distance(beside, n), 0.5, 1e-12);
  EXPECT_NEAR(n[0], 1, 1e-12);
}

TEST(Colliders, AStickyMovingPlaneImposesItsVelocity) {
  Collider<double> plane;  // the solid y <= 0.5, moving up at 1 m/s
  plane.center[1] = 0.5;
  plane.velocity[1] = 1;
  double v[3] = {3, -2, 1};
  const double x_in[3] = {0, 0.4, 0}, x_out[3] = {0, 0.6, 0};
  EXPECT_FALSE(plane.apply(v, x_out, 0.0));
  EXPECT_EQ(v[0], 3);
  EXPECT_TRUE(plane.apply(v, x_in, 0.0));
  EXPECT_EQ(v[0], 0);
  EXPECT_EQ(v[1], 1);
  EXPECT_EQ(v[2], 0);
}

// A node on the plane is outside whatever the rounding of its coordinate: the ground plane through
// a node row of the incline problems, computed as origin + i dx in float and in double, with and
// without a fused multiply-add, lands within rounding of zero on either side.
template <class T>
void expect_surface_nodes_outside() {
  const T dx = T(0.01), skin = T(kColliderSkin) * dx;
  Collider<T> ground;  // the solid y <= 0
  const T origin = T(-3 * 0.01);
  const T row[3] = {origin + T(3) * dx, std::fma(T(3), dx, origin), T(-1e-7) * dx};
  for (T y : row) {
    T v[3] = {T(1), T(-1), T(0)};
    const T x[3] = {T(0.05), y, T(0)};
    EXPECT_FALSE(ground.apply(v, x, skin)) << "y = " << y;
    EXPECT_EQ(v[1], T(-1));
  }
  T v[3] = {T(1), T(-1), T(0)};
  const T below[3] = {T(0.05), T(-0.01) * dx, T(0)};  // ten skins deep
  EXPECT_TRUE(ground.apply(v, below, skin));
  EXPECT_EQ(v[1], T(0));
}

TEST(Colliders, NodesOnTheSurfaceAreOutsideInFloatAndDouble) {
  expect_surface_nodes_outside<float>();
  expect_surface_nodes_outside<double>();
}

// A spinning sticky cylinder gives a node inside it the rigid velocity omega x r.
TEST(Colliders, ASpinningCylinderImposesOmegaCrossR) {
  Collider<double> wheel;
  wheel.shape = ColliderShape::cylinder;
  wheel.radius = 1, wheel.half[2] = 0.5;
  wheel.center[0] = 2;
  wheel.angular_velocity[2] = -3;
  double v[3] = {0, 0, 0}, n[3];
  const double bottom[3] = {2, -0.9, 0.1};
  EXPECT_NEAR(wheel.distance(bottom, n), -0.1, 1e-12);
  EXPECT_NEAR(n[1], -1, 1e-12);
  EXPECT_TRUE(wheel.apply(v, bottom, 0.0));
  EXPECT_NEAR(v[0], -2.7, 1e-12);  // (0, 0, -3) x (0, -0.9, 0.1) = (-2.7, 0, 0)
  EXPECT_NEAR(v[1], 0, 1e-12);
}

// The thesis' Figure 4.1: mu rises from 0 to mu0 at 1 mm/s, peaks at 110 mm/s, then falls.
TEST(Friction, VelocityDependentLawFollowsTheThesisCurve) {
  const Friction<double> f{FrictionLaw::velocity_dependent, 0.25};
  EXPECT_EQ(f.coefficient(0), 0);
  EXPECT_NEAR(f.coefficient(1e-3), 0.25, 1e-12);  // Eq. 4.9 at v = 1 mm/s: (12101 / 12101)^0.17
  const double peak = f.coefficient(0.110);
  EXPECT_NEAR(peak, 0.25 * std::pow(12101.0 * 110 / (2 * 12100), 0.17), 1e-12);
  EXPECT_NEAR(peak, 0.494, 1e-3);
  EXPECT_GT(peak, f.coefficient(0.100));
  EXPECT_GT(peak, f.coefficient(0.120));
  EXPECT_NEAR(f.coefficient(4.4704), 0.296, 1e-3);  // 10 mph
  EXPECT_LT(f.coefficient(10), f.coefficient(1));
  const Friction<double> coulomb{FrictionLaw::coulomb, 0.3};
  EXPECT_EQ(coulomb.coefficient(0), 0.3);
  EXPECT_EQ(coulomb.coefficient(7), 0.3);
}

// Friction at an approaching node: the normal velocity goes, the tangential one loses mu |v_n|.
TEST(Friction, WallUsesTheCoefficientAtTheSlipSpeed) {
  const double up[3] = {0, 1, 0};
  double v[3] = {0.110, -0.05, 0};
  apply_wall(v, up, WallType::separate, Friction<double>{FrictionLaw::velocity_dependent, 0.25});
  const double mu = Friction<double>{FrictionLaw::velocity_dependent, 0.25}.coefficient(0.110);
  EXPECT_NEAR(v[0], 0.110 - mu * 0.05, 1e-15);
  EXPECT_EQ(v[1], 0);
}

// A block of particles dropped on a fixed floor box: once resting, the floor carries its weight
// (force = m g upward... on the floor, downward), and the loaded axle's equation moves a collider.
TEST(ColliderReaction, AFloorCarriesTheWeightOfABlockResting) {
  SimulationConfig c;
  c.dx = 0.02;
  Simulation<double, backend::Serial> sim(c);
  sim.add_material({"rubber", "neo_hookean", 1000, ElasticModuli::from_E_nu(2e5, 0.3)});
  const double h = c.dx / 2;
  const auto x = fill_box({0, 0, 0}, c.dx, 2, {0.4, 0.3, 0.4}, {0.6, 0.4, 0.6});
  sim.add_particles(0, x, {0, 0, 0}, h * h * h);
  Collider<double> floor;
  floor.shape = ColliderShape::box;
  floor.center[0] = floor.center[2] = 0.5, floor.center[1] = 0.2;
  floor.half[0] = floor.half[2] = 0.3, floor.half[1] = 0.1;  // top at y = 0.3
  const int f = sim.add_collider(floor);
  sim.advance_to(0.3);
  ColliderBody& body = sim.collider(f);
  body.reset_impulse();
  sim.advance_to(0.5);
  const double weight = 1000 * 0.2 * 0.1 * 0.2 * 9.81;
  EXPECT_NEAR(body.impulse[1] / body.impulse_time, -weight, 0.02 * weight);
  EXPECT_NEAR(body.impulse[0] / body.impulse_time, 0, 1e-3 * weight);
  // Torque about the floor's centre (0.5, 0.2, 0.5) of a load centred above it: zero.
  EXPECT_NEAR(body.angular_impulse[2] / body.impulse_time, 0, 1e-3 * weight);
}

TEST(ColliderReaction, ALoadedAxleAcceleratesUnderItsNetForce) {
  ColliderBody axle;
  axle.motion = ColliderBody::Motion::loaded_axle;
  axle.mass = 2;
  axle.load = 30;
  const double f[3] = {0, 10, 0}, t[3] = {0, 0, 0};
  axle.add_reaction(f, t, 0.01);
  axle.advance(0.01);
  EXPECT_NEAR(axle.collider.velocity[1], -0.1, 1e-15);  // (10 - 30) / 2 * 0.01
  EXPECT_NEAR(axle.collider.center[1], -0.001, 1e-15);
}

// A free spin: I dw_z/dt = T_z, angular velocity first, then the rotation turns by the new rate.
TEST(ColliderReaction, AFreeSpinTurnsUnderItsTorque) {
  ColliderBody wheel;
  wheel.free_spin = true;
  wheel.inertia = 0.5;
  wheel.collider.angular_velocity[2] = -1;
  const double f[3] = {0, 0, 0}, t[3] = {0.3, 0.2, -4};  // only the torque about the axle (z) turns it
  wheel.add_reaction(f, t, 0.01);
  wheel.advance(0.01);
  EXPECT_NEAR(wheel.collider.angular_velocity[2], -1.08, 1e-15);  // -1 + (-4) / 0.5 * 0.01
  EXPECT_EQ(wheel.collider.angular_velocity[0], 0);
  EXPECT_EQ(wheel.collider.angular_velocity[1], 0);
  EXPECT_NEAR(wheel.collider.rotation[3], std::sin(-0.0108), 1e-15);  // R(1, 0) after turning by w dt about z
  ColliderBody driven = wheel;
  driven.free_spin = false;
  driven.advance(0.01);
  EXPECT_EQ(driven.collider.angular_velocity[2], wheel.collider.angular_velocity[2]);  // prescribed: unchanged
}

}  // namespace
}  // namespace firn

namespace firn {
namespace {

// The box that holds a collider: a tire's rims and width, a turned box's corners, a plane unbounded.
TEST(Colliders, BoundsHoldTheSolid) {
  Collider<double> tire;
  tire.shape = ColliderShape::tire;
  tire.tire.radius = 0.2, tire.tire.width = 0.1;
  tire.center[1] = 0.3;
  double lo[3], hi[3];
  tire.bounds(lo, hi);
  EXPECT_NEAR(lo[0], -0.2, 1e-15);
  EXPECT_NEAR(hi[1], 0.5, 1e-15);
  EXPECT_NEAR(hi[2], 0.05, 1e-15);
  Collider<double> box;  // half extents (1, 0.5, 0.5) turned 90 degrees about z
  box.shape = ColliderShape::box;
  box.half[0] = 1, box.half[1] = box.half[2] = 0.5;
  const double r[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
  for (int i = 0; i < 9; ++i) box.rotation[i] = r[i];
  box.bounds(lo, hi);
  EXPECT_NEAR(hi[0], 0.5, 1e-15);
  EXPECT_NEAR(hi[1], 1, 1e-15);
  Collider<double> plane;
  plane.bounds(lo, hi);
  EXPECT_TRUE(std::isinf(hi[1]));
}

// grid_update_block skips, for a whole block, the colliders whose bounding box is farther than the
// skin from the block's nodes (colliders_near_block). That may change nothing: no node of a skipped
// block is inside such a collider by more than the skin, or, for a pooled collider, nearer than half
// a cell outside it (kernels/pooled_contact.hpp). Checked for turned shapes on every block of a grid
// around them, in float and double, where both kinds of block occur.
template <class T>
void check_skipped_blocks_hold_no_node(ColliderContact contact) {
  GridUpdateParams<T> p{};
  p.dx = T(0.01);
  for (int d = 0; d < 3; ++d) p.origin[d] = T(-0.32);
  const double angle = 0.4, tilt = 0.15;  // about z, then about x: R = Rz(angle) Rx(tilt)
  const double ca = std::cos(angle), sa = std::sin(angle), ct = std::cos(tilt), st = std::sin(tilt);
  const double r[9] = {ca, -sa * ct, sa * st, sa, ca * ct, -ca * st, 0, st, ct};
  Collider<double> shapes[4];
  shapes[0].shape = ColliderShape::tire;
  shapes[0].tire.radius = 0.15, shapes[0].tire.width = 0.08;
  shapes[1].shape = ColliderShape::box;
  shapes[1].half[0] = 0.1, shapes[1].half[1] = 0.03, shapes[1].half[2] = 0.05;
  shapes[1].center[0] = 0.12;
  shapes[2].shape = ColliderShape::cylinder;
  shapes[2].radius = 0.06, shapes[2].half[2] = 0.04;
  shapes[2].center[1] = -0.15;
  shapes[3].center[1] = -0.25;  // a plane: skipped by the distance of the block's corners
  for (Collider<double>& c : shapes)
    for (int i = 0; i < 9; ++i) c.rotation[i] = r[i];
  p.collider_count = 4;
  for (Collider<double>& c : shapes) c.contact = contact;
  for (int c = 0; c < 4; ++c) p.colliders[c] = collider_cast<T>(shapes[c]);
  const T reach = contact == ColliderContact::pooled ? T(0.5) * p.dx : -T(kColliderSkin) * p.dx;
  int skipped[4] = {}, kept[4] = {};
  for (int bx = 0; bx < 16; ++bx)
    for (int by = 0; by < 16; ++by)
      for (int bz = 0; bz < 16; ++bz) {
        const int block[3] = {bx, by, bz};
        const std::uint32_t near = colliders_near_block(block, p);
        for (int c = 0; c < 4; ++c) {
          if (near >> c & 1u) {
            ++kept[c];
            continue;
          }
          ++skipped[c];
          for (int l = 0; l < kBlockNodes; ++l) {
            int node[3];
            block_node(block, l, node);
            const T x[3] = {p.origin[0] + T(node[0]) * p.dx, p.origin[1] + T(node[1]) * p.dx,
                            p.origin[2] + T(node[2]) * p.dx};
            T n[3];
            ASSERT_GE(p.colliders[c].distance(x, n), reach) << "collider " << c << " node " << l << " of block "
                                                            << bx << " " << by << " " << bz;
          }
        }
      }
  for (int c = 0; c < 4; ++c) {
    EXPECT_GT(skipped[c], 0) << "collider " << c;
    EXPECT_GT(kept[c], 0) << "collider " << c;
  }
}

TEST(Colliders, BlocksSkipOnlyCollidersThatHoldNoneOfTheirNodes) {
  for (const ColliderContact contact : {ColliderContact::nodes, ColliderContact::pooled}) {
    check_skipped_blocks_hold_no_node<float>(contact);
    check_skipped_blocks_hold_no_node<double>(contact);
  }
}

}  // namespace
}  // namespace firn

// The pooled collider contact (kernels/pooled_contact.hpp): what one block's update does with a
// known lambda, the sums lambda is solved from, the guard that keeps material out of the collider,
// a body resting on a pooled ground through the whole step, its moments scattered only near the
// collider against the whole scatter, and the solve for lambda and the friction share
// (engine/contact_pool_solve.hpp) at each of its ends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "engine/contact_pool_solve.hpp"
#include "engine/particle_fill.hpp"
#include "engine/simulation.hpp"
#include "kernels/backend/openmp.hpp"
#include "kernels/backend/serial.hpp"
#include "kernels/grid_update.hpp"
#include "kernels/pooled_contact.hpp"
#include "kernels/step/contact_pool_moments.hpp"
#include "kernels/step/contact_pool_sums.hpp"

namespace firn {
namespace {

using Ch = GridChannels<Transfer::apic>;
constexpr double kDx = 0.1, kDt = 1e-3, kPlane = 0.16;  // the solid y <= 0.16: node rows y = 0 and 0.1 inside

// One block at the origin, every node of mass 1. The nodes inside the ground approach it at
// 1 + (i - 1.5) m/s (i the node's x index: a mean approach of 1 and a turn across the contact;
// the nodes at i = 0 leave it);
// the others move along x at 0.2 m/s. The material of every node lies 0.3 m above it, out of the
// ground, unless `held` (then at the node itself, inside it).
struct OneBlock {
  std::vector<double> data = std::vector<double>(Ch::kCount * kBlockNodes, 0.0);
  std::vector<double> moments = std::vector<double>(kContactNormalChannels * kBlockNodes, 0.0);
  int coords[3] = {0, 0, 0};
  GridUpdateParams<double> p{};
  std::vector<double> reactions = std::vector<double>(kReactionComponents, 0.0);

  explicit OneBlock(bool held_ahead) {
    p.dt = kDt;
    p.dx = kDx;
    p.min_mass = 1e-12;
    p.damping_factor = 1;
    for (int d = 0; d < 3; ++d) p.nodes[d] = 4;
    p.collider_count = 1;
    Collider<double>& ground = p.colliders[0];
    ground.shape = ColliderShape::plane;
    ground.center[1] = kPlane;
    ground.boundary = WallType::separate;
    ground.contact = ColliderContact::pooled;
    p.reactions = reactions.data();
    p.footprint_collider = -1;
    p.moments = GridSlotsView<double>{moments.data(), coords, kContactNormalChannels};
    for (int l = 0; l < kBlockNodes; ++l) {
      int n[3];
      block_node(coords, l, n);
      data[Ch::kMass * kBlockNodes + l] = 1;
      if (n[1] * kDx < kPlane) data[(Ch::kVelocity + 1) * kBlockNodes + l] = -(1 + (n[0] - 1.5));
      else data[Ch::kVelocity * kBlockNodes + l] = 0.2;
      const bool held = held_ahead && n[0] == 3;
      moments[kBlockNodes + l] = held ? 0 : 0.3 / kDx;  // sum m w (x_p - x_i) / dx along y
    }
  }
  double vy(int l) const { return data[(Ch::kVelocity + 1) * kBlockNodes + l]; }
  double vx(int l) const { return data[Ch::kVelocity * kBlockNodes + l]; }
  static bool inside(int l) {
    const int c[3] = {0, 0, 0};
    int n[3];
    block_node(c, l, n);
    return n[1] * kDx < kPlane;
  }
};

// Every node inside takes the same normal velocity change, lambda, and keeps its share of the turn;
// the force on the ground is the pool's whole impulse. Node by node, only the approaching nodes
// would take any, most of it ahead, and more in all.
TEST(PooledContact, RemovesTheMeanApproachUniformlyAndKeepsTheTurn) {
  OneBlock b(false);
  const double lambda = 1;  // the mean approach
  const ContactPoolSums<double, Transfer::apic> sums{GridSlotsView<double>{b.data.data(), b.coords, Ch::kCount}, &b.p,
                                                     0, lambda};
  DoubleSums<kPoolSums> s;
  sums(0, s);
  EXPECT_DOUBLE_EQ(s.v[0], 32);   // two rows of 16 nodes inside
  EXPECT_DOUBLE_EQ(s.v[1], -32);  // sum m v_n
  EXPECT_NEAR(s.v[2], 0, 1e-12);  // S(1): no approach on average
  EXPECT_DOUBLE_EQ(s.v[3], 32);   // no node held by its guard
  EXPECT_DOUBLE_EQ(s.v[4], 32);   // the pool's normal impulse per dt, sum m max(lambda, least)
  EXPECT_NEAR(s.v[5], 16 * 0.2, 1e-12);  // the surface row's demand, sum m |v_t|
  EXPECT_DOUBLE_EQ(s.v[6], 16);   // and its mass

  std::vector<double> before(b.data);
  b.p.pool_lambda[0] = lambda;
  b.p.pool_keep[0] = 1;  // 1 - capacity / demand
  grid_update_block<double, Transfer::apic>(b.data.data(), b.coords, 0, b.p);
  double impulse = 0;
  for (int l = 0; l < kBlockNodes; ++l) {
    const double v0 = before[(Ch::kVelocity + 1) * kBlockNodes + l];
    if (OneBlock::inside(l)) {
      EXPECT_NEAR(b.vy(l) - v0, lambda, 1e-12) << "node " << l;
      impulse += b.vy(l) - v0;
    } else {
      EXPECT_EQ(b.vy(l), v0) << "node " << l;
      EXPECT_EQ(b.vx(l), 0.2) << "node " << l;  // no friction: mu = 0
    }
  }
  EXPECT_NEAR(impulse, 32, 1e-12);
  EXPECT_NEAR(b.reactions[1], -32 / kDt, 1e-9);
  EXPECT_NEAR(b.reactions[5] / b.reactions[1], 0.15, 1e-12);  // the force acts at the middle column, x = 0.15
  // The node-by-node condition on the same velocities: only the approaching nodes, by their own
  // approach, with a moment that leans ahead (+x).
  OneBlock nodes(false);
  nodes.p.colliders[0].contact = ColliderContact::nodes;
  grid_update_block<double, Transfer::apic>(nodes.data.data(), nodes.coords, 0, nodes.p);
  EXPECT_NEAR(nodes.reactions[1], -8 * (0.5 + 1.5 + 2.5) / kDt, 1e-9);
  EXPECT_NEAR(nodes.reactions[5] / nodes.reactions[1], (0.1 * 0.5 + 0.2 * 1.5 + 0.3 * 2.5) / 4.5, 1e-12);
}

// Coulomb's bound on the whole contact: the capacity mu sum m dv_n of the inside nodes against the
// surface row's demand sum m |v_t|; the row keeps 1 - capacity / demand of its slip (as
// Simulation::solve_contact_pool sets it), and the ground feels exactly mu times its normal force.
TEST(PooledContact, TheSurfaceRowSlidesWithMuTimesThePoolsNormalImpulse) {
  OneBlock b(false);
  b.p.colliders[0].friction = {FrictionLaw::coulomb, 0.01};
  DoubleSums<kPoolSums> s;
  ContactPoolSums<double, Transfer::apic>{GridSlotsView<double>{b.data.data(), b.coords, Ch::kCount}, &b.p, 0, 1.0}(0, s);
  EXPECT_NEAR(s.v[4], 32, 1e-12);
  EXPECT_NEAR(s.v[5], 16 * 0.2, 1e-12);
  b.p.pool_lambda[0] = 1;
  b.p.pool_keep[0] = 1 - 0.01 * s.v[4] / s.v[5];  // 0.9
  grid_update_block<double, Transfer::apic>(b.data.data(), b.coords, 0, b.p);
  for (int l = 0; l < kBlockNodes; ++l) {
    int n[3];
    block_node(b.coords, l, n);
    if (n[1] == 2) {
      EXPECT_NEAR(b.vx(l), 0.18, 1e-12) << "node " << l;  // the surface row, y = 0.2
    } else if (n[1] == 3) {
      EXPECT_EQ(b.vx(l), 0.2) << "node " << l;  // beyond it
    }
  }
  EXPECT_NEAR(b.reactions[0] / b.reactions[1], -0.01, 1e-12);  // F_x = mu N, against the slip
}

// Where a node's material reaches the surface, the guard stops that node's approach on its own and
// the pool needs less: S(lambda) = 0 at the lambda that the other nodes' mean approach calls for.
TEST(PooledContact, TheGuardHoldsMaterialThatReachesTheSurface) {
  OneBlock b(true);
  const GridSlotsView<double> slots{b.data.data(), b.coords, Ch::kCount};
  // Nodes at i = 3 approach at 2.5 and are held: least = 2.5. The other 24 have v_n = 0.5, -0.5
  // and -1.5 (mean -0.5): S(lambda) = 8 (-2.5 + 2.5) + 24 (lambda - 0.5), zero at 0.5.
  for (const double lambda : {0.25, 0.5, 1.0}) {
    DoubleSums<kPoolSums> s;
    ContactPoolSums<double, Transfer::apic>{slots, &b.p, 0, lambda}(0, s);
    EXPECT_NEAR(s.v[2], 24 * (lambda - 0.5), 1e-12) << lambda;
    EXPECT_DOUBLE_EQ(s.v[3], 24) << lambda;
  }
  b.p.pool_lambda[0] = 0.5;
  b.p.pool_keep[0] = 1;
  grid_update_block<double, Transfer::apic>(b.data.data(), b.coords, 0, b.p);
  for (int l = 0; l < kBlockNodes; ++l) {
    int n[3];
    block_node(b.coords, l, n);
    if (!OneBlock::inside(l)) continue;
    if (n[0] == 3) EXPECT_NEAR(b.vy(l), 0, 1e-12) << "node " << l;  // held: stopped, not pushed back
    else EXPECT_NEAR(b.vy(l), -(1 + (n[0] - 1.5)) + 0.5, 1e-12) << "node " << l;
  }
}

// pool_node's guard: a node's material a gap g above the surface may approach at g / dt more,
// with g measured at the step's start (the collider is posed at its end).
TEST(PooledContact, TheGuardAllowsTheGapAndNoMore) {
  Collider<double> ground;
  ground.shape = ColliderShape::plane;
  ground.contact = ColliderContact::pooled;
  const double x[3] = {0, -0.05, 0}, v[3] = {0, -2, 0};
  double moment[3 * kBlockNodes] = {};
  moment[kBlockNodes] = 0.07 / kDx;  // x̄ 0.02 above the surface
  const PoolNode<double> q = pool_node(ground, x, v, 1.0, moment, kDx, 1e-4, kDt);
  EXPECT_EQ(q.role, kPoolInside);
  EXPECT_DOUBLE_EQ(q.vn, -2);
  EXPECT_NEAR(q.least, 2 - 0.02 / kDt, 1e-9);
  Collider<double> receding = ground;  // moving down at 1 m/s: the gap at the step's start is
  receding.velocity[1] = -1;           // 0.001 smaller than at its end, and v_n = -2 - (-1)
  EXPECT_NEAR(pool_node(receding, x, v, 1.0, moment, kDx, 1e-4, kDt).least, 1 - 0.019 / kDt, 1e-9);
  moment[kBlockNodes] = 0.03 / kDx;  // x̄ 0.02 inside
  EXPECT_NEAR(pool_node(ground, x, v, 1.0, moment, kDx, 1e-4, kDt).least, 2, 1e-12);
  const double above[3] = {0, 0.04, 0}, far[3] = {0, 0.06, 0};
  EXPECT_EQ(pool_node(ground, above, v, 1.0, moment, kDx, 1e-4, kDt).role, kPoolSurface);
  EXPECT_EQ(pool_node(ground, far, v, 1.0, moment, kDx, 1e-4, kDt).role, kPoolNone);
}

// A block dropped on a pooled ground through the whole step, its bounce damped (dynamic
// relaxation): once resting, the ground carries its weight, no particle's centre is below the
// surface, and one and two threads give the same state to the bit.
std::uint64_t rest_on_pooled_ground(int threads, double* force, double* lowest) {
  SimulationConfig c;
  c.dx = 0.02;
  c.damping = 20;  // 1/s
  Simulation<float, backend::OpenMP> sim(c, backend::OpenMP(threads));
  sim.add_material({"rubber", "neo_hookean", 1000, ElasticModuli::from_E_nu(2e5, 0.3)});
  const double h = c.dx / 2;
  sim.add_particles(0, fill_box({0, 0, 0}, c.dx, 2, {0.4, 0.31, 0.4}, {0.6, 0.41, 0.6}), {0, 0, 0}, h * h * h);
  Collider<double> ground;
  ground.shape = ColliderShape::plane;
  ground.center[1] = 0.3;
  ground.boundary = WallType::separate;
  ground.friction = {FrictionLaw::coulomb, 0.5};
  ground.contact = ColliderContact::pooled;
  const int g = sim.add_collider(ground);
  sim.advance_to(0.3);
  sim.collider(g).reset_impulse();
  sim.advance_to(0.5);
  *force = sim.collider(g).impulse[1] / sim.collider(g).impulse_time;
  const ParticleView<float> pv = sim.particles();
  *lowest = 1;
  for (std::size_t p = 0; p < pv.n; ++p) *lowest = std::min(*lowest, double(pv.x[1][p]));
  return sim.state_hash();
}

TEST(PooledContact, ABlockRestsOnPooledGroundTheSameOnOneAndTwoThreads) {
  double force1, lowest1, force2, lowest2;
  const std::uint64_t one = rest_on_pooled_ground(1, &force1, &lowest1);
  const std::uint64_t two = rest_on_pooled_ground(2, &force2, &lowest2);
  EXPECT_EQ(one, two);
  const double weight = 1000 * 0.2 * 0.1 * 0.2 * 9.81;
  EXPECT_NEAR(force1, -weight, 0.02 * weight);
  EXPECT_GE(lowest1, 0.3);
}

// A block pressed by gravity along +y against a pooled box above it while sliding along x, and a
// ball far below (its blocks are more than two blocks from the box, so
// kernels/step/contact_pool_moments.hpp skips them). The box is on the side the particles' stencils
// reach past their own block (+y), where a particle block that is not near the box itself adds
// moments to a block that is: the scatter must keep it (scattering only the blocks near the box
// themselves, margin 0, fails this test). every_block: the serial backend scatters every block,
// past the moments scatter's keeps(b).
std::uint64_t press_against_a_pooled_box(bool every_block, double* normal_impulse) {
  SimulationConfig c;
  c.dx = 0.02;
  c.gravity = {0, 9.81, 0};
  backend::Serial serial;
  serial.scatter_every_block = every_block;
  Simulation<float, backend::Serial> sim(c, serial);
  sim.add_material({"rubber", "neo_hookean", 1000, ElasticModuli::from_E_nu(2e5, 0.3)});
  const double h = c.dx / 2;
  sim.add_particles(0, fill_box({0, 0, 0}, c.dx, 2, {0.4, 0.41, 0.4}, {0.6, 0.55, 0.6}), {0.5, 0, 0}, h * h * h);
  sim.add_particles(0, fill_sphere({0, 0, 0}, c.dx, 2, {0.5, 0.2, 0.5}, 0.06), {0, 0, 0}, h * h * h);
  Collider<double> box;
  box.shape = ColliderShape::box;
  box.center[0] = box.center[2] = 0.5;
  box.center[1] = 0.61;  // its lower face at y = 0.56, on a block's first node row
  box.half[0] = box.half[2] = 0.3;
  box.half[1] = 0.05;
  box.boundary = WallType::separate;
  box.friction = {FrictionLaw::coulomb, 0.2};
  box.contact = ColliderContact::pooled;
  const int k = sim.add_collider(box);
  sim.advance_to(0.06);
  *normal_impulse = sim.collider(k).impulse[1];
  return sim.state_hash();
}

TEST(PooledContact, MomentsScatteredNearTheColliderGiveTheWholeScattersState) {
  double near_impulse = 0, whole_impulse = 0;
  const std::uint64_t near = press_against_a_pooled_box(false, &near_impulse);
  const std::uint64_t whole = press_against_a_pooled_box(true, &whole_impulse);
  EXPECT_EQ(near, whole);
  EXPECT_EQ(near_impulse, whole_impulse);
  EXPECT_GT(near_impulse, 0);  // the block reached the box and pressed on it
}

// The moments scatter keeps the blocks whose particles can reach a block near the pooled collider
// and leaves out the others, as every backend asks it (kernels/backend/scatter_skip.hpp). A keeps(b)
// the backends did not find (not const, misspelt) would scatter every block, which the state test
// above cannot tell from the restricted scatter.
TEST(PooledContact, TheMomentsScatterKeepsOnlyTheBlocksThatReachTheCollider) {
  GridUpdateParams<double> p{};
  p.dx = 0.1;
  for (int d = 0; d < 3; ++d) p.nodes[d] = 64;
  p.collider_count = 1;
  Collider<double>& ground = p.colliders[0];  // the solid y <= 0.16, in the first row of blocks
  ground.shape = ColliderShape::plane;
  ground.center[1] = 0.16;
  ground.boundary = WallType::separate;
  ground.contact = ColliderContact::pooled;
  ContactPoolMomentsScatter<double, QuadraticBSpline<double>> moments{};
  moments.grid.box = BlockBox{{16, 16, 16}};
  moments.params = &p;
  moments.collider = 0;
  EXPECT_TRUE(backend::scatter_keeps(moments, moments.grid.box.id(5, 0, 5)));   // at the ground
  EXPECT_TRUE(backend::scatter_keeps(moments, moments.grid.box.id(5, 1, 5)));   // reaching into that row
  EXPECT_FALSE(backend::scatter_keeps(moments, moments.grid.box.id(5, 3, 5)));  // too far above
}

// Simulation::solve_contact_pool's solve (engine/contact_pool_solve.hpp) on pools given node by node,
// each inside node's mass, normal velocity and guard, summed as kernels/step/contact_pool_sums.hpp
// sums them.
struct NodePool {
  struct Node {
    double m, vn, least;
  };
  std::vector<Node> inside;
  double demand = 0, row_mass = 0;  // the surface row's sum m |v_t| and sum m

  DoubleSums<kPoolSums> operator()(double lambda) const {
    DoubleSums<kPoolSums> s;
    for (const Node& q : inside) {
      const double dvn = std::max(lambda, q.least);
      s.v[0] += q.m;
      s.v[1] += q.m * q.vn;
      s.v[2] += q.m * (q.vn + dvn);
      if (q.least < lambda) s.v[3] += q.m;
      s.v[4] += q.m * dvn;
    }
    s.v[5] = demand;
    s.v[6] = row_mass;
    return s;
  }
  // The smallest lambda >= 0 with S(lambda) >= 0, by bisection (S increases).
  double smallest_root() const {
    if ((*this)(0.0).v[2] >= 0) return 0;
    double lo = 0, hi = 1;
    while ((*this)(hi).v[2] < 0) hi *= 2;
    for (int i = 0; i < 200; ++i) ((*this)(0.5 * (lo + hi)).v[2] < 0 ? lo : hi) = 0.5 * (lo + hi);
    return hi;
  }
};
const auto kFrictionless = [](double) { return 0.0; };

// Random pools whose guards hold up to a third of the nodes (their material at the surface:
// least = -v_n) with the rest free (far from it): Newton's lambda is the smallest feasible one, it
// is feasible, and it takes a few evaluations.
TEST(PooledContact, NewtonFindsTheSmallestFeasibleLambdaPastTheGuards) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  int held_somewhere = 0;
  for (int trial = 0; trial < 200; ++trial) {
    NodePool pool;
    const double held_share = u(rng) / 3;
    for (int i = 0; i < 40; ++i) {
      const double vn = -2 + 3 * u(rng), gap = u(rng) < held_share ? 0 : 10;
      pool.inside.push_back({0.5 + u(rng), vn, -vn - gap});
    }
    const DoubleSums<kPoolSums> s0 = pool(0.0);
    if (!(s0.v[1] < 0)) continue;
    const PoolSolution r = solve_pool(pool, kFrictionless);
    const double root = pool.smallest_root();
    held_somewhere += pool(root).v[3] < s0.v[0];
    EXPECT_NEAR(r.lambda, root, 1e-6 * (1 + root)) << "trial " << trial;
    EXPECT_GE(pool(r.lambda).v[2], -1e-9 * s0.v[0]) << "trial " << trial;
    EXPECT_LE(r.evaluations, 6) << "trial " << trial;
  }
  EXPECT_GT(held_somewhere, 50);  // the guards did hold nodes at the root in many trials
}

// Every inside node held by its guard at lambda_0 (each approaching at 1 with its material at the
// surface): S' = 0, lambda = 0, and every node still stops, at max(0, least) = its own approach.
TEST(PooledContact, APoolHeldWhollyByItsGuardsTakesLambdaZero) {
  NodePool pool;
  for (int i = 0; i < 4; ++i) pool.inside.push_back({1.0 + i, -1, 1});
  const PoolSolution r = solve_pool(pool, kFrictionless);
  EXPECT_EQ(r.lambda, 0);
  EXPECT_EQ(r.evaluations, 2);
}

// A held node approaching at 3 and a free one leaving at 1: lambda_0 = 1, where S = 2 and S' = 1;
// Newton's step lands at -1, is clamped to 0, where S(0) = 1 >= 0, evaluated once more and done.
// The friction takes the pool's normal impulse at 0 (3, the held node's), not at 1 (4).
TEST(PooledContact, ANewtonStepBelowZeroStopsAtZero) {
  const NodePool pool{{{1, -3, 3}, {1, 1, -2}}, /*demand=*/10, /*row_mass=*/1};
  const PoolSolution r = solve_pool(pool, [](double) { return 0.5; });
  EXPECT_EQ(r.lambda, 0);
  EXPECT_EQ(r.evaluations, 3);
  EXPECT_EQ(pool.smallest_root(), 0);
  EXPECT_DOUBLE_EQ(r.keep, 1 - 0.5 * 3 / 10);
}

// Contact that leaves on average needs nothing: lambda = 0 from one evaluation.
TEST(PooledContact, AContactThatLeavesTakesNoLambda) {
  const NodePool pool{{{1, -1, 1}, {2, 1, -1}}};
  const PoolSolution r = solve_pool(pool, kFrictionless);
  EXPECT_EQ(r.lambda, 0);
  EXPECT_EQ(r.evaluations, 1);
}

// Coulomb's bound on the whole contact, mu taken at the surface row's mean slip: the row keeps
// 1 - capacity / demand of its slip where the demand is larger, and sticks where it is not.
TEST(PooledContact, TheRowKeepsWhatTheCapacityCannotTake) {
  // lambda = 1: the pool's normal impulse sum m dv_n = 4; the row's sum m |v_t| 3 over its mass 2:
  // mean slip 1.5.
  NodePool pool{{{2, -1, -5}, {2, -1, -5}}, /*demand=*/3, /*row_mass=*/2};
  double slip_seen = -1;
  const auto mu = [&](double slip) {
    slip_seen = slip;
    return 0.25;
  };
  PoolSolution r = solve_pool(pool, mu);
  EXPECT_DOUBLE_EQ(r.lambda, 1);
  EXPECT_DOUBLE_EQ(slip_seen, 1.5);
  EXPECT_DOUBLE_EQ(r.keep, 1 - 0.25 * 4 / 3);
  pool.demand = 0.9;  // below the capacity 1: the row sticks
  r = solve_pool(pool, mu);
  EXPECT_EQ(r.keep, 0);
}

}  // namespace
}  // namespace firn

// The grid update of a free block (kernels/grid_update.hpp): a block that no collider and no domain
// wall reaches is updated by one vectorised loop over its nodes. It must give the node-by-node
// path's bits, empty nodes, damping and the energy budget's gravity work included, and the
// wall-band test that sends a block to that loop must agree with apply_walls' test node by node.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "kernels/grid_update.hpp"

namespace firn {
namespace {

template <class T>
GridUpdateParams<T> free_params(T damping_factor) {
  GridUpdateParams<T> p{};
  p.dt = T(1e-4);
  p.gravity[1] = T(-9.81);
  p.gravity[2] = T(0.5);
  for (int f = 0; f < 6; ++f) p.walls[f] = Wall<T>{WallType::separate, 3 + f % 2, T(0.2), false};
  for (int d = 0; d < 3; ++d) p.nodes[d] = 41 + d;
  p.dx = T(0.01);
  p.min_mass = T(1e-12);
  p.damping_factor = damping_factor;
  return p;
}

template <class T, Transfer kTransfer>
void check_free_block_is_the_node_path(T damping_factor, bool gravity = true) {
  constexpr int K = GridChannels<kTransfer>::kCount;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<T> data(K * kBlockNodes);
  for (int l = 0; l < kBlockNodes; ++l) {
    const int kind = l % 8;  // empty, below min_mass, or a mass
    data[l] = kind == 0 ? T(0) : kind == 1 ? T(1e-14) : T(1e-3 * (1.5 + u(rng)));
    for (int d = 1; d < 4; ++d) data[d * kBlockNodes + l] = T(1e-3 * u(rng));
  }
  const int block[3] = {2, 3, 4};  // its nodes are 8-11, 12-15, 16-19: in no wall's band
  GridUpdateParams<T> p = free_params(damping_factor);
  if (!gravity) p.gravity[1] = p.gravity[2] = T(0);
  ASSERT_FALSE(block_in_wall_band(block, p));

  // Each path with and without an energy budget. A plane half a cell below the block's lowest
  // nodes reaches the block but holds none of its nodes: it sends the block down the node-by-node
  // path and changes nothing there.
  std::vector<T> vectorised = data, vectorised_budget = data, node_by_node = data, node_budget = data;
  grid_update_block<T, kTransfer>(vectorised.data(), block, 0, p);
  T free_work[kWorkKinds] = {}, node_work[kWorkKinds] = {}, reactions[kReactionComponents] = {};
  p.work = free_work;
  grid_update_block<T, kTransfer>(vectorised_budget.data(), block, 0, p);
  Collider<T> plane;
  plane.center[1] = T(block[1] * kBlockSize) * p.dx - (T(kColliderSkin) + T(0.5)) * p.dx;
  p.colliders[0] = plane;
  p.collider_count = 1;
  p.reactions = reactions;
  ASSERT_EQ(colliders_near_block(block, p), 1u);
  p.work = nullptr;
  grid_update_block<T, kTransfer>(node_by_node.data(), block, 0, p);
  p.work = node_work;
  grid_update_block<T, kTransfer>(node_budget.data(), block, 0, p);
  if (gravity) EXPECT_NE(free_work[kGravityWork], T(0));
  else EXPECT_EQ(free_work[kGravityWork], T(0));
  EXPECT_EQ(std::memcmp(&free_work[kGravityWork], &node_work[kGravityWork], sizeof(T)), 0);
  EXPECT_EQ(node_work[kColliderWork], T(0));
  EXPECT_EQ(std::memcmp(vectorised.data(), node_by_node.data(), data.size() * sizeof(T)), 0);
  EXPECT_EQ(std::memcmp(vectorised_budget.data(), node_by_node.data(), data.size() * sizeof(T)), 0);
  EXPECT_EQ(std::memcmp(node_budget.data(), node_by_node.data(), data.size() * sizeof(T)), 0);
  for (int l = 0; l < kBlockNodes; ++l)
    for (int d = 1; d < 4; ++d) {
      const T v = vectorised[d * kBlockNodes + l];
      EXPECT_EQ(v, node_by_node[d * kBlockNodes + l]) << "node " << l << " channel " << d;
      if (l % 8 < 2) EXPECT_EQ(v, T(0)) << "empty node " << l;
      else EXPECT_NE(v, data[d * kBlockNodes + l]) << "node " << l;  // a velocity, not the momentum
    }
}

TEST(GridUpdate, AFreeBlockTakesTheNodeByNodeBits) {
  check_free_block_is_the_node_path<float, Transfer::apic>(1.0f);
  check_free_block_is_the_node_path<float, Transfer::apic>(1.0f / 1.3f);
  check_free_block_is_the_node_path<float, Transfer::apic>(1.0f, /*gravity=*/false);
  check_free_block_is_the_node_path<float, Transfer::pic>(1.0f / 1.3f);
  check_free_block_is_the_node_path<double, Transfer::apic>(1.0);
  check_free_block_is_the_node_path<double, Transfer::apic>(1.0 / 1.3);
}

// block_in_wall_band(block) is true exactly where a node of the block is in a wall's band.
TEST(GridUpdate, TheWallBandTestIsApplyWallsTestOverTheBlock) {
  const GridUpdateParams<float> p = free_params(1.0f);
  int in_band = 0, free = 0;
  for (int bx = 0; bx * kBlockSize < p.nodes[0]; ++bx)
    for (int by = 0; by * kBlockSize < p.nodes[1]; ++by)
      for (int bz = 0; bz * kBlockSize < p.nodes[2]; ++bz) {
        const int block[3] = {bx, by, bz};
        bool any = false;
        for (int l = 0; l < kBlockNodes; ++l) {
          int node[3];
          block_node(block, l, node);
          for (int d = 0; d < 3; ++d)
            any = any || node[d] < p.walls[2 * d].width || node[d] > p.nodes[d] - 1 - p.walls[2 * d + 1].width;
        }
        EXPECT_EQ(block_in_wall_band(block, p), any) << bx << " " << by << " " << bz;
        (any ? in_band : free) += 1;
      }
  EXPECT_GT(in_band, 0);
  EXPECT_GT(free, 0);
}

}  // namespace
}  // namespace firn

// The sparse grid follows the particles: the same body in a domain 8x larger activates the same
// blocks, takes the same steps to the same state, and its grid storage grows only by the block map.
#include <gtest/gtest.h>

#include "kernels/backend/serial.hpp"
#include "studies/bench/reference_problems.hpp"

namespace firn {
namespace {

struct Outcome {
  std::size_t active_blocks;
  std::size_t map_blocks;
  std::size_t grid_bytes;
  std::uint64_t hash;
};

Outcome drop_cube(double domain_scale) {
  SimulationConfig c = cube_drop_config(domain_scale);
  c.dx = 0.02;
  Simulation<float, backend::Serial> sim(c);
  const int m = sim.add_material({"cube", "neo_hookean", 1000, ElasticModuli::from_E_nu(1e5, 0.3)});
  sim.add_particles(m, fill_box(c.domain_min, c.dx, 2, {0.3, 0.1, 0.3}, {0.5, 0.3, 0.5}), {0, -1, 0}, 1e-6);
  for (int s = 0; s < 10; ++s) sim.step();
  return {sim.grid().active_count(), sim.grid().block_count(), sim.grid().memory_bytes(), sim.state_hash()};
}

TEST(SparseGrid, CostFollowsParticlesNotDomain) {
  const Outcome small = drop_cube(1), large = drop_cube(2);
  EXPECT_EQ(small.active_blocks, large.active_blocks);
  EXPECT_EQ(small.hash, large.hash);
  // Particles span 10^3 cells: at most 4 blocks per axis plus one neighbour layer.
  EXPECT_LE(small.active_blocks, 6u * 6u * 6u);
  // Only the block map (4 bytes per 64 nodes) grows with the domain.
  EXPECT_GT(large.map_blocks, 6 * small.map_blocks);
  EXPECT_LE(large.grid_bytes, small.grid_bytes + (large.map_blocks - small.map_blocks) * 4);
}

TEST(SparseGrid, ActivatesNeighbourBlocksOfEveryParticleBlock) {
  SimulationConfig c;
  c.dx = 0.05;
  Simulation<double, backend::Serial> sim(c);
  const int m = sim.add_material({"m", "neo_hookean", 1000, ElasticModuli::from_E_nu(1e5, 0.3)});
  // One particle in the middle of block (2, 2, 2): nodes 8..11 hold x in [0.4, 0.55).
  sim.add_particles(m, {{0.47, 0.47, 0.47}}, {0, 0, 0}, 1e-6);
  sim.step();
  EXPECT_EQ(sim.grid().active_count(), 8u);
}

}  // namespace
}  // namespace firn

// The sparse grid follows the particles: the same body in a domain 8x larger activates the same
// blocks, takes the same steps to the same state, and its grid storage grows only by the block map.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "kernels/backend/serial.hpp"
#include "kernels/block_lists.hpp"
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

// ActiveBlock finds the writing particle blocks by id offsets, without coordinates; against the
// definition (b - o in the box and occupied, o in {0,1}^3) on random occupancy of boxes whose last
// layers are empty, as a particle binning leaves them, particle blocks on the faces x, y, z = 0
// included.
TEST(SparseGrid, ActiveBlocksAreTheNeighboursOfParticleBlocks) {
  std::mt19937 rng(7);
  for (const BlockBox box : {BlockBox{{3, 4, 5}}, BlockBox{{6, 2, 3}}, BlockBox{{5, 7, 2}}}) {
    for (int trial = 0; trial < 20; ++trial) {
      const std::size_t n = std::size_t(box.count[0]) * box.count[1] * box.count[2];
      std::vector<std::uint8_t> occupied(n, 0);
      for (std::size_t b = 0; b < n; ++b) {
        int c[3];
        box.coords(std::uint32_t(b), c);
        const bool last = c[0] == box.count[0] - 1 || c[1] == box.count[1] - 1 || c[2] == box.count[2] - 1;
        occupied[b] = !last && rng() % 4 == 0;
      }
      const ActiveBlock active{occupied.data(), box};
      for (std::size_t b = 0; b < n; ++b) {
        int c[3];
        box.coords(std::uint32_t(b), c);
        bool written = false;
        for (int o = 0; o < 8; ++o) {
          const int x = c[0] - (o >> 2), y = c[1] - ((o >> 1) & 1), z = c[2] - (o & 1);
          written = written || (x >= 0 && y >= 0 && z >= 0 && occupied[std::size_t(box.id(x, y, z))]);
        }
        EXPECT_EQ(active(b), written ? 0 : -1) << "block " << c[0] << " " << c[1] << " " << c[2];
      }
    }
  }
}

}  // namespace
}  // namespace firn

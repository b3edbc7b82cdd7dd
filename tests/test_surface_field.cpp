// The Zhu-Bridson field on the sparse grid (thesis Eq. 4.10-4.14) and the marching-tetrahedra mesh
// built from it: exact values for one particle, bitwise reproducibility across thread counts, the
// triangulation table, the topology check itself, and closed oriented manifolds from random
// particle clouds (many components, thin parts and every ambiguous sign pattern of a cell).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "engine/particle_storage.hpp"
#include "kernels/backend/openmp.hpp"
#include "kernels/backend/serial.hpp"
#include "viz/surface/marching_tetrahedra.hpp"
#include "viz/surface/mesh_topology.hpp"
#include "viz/surface/reconstruct_surface.hpp"

namespace firn::surface {
namespace {

// A cloud of `count` particles uniform in a cube of side `side`, spacing-sized volumes.
ParticleStorage<double> random_cloud(int count, double side, double volume, unsigned seed) {
  ParticleStorage<double> storage;
  storage.enable(Attribute::x0);
  storage.resize(std::size_t(count));
  ParticleView<double> pv = storage.view();
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coordinate(0.2, 0.2 + side);
  for (int p = 0; p < count; ++p) {
    for (int d = 0; d < 3; ++d) pv.x[d][p] = pv.x0[d][p] = coordinate(random);
    pv.vol0[p] = volume;
  }
  return storage;
}

TEST(SurfaceField, OneParticleGivesItsOwnSignedDistance) {
  ParticleStorage<double> storage;
  storage.resize(1);
  ParticleView<double> pv = storage.view();
  const double x[3] = {0.1234, 0.2345, 0.3456}, h = 0.01, R = 0.02, volume = 1e-6;
  for (int d = 0; d < 3; ++d) pv.x[d][0] = x[d];
  pv.vol0[0] = volume;
  const FieldGrid grid = compute_scalar_field(storage.view(), h, R, 0.85, backend::Serial{});
  const double r = 0.85 * std::cbrt(volume);
  int inside_support = 0;
  for (std::size_t slot = 0; slot < grid.active_blocks.size(); ++slot) {
    int b[3];
    grid.block_coords(grid.active_blocks[slot], b);
    for (int node = 0; node < kNodesPerBlock; ++node) {
      const int l[3] = {node >> 6, node >> 3 & 7, node & 7};
      double distance2 = 0;
      for (int d = 0; d < 3; ++d) {
        const double position = double(grid.origin[d] + b[d] * kBlockNodes + l[d]) * h;
        distance2 += (position - x[d]) * (position - x[d]);
      }
      const float phi = grid.phi[slot * kNodesPerBlock + node];
      if (distance2 < R * R) {
        ++inside_support;
        // One particle: x_avg = x_1, r_avg = r_1, so phi = |x - x_1| - r_1 (Eq. 4.10).
        EXPECT_NEAR(phi, std::sqrt(distance2) - r, 1e-6);
        EXPECT_NEAR(grid.rest[slot * kNodesPerBlock + node][0], x[0], 1e-6);  // x0 absent: x stands in
      } else {
        EXPECT_EQ(phi, grid.outside_value);
      }
    }
  }
  // Every lattice node within R of the particle was sampled: count them independently.
  int lattice_nodes_within_R = 0;
  for (int i = -3; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j)
      for (int k = -3; k <= 3; ++k) {
        const int n[3] = {i, j, k};
        double distance2 = 0;
        for (int d = 0; d < 3; ++d) {
          const double position = (std::floor(x[d] / h) + n[d]) * h;
          distance2 += (position - x[d]) * (position - x[d]);
        }
        lattice_nodes_within_R += distance2 < R * R;
      }
  EXPECT_GT(lattice_nodes_within_R, 20);
  EXPECT_EQ(inside_support, lattice_nodes_within_R);
}

// Bitwise the same mesh at every OpenMP thread count (each node, vertex and triangle is computed
// by one thread in a fixed order). The serial backend is not compared bit for bit: the compiler may
// contract its loops' multiply-adds differently (see the README's Determinism note).
TEST(SurfaceField, SameMeshForEveryThreadCount) {
  ParticleStorage<double> particles = random_cloud(20000, 0.3, 1e-6, 3);
  SurfaceParams params;
  params.simulation_dx = 0.02;
  auto surface_with = [&](int threads) {
    return reconstruct_surface(particles.view(), params, backend::OpenMP(threads));
  };
  const SurfaceMesh one = surface_with(1);
  for (int threads : {2, 3}) {
    const SurfaceMesh parallel = surface_with(threads);
    ASSERT_EQ(parallel.triangles, one.triangles) << threads << " threads";
    ASSERT_EQ(parallel.vertex_count(), one.vertex_count());
    for (std::size_t v = 0; v < one.vertex_count(); ++v)
      for (int d = 0; d < 3; ++d) {
        ASSERT_EQ(parallel.positions[v][d], one.positions[v][d]);
        ASSERT_EQ(parallel.normals[v][d], one.normals[v][d]);
      }
    ASSERT_EQ(parallel.crystals.size(), one.crystals.size());
  }
}

// Sparse random clouds make blobs, bridges, handles and cavities: every sign pattern of a cell
// turns up, and the mesh must still be closed, manifold and consistently oriented.
TEST(SurfaceField, RandomCloudsGiveClosedOrientedManifolds) {
  SurfaceParams params;
  params.simulation_dx = 0.02;
  params.crystals = false;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    ParticleStorage<double> cloud = random_cloud(400 * int(seed), 0.2, 2e-6, seed);
    SurfaceMesh mesh = reconstruct_surface(cloud.view(), params, backend::Serial{});
    const MeshTopology topology = analyse_topology(mesh.triangles, mesh.vertex_count());
    EXPECT_GT(topology.faces, 100u);
    EXPECT_TRUE(topology.closed_manifold())
        << "seed " << seed << ": boundary " << topology.boundary_edges << ", non-manifold edges "
        << topology.non_manifold_edges << ", misoriented " << topology.misoriented_edges << ", non-manifold vertices "
        << topology.non_manifold_vertices;
    EXPECT_EQ(topology.euler_characteristic() % 2, 0);  // a closed orientable surface
    EXPECT_GT(enclosed_volume(mesh.positions, mesh.triangles), 0);  // outward orientation
  }
}

TEST(SurfaceField, TopologyCheckCatchesOpenFlippedAndPinchedMeshes) {
  // A tetrahedron, outward: closed, Euler characteristic 2.
  const std::vector<std::uint32_t> tetrahedron = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
  EXPECT_TRUE(analyse_topology(tetrahedron, 4).closed_manifold());
  EXPECT_EQ(analyse_topology(tetrahedron, 4).euler_characteristic(), 2);
  const std::vector<Vec3f> corners = {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}};
  EXPECT_NEAR(enclosed_volume(corners, tetrahedron), 1.0 / 6, 1e-7);
  std::vector<std::uint32_t> open(tetrahedron.begin(), tetrahedron.end() - 3);
  EXPECT_EQ(analyse_topology(open, 4).boundary_edges, 3u);
  std::vector<std::uint32_t> flipped = tetrahedron;
  std::swap(flipped[1], flipped[2]);
  EXPECT_EQ(analyse_topology(flipped, 4).misoriented_edges, 3u);
  // Two tetrahedra sharing only vertex 0: every edge is fine, vertex 0 is a pinch.
  std::vector<std::uint32_t> pinched = tetrahedron;
  for (std::uint32_t v : tetrahedron) pinched.push_back(v == 0 ? 0 : v + 3);
  const MeshTopology pinch = analyse_topology(pinched, 7);
  EXPECT_EQ(pinch.boundary_edges + pinch.non_manifold_edges + pinch.misoriented_edges, 0u);
  EXPECT_EQ(pinch.non_manifold_vertices, 1u);
  EXPECT_FALSE(pinch.closed_manifold());
}

// Each triangle's edges as three (corner, direction) codes, rotated to start at the smallest.
std::array<int, 3> edge_cycle(const CellEdge* t, bool reversed) {
  std::array<int, 3> codes;
  for (int c = 0; c < 3; ++c) codes[c] = t[reversed ? (3 - c) % 3 : c].corner * 8 + t[reversed ? (3 - c) % 3 : c].direction;
  std::rotate(codes.begin(), std::min_element(codes.begin(), codes.end()), codes.end());
  return codes;
}

TEST(SurfaceField, TriangulationTableIsComplementSymmetric) {
  // Swapping inside and outside gives the same triangles with the opposite winding.
  const CellTriangulation* cases = cell_triangulations();
  for (int m = 0; m < 256; ++m) {
    const CellTriangulation& a = cases[m];
    const CellTriangulation& b = cases[255 - m];
    ASSERT_EQ(a.triangle_count, b.triangle_count);
    std::vector<std::array<int, 3>> forward, backward;
    for (int t = 0; t < a.triangle_count; ++t) {
      forward.push_back(edge_cycle(a.triangles[t], false));
      backward.push_back(edge_cycle(b.triangles[t], true));
    }
    std::sort(forward.begin(), forward.end());
    std::sort(backward.begin(), backward.end());
    EXPECT_EQ(forward, backward) << "case " << m;
  }
  EXPECT_EQ(cases[0].triangle_count, 0);
  EXPECT_EQ(cases[1].triangle_count, 6);  // corner (0,0,0) alone: it is in all six tetrahedra
  EXPECT_EQ(cases[2].triangle_count, 2);  // corner (1,0,0) alone: in the two that step along x first
}

}  // namespace
}  // namespace firn::surface

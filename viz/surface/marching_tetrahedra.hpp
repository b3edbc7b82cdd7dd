// Isosurface extraction phi = 0 from the sparse field grid by marching tetrahedra (the table and
// the reasons for tetrahedra are in tetrahedral_cases.hpp). One vertex per crossed grid edge,
// shared by every triangle around that edge, so the mesh is indexed and watertight.
//
// Parallel and deterministic, block by block: (1) every active block marks the crossed edges of
// the nodes it owns and counts its vertices and triangles; (2) a prefix sum over the blocks, in
// block order, gives each block its ranges of the output arrays; (3) every block writes its
// vertices (in node order, then direction order) and its cells' triangles. A vertex's index
// follows from its owner node alone (block offset + node offset + crossings below it in that
// node), so a cell finds the vertices owned by a neighbouring block without any search.
#pragma once

#include <bitset>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "kernels/backend/schedule.hpp"
#include "viz/surface/scalar_field.hpp"
#include "viz/surface/surface_mesh.hpp"
#include "viz/surface/tetrahedral_cases.hpp"

namespace firn::surface {

namespace detail {

// A block and its seven neighbours toward +x, +y, +z: node (lx, ly, lz) with each coordinate in
// [0, 2 * kBlockNodes) lies in neighbour (lx >> 3) | (ly >> 3) << 1 | (lz >> 3) << 2.
struct BlockNeighbourhood {
  int slots[8];

  BlockNeighbourhood(const FieldGrid& grid, std::uint32_t block_id) {
    int b[3];
    grid.block_coords(block_id, b);
    for (int u = 0; u < 8; ++u) slots[u] = grid.slot(b[0] + (u & 1), b[1] + (u >> 1 & 1), b[2] + (u >> 2 & 1));
  }
  // (slot, local node) of node (lx, ly, lz); slot -1 outside the active blocks.
  void locate(int lx, int ly, int lz, int& slot, int& node) const {
    slot = slots[(lx >> kBlockShift) | (ly >> kBlockShift) << 1 | (lz >> kBlockShift) << 2];
    node = local_node(lx & kBlockMask, ly & kBlockMask, lz & kBlockMask);
  }
  float phi(const FieldGrid& grid, int lx, int ly, int lz) const {
    int slot, node;
    locate(lx, ly, lz, slot, node);
    return slot < 0 ? grid.outside_value : grid.phi[std::size_t(slot) * kNodesPerBlock + node];
  }
};

inline bool is_inside(float phi) { return phi < 0; }

// Bit (d - 1) set when the edge from node (lx, ly, lz) in direction d crosses the surface.
inline std::uint8_t crossed_edges(const FieldGrid& grid, const BlockNeighbourhood& hood, int lx, int ly, int lz) {
  const bool inside = is_inside(hood.phi(grid, lx, ly, lz));
  std::uint8_t crossed = 0;
  for (int d = 1; d <= kEdgeDirections; ++d)
    if (is_inside(hood.phi(grid, lx + (d & 1), ly + (d >> 1 & 1), lz + (d >> 2 & 1))) != inside)
      crossed |= std::uint8_t(1 << (d - 1));
  return crossed;
}

// Bit u set when corner u of the cell with lower node (lx, ly, lz) is inside.
inline int inside_corners(const FieldGrid& grid, const BlockNeighbourhood& hood, int lx, int ly, int lz) {
  int inside = 0;
  for (int u = 0; u < 8; ++u)
    if (is_inside(hood.phi(grid, lx + (u & 1), ly + (u >> 1 & 1), lz + (u >> 2 & 1)))) inside |= 1 << u;
  return inside;
}

inline int popcount(std::uint8_t bits) { return int(std::bitset<8>(bits).count()); }

}  // namespace detail

// Replaces mesh.positions, rest_positions and triangles with the surface of `grid`; normals are
// left to the caller (they follow the final, smoothed geometry).
template <class Backend>
void extract_isosurface(const FieldGrid& grid, SurfaceMesh& mesh, const Backend& backend) {
  using detail::BlockNeighbourhood;
  const std::size_t blocks = grid.active_blocks.size();
  const CellTriangulation* cases = cell_triangulations();
  std::vector<std::uint8_t> crossed(blocks * kNodesPerBlock);
  std::vector<std::uint32_t> first_vertex(blocks * kNodesPerBlock);  // of each node, within its block
  std::vector<std::size_t> vertex_offset(blocks + 1, 0), triangle_offset(blocks + 1, 0);

  backend.parallel_for(
      "surface_mc_count", blocks,
      [&](std::size_t slot) {
        const BlockNeighbourhood hood(grid, grid.active_blocks[slot]);
        std::uint32_t vertices = 0;
        std::size_t triangles = 0;
        for (int lx = 0; lx < kBlockNodes; ++lx)
          for (int ly = 0; ly < kBlockNodes; ++ly)
            for (int lz = 0; lz < kBlockNodes; ++lz) {
              const std::size_t node = slot * kNodesPerBlock + local_node(lx, ly, lz);
              crossed[node] = detail::crossed_edges(grid, hood, lx, ly, lz);
              first_vertex[node] = vertices;
              vertices += std::uint32_t(detail::popcount(crossed[node]));
              // The lower node's seven edges reach every other corner of its cell: no crossing, no triangle.
              if (crossed[node]) triangles += cases[detail::inside_corners(grid, hood, lx, ly, lz)].triangle_count;
            }
        vertex_offset[slot + 1] = vertices;
        triangle_offset[slot + 1] = triangles;
      },
      backend::Schedule::uneven);
  for (std::size_t s = 0; s < blocks; ++s) {
    vertex_offset[s + 1] += vertex_offset[s];
    triangle_offset[s + 1] += triangle_offset[s];
  }
  if (vertex_offset[blocks] >= std::size_t(UINT32_MAX)) throw std::length_error("surface: too many vertices");
  mesh.positions.resize(vertex_offset[blocks]);
  mesh.rest_positions.resize(vertex_offset[blocks]);
  mesh.triangles.resize(3 * triangle_offset[blocks]);
  mesh.normals.clear();

  backend.parallel_for(
      "surface_mc_emit", blocks,
      [&](std::size_t slot) {
        const BlockNeighbourhood hood(grid, grid.active_blocks[slot]);
        int b[3];
        grid.block_coords(grid.active_blocks[slot], b);
        long first[3];
        for (int d = 0; d < 3; ++d) first[d] = grid.origin[d] + (long(b[d]) << kBlockShift);
        // Index of the vertex on edge (node (lx, ly, lz), direction d). Its owner node is always in an
        // active block: a crossed edge has a node within R of a particle, and every block within one
        // of that particle's block is active (scalar_field.hpp).
        auto vertex_index = [&](int lx, int ly, int lz, int d) {
          int owner, node;
          hood.locate(lx, ly, lz, owner, node);
          const std::size_t i = std::size_t(owner) * kNodesPerBlock + node;
          return std::uint32_t(vertex_offset[owner] + first_vertex[i] +
                               detail::popcount(std::uint8_t(crossed[i] & ((1 << (d - 1)) - 1))));
        };
        std::size_t next_triangle = triangle_offset[slot];
        for (int lx = 0; lx < kBlockNodes; ++lx)
          for (int ly = 0; ly < kBlockNodes; ++ly)
            for (int lz = 0; lz < kBlockNodes; ++lz) {
              const int local = local_node(lx, ly, lz);
              const std::size_t node = slot * kNodesPerBlock + local;
              const float phi_a = grid.phi[node];
              std::size_t v = vertex_offset[slot] + first_vertex[node];
              for (int d = 1; d <= kEdgeDirections; ++d) {
                if (!(crossed[node] >> (d - 1) & 1)) continue;
                const int step[3] = {d & 1, d >> 1 & 1, d >> 2 & 1};
                int other_slot, other;
                hood.locate(lx + step[0], ly + step[1], lz + step[2], other_slot, other);
                const float phi_b = other_slot < 0 ? grid.outside_value
                                                   : grid.phi[std::size_t(other_slot) * kNodesPerBlock + other];
                // Linear interpolation of phi along the edge; the signs differ, so t is in [0, 1].
                const double t = double(phi_a) / (double(phi_a) - double(phi_b));
                const int l[3] = {lx, ly, lz};
                for (int k = 0; k < 3; ++k) mesh.positions[v][k] = float((first[k] + l[k] + t * step[k]) * grid.h);
                const Vec3f rest_a = grid.rest[node];
                const Vec3f rest_b = other_slot < 0 ? rest_a : grid.rest[std::size_t(other_slot) * kNodesPerBlock + other];
                for (int k = 0; k < 3; ++k) {
                  // A node that no particle reaches has no material coordinates: use the other end's.
                  const float from = std::isnan(rest_a[k]) ? rest_b[k] : rest_a[k];
                  const float to = std::isnan(rest_b[k]) ? rest_a[k] : rest_b[k];
                  mesh.rest_positions[v][k] = float(from + t * (to - from));
                }
                ++v;
              }
              if (!crossed[node]) continue;
              const CellTriangulation& cell = cases[detail::inside_corners(grid, hood, lx, ly, lz)];
              for (int tri = 0; tri < cell.triangle_count; ++tri) {
                for (int c = 0; c < 3; ++c) {
                  const CellEdge e = cell.triangles[tri][c];
                  mesh.triangles[3 * next_triangle + c] =
                      vertex_index(lx + (e.corner & 1), ly + (e.corner >> 1 & 1), lz + (e.corner >> 2 & 1), e.direction);
                }
                ++next_triangle;
              }
            }
      },
      backend::Schedule::uneven);
}

}  // namespace firn::surface

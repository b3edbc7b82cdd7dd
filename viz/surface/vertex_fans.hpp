// Per-vertex adjacency of a triangle mesh in compressed rows: for every triangle (a, b, c), vertex
// a gets the pair (b, c), b gets (c, a) and c gets (a, b). On a closed oriented manifold each
// vertex's pairs list its neighbours once each (its one-ring) and its triangles' corners, which is
// all that normals and the uniform Laplacian need. Rows follow triangle order, so every sum over a
// row runs in the same order whatever the thread count.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "viz/surface/surface_mesh.hpp"

namespace firn::surface {

struct VertexFans {
  std::vector<std::uint32_t> begin;  // row of vertex v: [begin[v], begin[v + 1])
  std::vector<std::uint32_t> next;   // b of the pair (b, c): a one-ring neighbour
  std::vector<std::uint32_t> after;  // c: the triangle's third corner
};

VertexFans build_vertex_fans(const std::vector<std::uint32_t>& triangles, std::size_t vertex_count);

// Area-weighted vertex normals: n_a = normalise(sum over a's triangles (b - a) x (c - a)); a vertex
// whose triangles all have zero area keeps a zero normal.
template <class Backend>
void compute_vertex_normals(SurfaceMesh& mesh, const VertexFans& fans, const Backend& backend) {
  mesh.normals.resize(mesh.positions.size());
  backend.parallel_for("surface_normals", mesh.positions.size(), [&](std::size_t v) {
    const Vec3f a = mesh.positions[v];
    Vec3f sum = {{0, 0, 0}};
    for (std::uint32_t e = fans.begin[v]; e < fans.begin[v + 1]; ++e)
      sum = sum + cross(mesh.positions[fans.next[e]] - a, mesh.positions[fans.after[e]] - a);
    const float length = norm(sum);
    mesh.normals[v] = length > 0 ? (1 / length) * sum : sum;
  });
}

}  // namespace firn::surface

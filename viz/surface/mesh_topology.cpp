#include "viz/surface/mesh_topology.hpp"

#include <algorithm>

#include "viz/surface/vertex_fans.hpp"

namespace firn::surface {

MeshTopology analyse_topology(const std::vector<std::uint32_t>& triangles, std::size_t vertex_count) {
  MeshTopology topology;
  topology.vertices = vertex_count;
  topology.faces = triangles.size() / 3;
  // Directed edges (a, b) as 64-bit keys; an undirected edge's uses are its two directions.
  std::vector<std::uint64_t> directed;
  directed.reserve(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); t += 3) {
    const std::uint32_t* v = &triangles[t];
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) ++topology.degenerate_triangles;
    for (int c = 0; c < 3; ++c) directed.push_back(std::uint64_t(v[c]) << 32 | v[(c + 1) % 3]);
  }
  std::sort(directed.begin(), directed.end());
  std::vector<std::uint64_t> undirected(directed.size());
  std::transform(directed.begin(), directed.end(), undirected.begin(), [](std::uint64_t e) {
    const std::uint64_t a = e >> 32, b = e & 0xffffffffu;
    return a < b ? a << 32 | b : b << 32 | a;
  });
  std::sort(undirected.begin(), undirected.end());
  for (std::size_t i = 0; i < undirected.size();) {
    std::size_t j = i;
    while (j < undirected.size() && undirected[j] == undirected[i]) ++j;
    ++topology.edges;
    if (j - i == 1) ++topology.boundary_edges;
    if (j - i > 2) ++topology.non_manifold_edges;
    i = j;
  }
  for (std::size_t i = 0; i + 1 < directed.size(); ++i)
    if (directed[i] == directed[i + 1]) ++topology.misoriented_edges;

  // Around a manifold vertex a, its triangles (a, b, c) chain b -> c into one cycle through all of them.
  const VertexFans fans = build_vertex_fans(triangles, vertex_count);
  for (std::size_t a = 0; a < vertex_count; ++a) {
    const std::uint32_t begin = fans.begin[a], end = fans.begin[a + 1];
    if (begin == end) {
      ++topology.isolated_vertices;
      continue;
    }
    std::uint32_t e = begin, steps = 0;
    do {
      std::uint32_t following = end;
      for (std::uint32_t f = begin; f < end; ++f)
        if (fans.next[f] == fans.after[e]) following = following == end ? f : end + 1;  // end + 1: ambiguous
      if (following >= end) break;
      e = following;
      ++steps;
    } while (e != begin && steps <= end - begin);
    if (e != begin || steps != end - begin) ++topology.non_manifold_vertices;
  }
  return topology;
}

double enclosed_volume(const std::vector<Vec3f>& positions, const std::vector<std::uint32_t>& triangles) {
  double six_volume = 0;
  for (std::size_t t = 0; t < triangles.size(); t += 3) {
    const Vec3f& a = positions[triangles[t]];
    const Vec3f& b = positions[triangles[t + 1]];
    const Vec3f& c = positions[triangles[t + 2]];
    six_volume += double(a[0]) * (double(b[1]) * c[2] - double(b[2]) * c[1]) +
                  double(a[1]) * (double(b[2]) * c[0] - double(b[0]) * c[2]) +
                  double(a[2]) * (double(b[0]) * c[1] - double(b[1]) * c[0]);
  }
  return six_volume / 6;
}

}  // namespace firn::surface

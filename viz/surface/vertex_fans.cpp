#include "viz/surface/vertex_fans.hpp"

namespace firn::surface {

VertexFans build_vertex_fans(const std::vector<std::uint32_t>& triangles, std::size_t vertex_count) {
  VertexFans fans;
  fans.begin.assign(vertex_count + 1, 0);
  for (std::uint32_t v : triangles) ++fans.begin[v + 1];
  for (std::size_t v = 0; v < vertex_count; ++v) fans.begin[v + 1] += fans.begin[v];
  fans.next.resize(triangles.size());
  fans.after.resize(triangles.size());
  std::vector<std::uint32_t> fill(fans.begin.begin(), fans.begin.end() - 1);
  for (std::size_t t = 0; t < triangles.size(); t += 3)
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t e = fill[triangles[t + c]]++;
      fans.next[e] = triangles[t + (c + 1) % 3];
      fans.after[e] = triangles[t + (c + 2) % 3];
    }
  return fans;
}

}  // namespace firn::surface

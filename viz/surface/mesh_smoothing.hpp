// Smoothing with the uniform ("umbrella") Laplacian L(x_a) = (1/|N(a)|) sum_{b in N(a)} x_b - x_a:
// - uniform Laplacian smoothing, x <- x + lambda L(x) per iteration (the thesis used three);
// - Taubin (1995) lambda|mu smoothing, x <- x + lambda L(x) then x <- x + mu L(x) with
//   mu < -lambda < 0, a low-pass filter that removes the grid's staircase without the shrinkage of
//   plain Laplacian smoothing.
// Each step is a Jacobi update into a second buffer (every vertex reads the previous positions), so
// the result does not depend on the thread count. Rest positions stay with their vertices.
#pragma once

#include <cstddef>
#include <vector>

#include "viz/surface/surface_mesh.hpp"
#include "viz/surface/surface_params.hpp"
#include "viz/surface/vertex_fans.hpp"

namespace firn::surface {

// One step x <- x + factor L(x).
template <class Backend>
void laplacian_step(std::vector<Vec3f>& positions, std::vector<Vec3f>& scratch, const VertexFans& fans, float factor,
                    const Backend& backend) {
  scratch.resize(positions.size());
  backend.parallel_for("surface_smooth", positions.size(), [&](std::size_t v) {
    const std::uint32_t begin = fans.begin[v], end = fans.begin[v + 1];
    if (begin == end) {
      scratch[v] = positions[v];
      return;
    }
    Vec3f sum = {{0, 0, 0}};
    for (std::uint32_t e = begin; e < end; ++e) sum = sum + positions[fans.next[e]];
    const Vec3f laplacian = (1.0f / float(end - begin)) * sum - positions[v];
    scratch[v] = positions[v] + factor * laplacian;
  });
  positions.swap(scratch);
}

template <class Backend>
void smooth_surface(SurfaceMesh& mesh, const VertexFans& fans, const SurfaceParams& params, const Backend& backend) {
  if (params.smoothing == Smoothing::none) return;
  std::vector<Vec3f> scratch;
  for (int i = 0; i < params.smoothing_iterations; ++i) {
    laplacian_step(mesh.positions, scratch, fans, float(params.smoothing_lambda), backend);
    if (params.smoothing == Smoothing::taubin) laplacian_step(mesh.positions, scratch, fans, float(params.taubin_mu), backend);
  }
}

}  // namespace firn::surface

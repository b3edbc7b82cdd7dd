// A particle's interpolation stencil: the first node per axis (base), the particle's offset from
// it in cells (f) and the B-spline weights of the kSupport nodes per axis. Shared by P2G and G2P.
#pragma once

#include <cstddef>

#include "kernels/grid_geometry.hpp"
#include "kernels/hd.hpp"
#include "kernels/particle_attributes.hpp"

namespace firn {

// The axes are the lanes of short vectors, a fourth lane repeating z, so that one subtraction,
// conversion and weight polynomial serve all three axes (issue 15; docs/performance.md, "The
// stencil's axes as lanes"). Each axis takes the same operations as it would alone, so the results
// are the same bits. Lane 3 is padding: kernels read lanes 0-2. The weights are stored node by node,
// w[c][d], so that each node's weights along the axes are one vector store.
template <class T, class ShapeT>
struct Stencil {
  int base[4];
  T f[4];
  T w[ShapeT::kSupport][4];  // w[c][d]: node c's weight along axis d
};

template <class T, class ShapeT>
FIRN_HD Stencil<T, ShapeT> particle_stencil(const ParticleView<T>& pv, std::size_t p, const GridGeometry<T>& g) {
  const T x[4] = {pv.x[0][p], pv.x[1][p], pv.x[2][p], pv.x[2][p]};
  const T origin[4] = {g.origin[0], g.origin[1], g.origin[2], g.origin[2]};
  Stencil<T, ShapeT> s;
  FIRN_LANES
  for (int d = 0; d < 4; ++d) {
    const T X = (x[d] - origin[d]) * g.inv_dx;
    s.base[d] = ShapeT::base(X);
    s.f[d] = X - T(s.base[d]);
    ShapeT::weights(s.f[d], &s.w[0][d], 4);
  }
  return s;
}

}  // namespace firn

// A particle's interpolation stencil: the first node per axis (base), the particle's offset from
// it in cells (f) and the B-spline weights of the kSupport nodes per axis. Shared by P2G and G2P.
#pragma once

#include <cstddef>

#include "kernels/grid_geometry.hpp"
#include "kernels/hd.hpp"
#include "kernels/particle_attributes.hpp"

namespace firn {

template <class T, class ShapeT>
struct Stencil {
  int base[3];
  T f[3];
  T w[3][ShapeT::kSupport];
};

template <class T, class ShapeT>
FIRN_HD Stencil<T, ShapeT> particle_stencil(const ParticleView<T>& pv, std::size_t p, const GridGeometry<T>& g) {
  Stencil<T, ShapeT> s;
  for (int d = 0; d < 3; ++d) {
    const T X = (pv.x[d][p] - g.origin[d]) * g.inv_dx;
    s.base[d] = ShapeT::base(X);
    s.f[d] = X - T(s.base[d]);
    ShapeT::weights(s.f[d], s.w[d]);
  }
  return s;
}

}  // namespace firn

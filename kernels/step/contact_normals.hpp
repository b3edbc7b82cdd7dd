// The contact normal and the nodal volume of two bodies on the grid (multi-velocity-field contact,
// Bardenhagen et al. 2001, "An improved contact algorithm for the material point method and
// application to stress propagation in granular material", CMES 2(4), section 3). A scatter like
// the step's P2G (kernels/step/p2g_scatter.hpp) writes, at every node,
//   channels 0-2:  grad m_A - grad m_B,   grad m = -sum_p m_p w_ip (o - f_p) over the group's particles,
//   channel 3:     sum_p w_ip V0_p, the particles' rest volume seen by the node.
// A mass gradient points into its body, so the difference points from B into A. The gradient of
// w_ip with respect to the node's position is -D^-1 w_ip (x_i - x_p) (the MLS gradient of Jiang et
// al. 2015) with x_i - x_p = (o - f_p) dx; the positive factor D^-1 dx is left out, as a direction
// does not need it. The volume tells touching bodies from bodies a gap apart
// (kernels/step/contact_update.hpp).
#pragma once

#include <cstddef>
#include <cstdint>

#include "kernels/binning_view.hpp"
#include "kernels/block_window.hpp"
#include "kernels/grid_geometry.hpp"
#include "kernels/hd.hpp"
#include "kernels/particle_attributes.hpp"
#include "kernels/particle_ranges.hpp"
#include "kernels/stencil.hpp"
#include "kernels/step/p2g_scatter.hpp"

namespace firn {

constexpr int kContactNormalChannels = 4;  // grad m_A - grad m_B, the volume

template <class T, class ShapeT>
struct ContactNormalScatter {
  static constexpr int kSupport = ShapeT::kSupport;
  static constexpr int kSpan = kBlockSize + kSupport - 1;
  static constexpr int kChannels = kContactNormalChannels;
  using Value = T;
  using Scratch = BlockScratch<T, kSpan, kChannels>;

  ParticleView<T> pv;
  SparseGridView<T> grid;
  BinningView bins;
  GridGeometry<T> g;
  ParticleRanges group_b;  // every other particle is in group A

  template <class Target>
  FIRN_HD void particle(std::uint32_t s, Target& out) const {
    const std::size_t p = bins.order[s];
    const Stencil<T, ShapeT> st = particle_stencil<T, ShapeT>(pv, p, g);
    const T sign = group_b.holds(p) ? T(-1) : T(1);  // grad m_A - grad m_B
    for (int a = 0; a < kSupport; ++a)
      for (int b = 0; b < kSupport; ++b) {
        T v[kSupport * kChannels];
        for (int c = 0; c < kSupport; ++c) {
          const T w = st.w[a][0] * st.w[b][1] * st.w[c][2], smw = sign * pv.mass[p] * w;
          T* node = v + c * kChannels;
          node[0] = smw * (st.f[0] - T(a));
          node[1] = smw * (st.f[1] - T(b));
          node[2] = smw * (st.f[2] - T(c));
          node[3] = w * pv.vol0[p];
        }
        out.template add_row<kSupport>(st.base[0] + a, st.base[1] + b, st.base[2], v);
      }
  }

  FIRN_HD void operator()(std::uint32_t b) const { scatter_block(*this, b); }
};

}  // namespace firn

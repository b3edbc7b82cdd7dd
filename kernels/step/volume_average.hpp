// The assumed deformation gradient (F-bar) by volume averaging through the grid, against the
// volumetric locking and the pressure checkerboard of nearly incompressible solids (Zhao, Jiang,
// Li and Choo 2023, "Circumventing volumetric locking in explicit material point methods: a
// simple, efficient, and general approach", Int. J. Numer. Methods Eng., section 3): each
// particle's volume ratio J_p = det F_p is averaged over its neighbourhood with the transfer's own
// weights, mass weighted,
//   J_i = sum_p w_ip m_p J_p / sum_p w_ip m_p,     Jbar_p = sum_i w_ip J_i,
// and F_p is rescaled to that volume, keeping its isochoric part:
//   F_p <- (Jbar_p / J_p)^(1/3) F_p.
// Only the particles of the averaged materials take part (a ParticleRanges): a snow particle
// touching rubber neither gives its volume to the rubber's average nor takes the rubber's.
//
// Two launches, as the step's P2G and G2P (kernels/step/p2g_scatter.hpp, g2p_gather.hpp): the
// scatter writes (m, m J) into grid channels 0 and 1 of a cleared grid, the gather reads them
// back and rescales F; its result is the number of particles rescaled.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "kernels/binning_view.hpp"
#include "kernels/block_window.hpp"
#include "kernels/grid_geometry.hpp"
#include "kernels/hd.hpp"
#include "kernels/mat3.hpp"
#include "kernels/particle_attributes.hpp"
#include "kernels/particle_ranges.hpp"
#include "kernels/particle_state.hpp"
#include "kernels/stencil.hpp"

namespace firn {

template <class T, class ShapeT>
struct VolumeScatter {
  static constexpr int kSupport = ShapeT::kSupport;
  static constexpr int kSpan = kBlockSize + kSupport - 1;
  static constexpr int kChannels = 2;  // m, m J
  using Value = T;
  using Scratch = BlockScratch<T, kSpan, kChannels>;

  ParticleView<T> pv;
  SparseGridView<T> grid;
  BinningView bins;
  GridGeometry<T> g;
  ParticleRanges averaged;

  // A particle of another material adds zeros over its stencil, so that a backend that stages
  // every particle of a block (the CUDA backend) sees a full stencil and the sums are unchanged.
  template <class Target>
  FIRN_HD void particle(std::uint32_t s, Target& out) const {
    const std::size_t p = bins.order[s];
    const Stencil<T, ShapeT> st = particle_stencil<T, ShapeT>(pv, p, g);
    const T m = averaged.holds(p) ? pv.mass[p] : T(0);
    const T mJ = m * determinant(particle_F(pv, p));
    for (int a = 0; a < kSupport; ++a)
      for (int b = 0; b < kSupport; ++b) {
        T v[kSupport * kChannels];
        for (int c = 0; c < kSupport; ++c) {
          const T w = st.w[a][0] * st.w[b][1] * st.w[c][2];
          v[c * kChannels] = w * m;
          v[c * kChannels + 1] = w * mJ;
        }
        out.template add_row<kSupport>(st.base[0] + a, st.base[1] + b, st.base[2], v);
      }
  }

  FIRN_HD void operator()(std::uint32_t b) const {
    int block[3];
    grid.box.coords(b, block);
    Scratch scratch;
    scratch.reset(block);
    for (std::size_t m = 0; m < bins.material_count; ++m) {
      const std::uint32_t begin = bins.bucket_begin(m, b), end = bins.bucket_end(m, b);
      if (begin == end || !averaged.holds(bins.order[begin])) continue;  // a bucket is one material
      for (std::uint32_t s = begin; s < end; ++s) particle(s, scratch);
    }
    scratch.flush(grid);
  }
};

template <class T, class ShapeT>
struct VolumeGather {
  static constexpr int kSpan = kBlockSize + ShapeT::kSupport - 1;
  static constexpr int kFirstChannel = 0;
  using Window = BlockGather<T, kSpan, 2>;
  using Result = std::size_t;

  ParticleView<T> pv;
  SparseGridView<T> grid;
  BinningView bins;
  GridGeometry<T> g;
  ParticleRanges averaged;

  FIRN_HD void particle(std::uint32_t s, const Window& window, std::size_t& rescaled) const {
    const std::size_t p = bins.order[s];
    if (!averaged.holds(p)) return;
    constexpr int S = ShapeT::kSupport;
    const Stencil<T, ShapeT> st = particle_stencil<T, ShapeT>(pv, p, g);
    T J_bar = T(0);
    for (int a = 0; a < S; ++a)
      for (int b = 0; b < S; ++b) {
        const T* row = window.row(st.base[0] + a, st.base[1] + b, st.base[2]);
        for (int c = 0; c < S; ++c) {
          const T* node = row + c * 2;  // m, m J
          if (node[0] > T(0)) J_bar += st.w[a][0] * st.w[b][1] * st.w[c][2] * node[1] / node[0];
        }
      }
    const T J = determinant(particle_F(pv, p));
    if (!(J > T(0)) || !(J_bar > T(0))) return;  // an inverted particle is the guard's to report
    const T scale = std::cbrt(J_bar / J);
    for (int q = 0; q < 9; ++q) pv.F[q][p] *= scale;
    ++rescaled;
  }

  FIRN_HD std::size_t operator()(std::uint32_t b) const {
    int block[3];
    grid.box.coords(b, block);
    Window window;
    window.load(grid, kFirstChannel, block);
    std::size_t rescaled = 0;
    for (std::size_t m = 0; m < bins.material_count; ++m)
      for (std::uint32_t s = bins.bucket_begin(m, b), e = bins.bucket_end(m, b); s < e; ++s)
        particle(s, window, rescaled);
    return rescaled;
  }
};

}  // namespace firn
